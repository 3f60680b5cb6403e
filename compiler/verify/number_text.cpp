#include "verify/number_text.hpp"

#include <cstdio>

namespace oasis::verify {

std::string number_text(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

}  // namespace oasis::verify
