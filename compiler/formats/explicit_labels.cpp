// The .lab file: its labels are the model's atomic propositions, and "init" gives the initial
// states. PRISM's form, and Storm's (AtomicPropositionLabelingParser), told apart by the
// first line:
//
//   0="init" 1="deadlock" 2="done"          #DECLARATION
//   0: 0                                    init deadlock done
//   4: 1 2                                  #END
//                                           0 init
//                                           4 deadlock done
//
// In Storm's form the names are blank-separated words between #DECLARATION and #END (on any
// number of lines), and the states are listed in increasing order, each once.

#include <unordered_map>

#include "formats/explicit_parts.hpp"
#include "support/text.hpp"

namespace oasis::formats {
namespace {

class LabelsReader {
 public:
  LabelsReader(FileId file, DiagnosticEngine& diagnostics, std::uint32_t num_states,
               std::vector<model::StateIndex>& initial)
      : scan_(file, diagnostics), num_states_(num_states), initial_(initial) {}

  bool read(bool& found, model::StateLabels& labels) {
    const std::size_t errors = scan_.diagnostics().error_count();
    scan_.skip_blank_lines();
    scan_.skip_blanks();
    const bool storm = scan_.rest_of_line().starts_with("#DECLARATION");
    if (!(storm ? read_declaration() : read_names())) return false;
    found = init_ != kNone;
    model::StateLabelsBuilder builder(names_);
    while (scan_.next_line() && !scan_.diagnostics().should_stop()) {
      if (storm) {
        read_storm_state(builder);
      } else {
        read_state(builder);
      }
      scan_.skip_line();
    }
    labels = builder.finish(num_states_);
    return scan_.diagnostics().error_count() == errors;
  }

 private:
  static constexpr std::uint32_t kNone = UINT32_MAX;

  // `0="init" 1="deadlock" ...`: indices in order from 0, as PRISM writes and requires.
  bool read_names() {
    if (!scan_.next_line()) return true;  // an empty file: no labels at all
    while (!scan_.at_line_end()) {
      const char* token = scan_.position();
      std::uint32_t index = 0;
      if (!scan_.read_index("a label index", index)) return false;
      if (index != count_) {
        scan_.error_at(token, 1, "expected label index " + std::to_string(count_));
        return false;
      }
      if (!scan_.expect('=', "expected '=' after the label index")) return false;
      if (!scan_.expect('"', "expected the quoted label name")) return false;
      const std::string_view rest = scan_.rest_of_line();
      const std::size_t close = rest.find('"');
      if (close == std::string_view::npos) {
        scan_.error_here("unterminated label name");
        return false;
      }
      const std::string_view name = rest.substr(0, close);
      if (!acceptable_name(name, scan_.position())) return false;
      if (name == "init") init_ = index;
      names_.emplace_back(name);
      scan_.seek(scan_.position() + close + 1);
      ++count_;
      scan_.skip_blanks();
    }
    scan_.skip_line();
    return true;
  }

  // Storm's "#DECLARATION name name ... #END".
  bool read_declaration() {
    const char* declaration = scan_.position();
    scan_.skip_line();
    for (;;) {
      scan_.skip_blank_lines();
      scan_.skip_blanks();
      if (scan_.at_end()) {
        scan_.error_at(declaration, 12, "'#DECLARATION' without its '#END'");
        return false;
      }
      const char* token = scan_.position();
      const std::string_view name = scan_.read_word();
      if (name == "#END") break;
      if (!acceptable_name(name, token)) return false;
      if (name == "init") init_ = count_;
      indices_.emplace(std::string(name), count_);
      names_.emplace_back(name);
      ++count_;
      scan_.skip_blanks();
      if (scan_.at_line_end()) scan_.skip_line();
    }
    scan_.skip_line();
    return true;
  }

  // A name is a model's atomic proposition: it must be one a user can name (not empty, no NUL
  // or other control character, which no message or file could show as it is, and no '"',
  // which PRISM's .lab and a property's "label" use to quote it, so neither could write it)
  // and appear once, so that "init" gives the initial states once and --respect-labels picks
  // one label.
  bool acceptable_name(std::string_view name, const char* at) {
    if (name.empty()) {
      scan_.error_at(at, 1, "empty label name");
      return false;
    }
    for (std::size_t i = 0; i < name.size(); ++i) {
      const auto byte = static_cast<unsigned char>(name[i]);
      if (byte == '"') {
        scan_.error_at(at + i, 1,
                       "a label name cannot hold '\"' (PRISM's labels and properties quote "
                       "names with it)");
        return false;
      }
      if (byte >= 0x20 && byte != 0x7f) continue;
      scan_.error_at(at + i, 1,
                     byte == 0 ? std::string("a label name cannot hold a NUL character")
                               : "a label name cannot hold a control character (" +
                                     text::printable_excerpt(name.substr(i, 1)) + ")");
      return false;
    }
    for (std::uint32_t k = 0; k < names_.size(); ++k) {
      if (names_[k] != name) continue;
      scan_.error_at(at, name.size(),
                     "label " + quoted(name) + " is declared twice (as label " + std::to_string(k) +
                         " and label " + std::to_string(count_) + ")");
      return false;
    }
    return true;
  }

  void read_state(model::StateLabelsBuilder& builder) {
    model::StateIndex state = 0;
    if (!scan_.read_state(num_states_, "a state index", state)) return;
    scan_.skip_blanks();
    if (!scan_.expect(':', "expected ':' after the state index")) return;
    for (scan_.skip_blanks(); !scan_.at_line_end(); scan_.skip_blanks()) {
      const char* token = scan_.position();
      std::uint32_t label = 0;
      if (!scan_.read_index("a label index", label)) return;
      if (label >= count_) {
        scan_.error_at(token, 1,
                       "label " + std::to_string(label) + " is not declared in the first line");
        return;
      }
      if (label == init_) initial_.push_back(state);
      builder.add(state, label);
    }
  }

  // Storm's "STATE name name ...", states in increasing order.
  void read_storm_state(model::StateLabelsBuilder& builder) {
    const char* token = scan_.position();
    model::StateIndex state = 0;
    if (!scan_.read_state(num_states_, "a state index", state)) return;
    if (any_state_ && state <= last_state_) {
      scan_.error_at(token, 1,
                     "state " + std::to_string(state) + " after state " +
                         std::to_string(last_state_) +
                         ": Storm's labels list each state once, in increasing order");
      return;
    }
    any_state_ = true;
    last_state_ = state;
    for (scan_.skip_blanks(); !scan_.at_line_end(); scan_.skip_blanks()) {
      const char* at = scan_.position();
      const std::string_view name = scan_.read_word();
      const auto found = indices_.find(std::string(name));
      if (found == indices_.end()) {
        scan_.error_at(at, name.size(),
                       "label " + quoted(name) + " is not declared between #DECLARATION and #END");
        return;
      }
      if (found->second == init_) initial_.push_back(state);
      builder.add(state, found->second);
    }
  }

  PrismScanner scan_;
  std::unordered_map<std::string, std::uint32_t> indices_;  // Storm's form: name -> index
  bool any_state_ = false;
  model::StateIndex last_state_ = 0;
  std::uint32_t num_states_;
  std::vector<model::StateIndex>& initial_;
  std::uint32_t count_ = 0;
  std::uint32_t init_ = kNone;
  std::vector<std::string> names_;
};

}  // namespace

bool read_prism_labels(FileId file, DiagnosticEngine& diagnostics, std::uint32_t num_states,
                       std::vector<model::StateIndex>& initial, model::StateLabels& labels,
                       bool& found) {
  found = false;
  return LabelsReader(file, diagnostics, num_states, initial).read(found, labels);
}

}  // namespace oasis::formats
