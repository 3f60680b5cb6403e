#pragma once
// Atomic propositions: the labels that hold in each state (a PRISM .lab file, PRISM's `label`s).
// To a model checker they are the observable behaviour, so bisimulation keeps apart states whose
// respected labels differ. Which labels are respected follows Storm's
// `respectedAtomicPropositions`: all of them (the default), none, or those named.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace oasis::model {

struct StateLabels {
  std::vector<std::string> names;
  // State s holds the labels label[begin[s] .. begin[s+1]), ascending indices into `names`.
  // Both are empty when the model has no labels.
  std::vector<std::uint32_t> begin;
  std::vector<std::uint32_t> label;

  [[nodiscard]] bool empty() const { return names.empty(); }
  [[nodiscard]] std::span<const std::uint32_t> of(std::uint32_t state) const {
    if (begin.empty()) return {};
    return {label.data() + begin[state], label.data() + begin[state + 1]};
  }
  // The index of the label called `name`, if there is one.
  [[nodiscard]] std::optional<std::uint32_t> find(std::string_view name) const;
};

// Builds StateLabels from (state, label) pairs in any order; a pair given twice counts once.
class StateLabelsBuilder {
 public:
  explicit StateLabelsBuilder(std::vector<std::string> names) : names_(std::move(names)) {}
  void add(std::uint32_t state, std::uint32_t label) { pairs_.emplace_back(state, label); }
  [[nodiscard]] StateLabels finish(std::uint32_t num_states);

 private:
  std::vector<std::string> names_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs_;
};

// Which labels bisimulation respects.
struct LabelSelection {
  enum class Kind { kAll, kNone, kNamed };
  Kind kind = Kind::kAll;
  std::vector<std::string> names;  // kNamed only

  // "all", "none", or labels separated by commas ("one,done"); nothing for an empty name.
  static std::optional<LabelSelection> parse(std::string_view text);
  [[nodiscard]] std::string describe() const;
};

// Per state, a class number: two states share one exactly when the same respected labels hold
// in them. Empty when nothing is respected (no labels, or kNone), which every caller reads as
// "one class". Throws std::invalid_argument naming a selected label the model does not have.
std::vector<std::uint32_t> label_classes(const StateLabels& labels, std::uint32_t num_states,
                                         const LabelSelection& selection);

}  // namespace oasis::model
