// The .sta file: the variables, then each state's valuation.
//
//   (x,y,b)
//   0:(0,1,false)
//   1:(-2,0,true)
//
// Booleans become 0 and 1 (StateSpace valuations are integers).

#include <charconv>
#include <vector>

#include "formats/explicit_parts.hpp"
#include "support/text.hpp"

namespace oasis::formats {
namespace {

class StatesReader {
 public:
  StatesReader(FileId file, DiagnosticEngine& diagnostics, model::StateSpace& states)
      : scan_(file, diagnostics), states_(states) {}

  bool read() {
    const std::size_t errors = scan_.diagnostics().error_count();
    if (!read_variables()) return false;
    const std::size_t width = states_.variables.size();
    states_.valuations.assign(std::size_t{states_.size} * width, 0);
    listed_.assign(states_.size, false);
    while (scan_.next_line() && !scan_.diagnostics().should_stop()) {
      read_state();
      scan_.skip_line();
    }
    check_all_listed();
    return scan_.diagnostics().error_count() == errors;
  }

 private:
  bool read_variables() {
    if (!scan_.next_line()) {
      scan_.error_here("empty states file: expected the variables '(x,y,...)'");
      return false;
    }
    header_ = scan_.position();
    if (!scan_.expect('(', "expected the variables '(x,y,...)'")) return false;
    const std::string_view line = scan_.rest_of_line();
    const std::size_t close = line.find(')');
    if (close == std::string_view::npos) {
      scan_.error_here("expected ')' to close the variables");
      return false;
    }
    std::string_view names = line.substr(0, close);
    while (!trim_blanks(names).empty()) {
      const std::size_t comma = names.find(',');
      states_.variables.emplace_back(trim_blanks(names.substr(0, comma)));
      if (states_.variables.back().empty()) {
        scan_.error_here("empty variable name");
        return false;
      }
      if (comma == std::string_view::npos) break;
      names.remove_prefix(comma + 1);
    }
    scan_.seek(scan_.position() + close + 1);
    if (!scan_.expect_line_end("the variables")) return false;
    scan_.skip_line();
    return true;
  }

  void read_state() {
    model::StateIndex state = 0;
    const char* token = scan_.position();
    if (!scan_.read_state(states_.size, "a state index", state)) return;
    if (listed_[state]) {
      scan_.error_at(token, 1, "state " + std::to_string(state) + " is listed twice");
      return;
    }
    scan_.skip_blanks();
    if (!scan_.expect(':', "expected ':' after the state index")) return;
    scan_.skip_blanks();
    if (!scan_.expect('(', "expected '(' before the values")) return;
    const std::size_t width = states_.variables.size();
    for (std::size_t v = 0; v < width; ++v) {
      if (v > 0 && !scan_.expect(',', "expected ',' between values")) return;
      if (!read_value(states_.valuations[state * width + v])) return;
    }
    if (!scan_.expect(')', "expected ')' after " + std::to_string(width) +
                               (width == 1 ? " value" : " values") + ", as in the header")) {
      return;
    }
    if (!scan_.expect_line_end("the values")) return;
    listed_[state] = true;
  }

  bool read_value(std::int64_t& value) {
    scan_.skip_blanks();
    const char* start = scan_.position();
    const char* stop = start;
    while (stop < scan_.end() && *stop != ',' && *stop != ')' && *stop != '\n')
      ++stop;
    const std::string_view text = trim_blanks({start, static_cast<std::size_t>(stop - start)});
    scan_.seek(stop);
    if (text == "true" || text == "false") {
      value = text == "true" ? 1 : 0;
      return true;
    }
    const auto [end, code] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (code == std::errc() && end == text.data() + text.size() && !text.empty()) return true;
    scan_.error_at(start, text.size(),
                   "value '" + std::string(text) + "' is not an integer or boolean");
    return false;
  }

  void check_all_listed() {
    if (scan_.diagnostics().should_stop()) return;
    std::size_t missing = 0;
    model::StateIndex first = 0;
    for (model::StateIndex s = states_.size; s-- > 0;) {
      if (!listed_[s]) {
        ++missing;
        first = s;
      }
    }
    if (missing == 0) return;
    scan_.error_at(header_, 1,
                   std::to_string(missing) + " of the " + std::to_string(states_.size) +
                       " states have no valuation here, the first being state " +
                       std::to_string(first));
  }

  PrismScanner scan_;
  model::StateSpace& states_;
  std::vector<bool> listed_;
  const char* header_ = nullptr;
};

}  // namespace

bool read_prism_states(FileId file, DiagnosticEngine& diagnostics, model::StateSpace& states) {
  return StatesReader(file, diagnostics, states).read();
}

}  // namespace oasis::formats
