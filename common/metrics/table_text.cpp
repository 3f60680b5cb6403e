#include "metrics/table_text.hpp"

#include <iomanip>
#include <sstream>

namespace oasis::metrics {

std::string mean_std_text(const MeanStd& value) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(2) << value.mean << " ± " << value.std;
  return text.str();
}

std::string pad_columns(const std::string& text, std::size_t width) {
  std::size_t columns = 0;
  for (unsigned char c : text)
    if ((c & 0xC0) != 0x80) ++columns;  // count every byte but UTF-8 continuation bytes
  return text + std::string(columns < width ? width - columns : 0, ' ');
}

}  // namespace oasis::metrics
