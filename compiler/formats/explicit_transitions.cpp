// The .tra file of a PRISM MDP or Markov chain (DTMC):
//
//   # comments and blank lines anywhere
//   STATES CHOICES TRANSITIONS        or, for a Markov chain,   STATES TRANSITIONS
//   - - INITIAL -          (optional; PRISM writes these for some model types)
//   SOURCE CHOICE TARGET PROBABILITY [ACTION]                  SOURCE TARGET PROBABILITY [ACTION]
//
// Storm's explicit files (its AutoParser) start with the model type, `dtmc` or `mdp`, and have
// no header: the states are 0 to the largest index a row names. Both forms are read, and a
// type line before PRISM's header too.
//
// Rows of one (SOURCE, CHOICE) must be adjacent, as PRISM writes them; they form one
// distribution whose probabilities must sum to 1 (or to within ReadOptions::tolerance). A
// Markov chain is read as an MDP with one action, "[0]": each state's rows are its one
// distribution, and their action labels, which a chain does not choose by, are read and set
// aside.

#include <algorithm>
#include <unordered_map>

#include "formats/exact_sum.hpp"
#include "formats/explicit_parts.hpp"
#include "formats/explicit_reader.hpp"
#include "formats/model_size.hpp"

namespace oasis::formats {
namespace {

using model::StateIndex;

class TransitionsReader {
 public:
  TransitionsReader(FileId file, DiagnosticEngine& diagnostics, const ReadOptions& options,
                    ValueCache& values, PrismTransitions& result)
      : scan_(file, diagnostics), options_(options), values_(values), result_(result) {}

  bool read() {
    const std::size_t errors = scan_.diagnostics().error_count();
    if (!read_header()) return false;
    while (scan_.next_line() && !scan_.diagnostics().should_stop()) {
      if (scan_.peek() == '-') {
        read_initial_line();
      } else {
        read_row();
      }
      scan_.skip_line();
      if (result_.collector.full()) {
        scan_.error_here("the file has more than 2^32 transitions");
        break;
      }
    }
    close_choice();
    check_counts();
    return scan_.diagnostics().error_count() == errors;
  }

 private:
  bool read_header() {
    if (!scan_.next_line()) {
      scan_.error_here("empty transitions file: expected the header 'states choices transitions'");
      return false;
    }
    if (is_letter(scan_.peek())) {
      if (!read_type_line()) return false;
      if (storm_) return count_storm_states();
    }
    header_ = scan_.position();
    std::uint64_t numbers[4] = {};
    int count = 0;
    while (count < 4 && TextScanner::is_digit(scan_.peek())) {
      const Natural number = scan_.read_natural();
      numbers[count++] = number.overflow ? UINT64_MAX : number.value;
      scan_.skip_blanks();
    }
    if ((count != 2 && count != 3) || !scan_.at_line_end()) {
      scan_.error_at(header_, scan_.rest_of_line().size(),
                     "expected the header 'states choices transitions' of an MDP, or 'states "
                     "transitions' of a Markov chain");
      return false;
    }
    result_.markov_chain = count == 2;
    if (numbers[0] == 0) {
      scan_.error_at(header_, 1, "the header declares no states");
      return false;
    }
    if (const auto refusal =
            state_count_refusal(std::to_string(numbers[0]), numbers[0], options_)) {
      scan_.error_at(header_, 1, "the header declares " + *refusal);
      return false;
    }
    result_.num_states = static_cast<std::uint32_t>(numbers[0]);
    declared_choices_ = result_.markov_chain ? 0 : numbers[1];
    declared_rows_ = numbers[count - 1];
    // Before the body is read or anything is reserved for it. A Markov chain's header counts
    // its rows (edges) only; its choices, one per state with rows, are left out of the bound.
    const DeclaredSize size{.states = numbers[0],
                            .choices = result_.markov_chain ? 0 : declared_choices_,
                            .edges = declared_rows_};
    if (const auto refusal = memory_refusal(size, options_)) {
      scan_.error_at(
          header_, scan_.rest_of_line().size(),
          "the header declares " + std::to_string(numbers[0]) + " states" +
              (result_.markov_chain ? "" : ", " + std::to_string(declared_choices_) + " choices") +
              " and " + std::to_string(declared_rows_) + " transitions: " + *refusal);
      return false;
    }
    const std::size_t reserve = std::min<std::uint64_t>(declared_rows_, scan_.end() - header_);
    const std::uint64_t choices = result_.markov_chain ? numbers[0] : declared_choices_;
    result_.collector.reserve(std::min<std::uint64_t>(choices, reserve), reserve);
    scan_.skip_line();
    return true;
  }

  static bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

  // Storm's first line, the model type. PRISM's header may follow it (one number fewer than
  // a row); otherwise the file is in Storm's form.
  bool read_type_line() {
    const char* token = scan_.position();
    std::string type(scan_.read_word());
    for (char& c : type)
      c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    if (type != "dtmc" && type != "mdp") {
      const bool known = type == "ctmc" || type == "ma";
      scan_.error_at(
          token, type.size(),
          known ? "Storm's explicit " + type + " files are not supported: oasis reads dtmc and mdp"
                : std::string("expected the model type 'dtmc' or 'mdp' (Storm), or "
                              "the header 'states choices transitions' (PRISM)"));
      return false;
    }
    if (!scan_.expect_line_end("the model type")) return false;
    result_.markov_chain = type == "dtmc";
    scan_.skip_line();
    if (!scan_.next_line()) {
      scan_.error_here("no transitions after the model type");
      return false;
    }
    storm_ = count_fields(scan_.rest_of_line()) != (result_.markov_chain ? 2 : 3);
    return true;
  }

  static int count_fields(std::string_view line) {
    int fields = 0;
    bool in_field = false;
    for (const char c : line) {
      const bool blank = TextScanner::is_blank(c);
      if (!blank && !in_field) ++fields;
      in_field = !blank;
    }
    return fields;
  }

  // Storm's form has no header: the states are 0 to the largest state a row names. Rows
  // that do not parse are skipped here and reported by read_row().
  bool count_storm_states() {
    header_ = scan_.position();
    std::uint64_t largest = 0;
    bool any = false;
    while (scan_.next_line()) {
      for (int field = 0; field < (result_.markov_chain ? 2 : 3); ++field) {
        const char* token = scan_.position();
        const Natural number = scan_.read_natural();
        if (number.empty()) break;
        scan_.skip_blanks();
        if (!result_.markov_chain && field == 1) continue;  // the choice index
        if (number.overflow || number.value >= options_.max_states) {
          scan_.error_at(token, number.text.size(),
                         "state " + std::string(number.text) + " is beyond the limit of " +
                             std::to_string(options_.max_states) + " states" +
                             (options_.max_states < limits::kMaxStates
                                  ? " (raise it with --max-states)"
                                  : " (states are numbered with 32 bits)"));
          return false;
        }
        largest = std::max<std::uint64_t>(largest, number.value);
        any = true;
      }
      scan_.skip_line();
    }
    scan_.seek(header_);
    if (!any) {
      scan_.error_here("no transitions after the model type");
      return false;
    }
    result_.num_states = static_cast<std::uint32_t>(largest + 1);
    return true;
  }

  // "- - s -": PRISM's way of listing initial states inside the .tra file.
  void read_initial_line() {
    scan_.consume('-');
    scan_.skip_blanks();
    if (!scan_.expect('-', "expected '- - state -' for an initial state")) return;
    scan_.skip_blanks();
    StateIndex state = 0;
    if (!scan_.read_state(result_.num_states, "the initial state", state)) return;
    scan_.skip_blanks();
    scan_.consume('-');
    if (!scan_.expect_line_end("the initial state")) return;
    result_.initial.push_back(state);
    result_.has_initial_lines = true;
  }

  void read_row() {
    const char* row = scan_.position();
    StateIndex source = 0;
    std::uint32_t choice = 0;
    StateIndex target = 0;
    if (!scan_.read_state(result_.num_states, "the source state", source)) return;
    scan_.skip_blanks();
    if (!result_.markov_chain && !scan_.read_index("the choice index", choice)) return;
    scan_.skip_blanks();
    if (!scan_.read_state(result_.num_states, "the target state", target)) return;
    scan_.skip_blanks();
    const std::optional<ValueId> probability = read_probability();
    if (!probability) return;
    scan_.skip_blanks();
    const char* action_token = scan_.position();
    const std::string_view action = scan_.read_word();
    if (!scan_.expect_line_end("the action")) return;
    ++rows_;
    if (!open_ || source != source_ || choice != choice_) {
      close_choice();
      open_choice(row, source, choice, result_.markov_chain ? std::string_view() : action);
    } else if (!result_.markov_chain && action != action_text_) {
      report_action_mismatch(action_token, action);
      return;
    }
    result_.collector.add(target, *probability);
    sum_.add(*probability, values_);
  }

  std::optional<ValueId> read_probability() {
    const char* token = scan_.position();
    const std::string_view text = scan_.read_word();
    if (text.empty()) {
      scan_.error_here("expected the probability");
      return std::nullopt;
    }
    const std::optional<ValueId> id = values_.intern_text(text);
    if (!id) {
      scan_.error_at(token, text.size(), "probability '" + std::string(text) + "' is not a number");
      return std::nullopt;
    }
    if (sgn(values_.pool()[*id]) <= 0) {
      scan_.error_at(token, text.size(), "probability must be positive");
      return std::nullopt;
    }
    if (!values_.check_carried(*id, "probability", scan_.range_at(token, text.size()),
                               scan_.diagnostics())) {
      return std::nullopt;
    }
    return id;
  }

  void open_choice(const char* row, StateIndex source, std::uint32_t choice,
                   std::string_view action) {
    open_ = true;
    source_ = source;
    choice_ = choice;
    action_text_ = action;
    action_line_ = scan_.line_of(scan_.offset_of(row));
    const std::string name = action.empty() ? unlabelled_action_name(choice) : std::string(action);
    result_.collector.begin(source, action_index(name), scan_.offset_of(row), choice);
    ++choices_;
    sum_.reset();
  }

  // Checks the sum of the choice that just ended.
  void close_choice() {
    if (!open_) return;
    open_ = false;
    if (sum_.compare_to_one() == 0) return;
    const Rational sum = sum_.value();
    if (options_.tolerance && abs(sum - 1) <= *options_.tolerance) return;
    const std::uint32_t d = static_cast<std::uint32_t>(result_.collector.size() - 1);
    const SourceLocation where{scan_.file(), result_.collector.offset(d)};
    scan_.diagnostics().error(where, "probabilities of state " + std::to_string(source_) +
                                         ", choice " + std::to_string(choice_) + " sum to " +
                                         describe(sum) + ", not 1");
  }

  void report_action_mismatch(const char* token, std::string_view action) {
    const auto quoted = [](std::string_view name) {
      return name.empty() ? std::string("no action") : "action '" + std::string(name) + "'";
    };
    scan_.error_at(token, action.size(),
                   "state " + std::to_string(source_) + ", choice " + std::to_string(choice_) +
                       " has " + quoted(action) + " here but " + quoted(action_text_) +
                       " on line " + std::to_string(action_line_));
  }

  model::ActionIndex action_index(const std::string& name) {
    const auto [it, inserted] =
        action_indices_.try_emplace(name, static_cast<model::ActionIndex>(result_.actions.size()));
    if (inserted) result_.actions.push_back(name);
    return it->second;
  }

  void check_counts() {
    if (scan_.diagnostics().should_stop() || storm_) return;
    if (!result_.markov_chain && choices_ != declared_choices_) {
      scan_.error_at(header_, 1,
                     "the header declares " + std::to_string(declared_choices_) +
                         " choices but the file has " + std::to_string(choices_));
    }
    if (rows_ != declared_rows_) {
      scan_.error_at(header_, 1,
                     "the header declares " + std::to_string(declared_rows_) +
                         " transitions but the file has " + std::to_string(rows_));
    }
  }

  PrismScanner scan_;
  const ReadOptions& options_;
  ValueCache& values_;
  PrismTransitions& result_;
  ExactSum sum_;
  std::unordered_map<std::string, model::ActionIndex> action_indices_;

  const char* header_ = nullptr;
  bool storm_ = false;  // Storm's form: a model type line and no header
  std::uint64_t declared_choices_ = 0;
  std::uint64_t declared_rows_ = 0;
  std::uint64_t choices_ = 0;
  std::uint64_t rows_ = 0;

  // The choice whose rows are being read.
  bool open_ = false;
  StateIndex source_ = 0;
  std::uint32_t choice_ = 0;
  std::string_view action_text_;
  std::uint32_t action_line_ = 0;
};

}  // namespace

bool read_prism_transitions(FileId file, DiagnosticEngine& diagnostics, const ReadOptions& options,
                            ValueCache& values, PrismTransitions& transitions) {
  return TransitionsReader(file, diagnostics, options, values, transitions).read();
}

}  // namespace oasis::formats
