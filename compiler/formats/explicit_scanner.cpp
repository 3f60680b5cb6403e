#include "formats/explicit_parts.hpp"

namespace oasis::formats {

bool PrismScanner::read_state(std::uint32_t num_states, const char* what,
                              model::StateIndex& state) {
  const char* token = position();
  const Natural number = read_natural();
  if (number.empty()) {
    error_here(std::string("expected ") + what);
    return false;
  }
  if (number.overflow || number.value >= num_states) {
    error_at(token, number.text.size(),
             "state " + std::string(number.text) + " is out of range: the model has " +
                 std::to_string(num_states) + (num_states == 1 ? " state" : " states"));
    return false;
  }
  state = static_cast<model::StateIndex>(number.value);
  return true;
}

bool PrismScanner::read_index(const char* what, std::uint32_t& index) {
  const char* token = position();
  const Natural number = read_natural();
  if (number.empty()) {
    error_here(std::string("expected ") + what);
    return false;
  }
  if (number.overflow || number.value >= UINT32_MAX) {
    error_at(token, number.text.size(),
             std::string(what) + " " + std::string(number.text) + " is too large");
    return false;
  }
  index = static_cast<std::uint32_t>(number.value);
  return true;
}

bool PrismScanner::expect_line_end(const char* after) {
  skip_blanks();
  if (at_line_end()) return true;
  error_here(std::string("unexpected text after ") + after);
  return false;
}

bool PrismScanner::expect(char c, const std::string& message) {
  if (consume(c)) return true;
  error_here(message);
  return false;
}

}  // namespace oasis::formats
