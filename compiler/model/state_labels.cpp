#include "model/state_labels.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace oasis::model {

std::optional<std::uint32_t> StateLabels::find(std::string_view name) const {
  for (std::uint32_t k = 0; k < names.size(); ++k)
    if (names[k] == name) return k;
  return std::nullopt;
}

StateLabels StateLabelsBuilder::finish(std::uint32_t num_states) {
  StateLabels labels;
  labels.names = std::move(names_);
  if (labels.names.empty()) return labels;
  std::sort(pairs_.begin(), pairs_.end());
  pairs_.erase(std::unique(pairs_.begin(), pairs_.end()), pairs_.end());
  labels.begin.assign(std::size_t{num_states} + 1, 0);
  for (const auto& [state, label] : pairs_)
    ++labels.begin[state + 1];
  for (std::size_t s = 0; s < num_states; ++s)
    labels.begin[s + 1] += labels.begin[s];
  labels.label.reserve(pairs_.size());
  for (const auto& pair : pairs_)
    labels.label.push_back(pair.second);
  pairs_.clear();
  return labels;
}

std::optional<LabelSelection> LabelSelection::parse(std::string_view text) {
  if (text == "all") return LabelSelection{};
  if (text == "none") return LabelSelection{Kind::kNone, {}};
  LabelSelection selection{Kind::kNamed, {}};
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string_view name = text.substr(start, comma - start);
    if (name.empty()) return std::nullopt;
    selection.names.emplace_back(name);
    start = comma + 1;
  }
  return selection;
}

std::string LabelSelection::describe() const {
  switch (kind) {
    case Kind::kAll:
      return "all";
    case Kind::kNone:
      return "none";
    case Kind::kNamed:
      break;
  }
  std::string text;
  for (const std::string& name : names)
    text += (text.empty() ? "" : ",") + name;
  return text;
}

std::vector<std::uint32_t> label_classes(const StateLabels& labels, std::uint32_t num_states,
                                         const LabelSelection& selection) {
  std::vector<bool> respected(labels.names.size(), selection.kind == LabelSelection::Kind::kAll);
  for (const std::string& name : selection.names) {
    const std::optional<std::uint32_t> index = labels.find(name);
    if (!index) {
      std::string known;
      for (const std::string& have : labels.names)
        known += (known.empty() ? "" : ", ") + have;
      throw std::invalid_argument("no label \"" + name + "\" in the model (it has: " +
                                  (known.empty() ? "no labels" : known) + ")");
    }
    respected[*index] = true;
  }
  if (std::find(respected.begin(), respected.end(), true) == respected.end()) return {};
  std::map<std::vector<std::uint32_t>, std::uint32_t> class_of_set;
  std::vector<std::uint32_t> classes(num_states);
  std::vector<std::uint32_t> held;
  for (std::uint32_t s = 0; s < num_states; ++s) {
    held.clear();
    for (std::uint32_t label : labels.of(s))
      if (respected[label]) held.push_back(label);
    classes[s] = class_of_set.try_emplace(held, static_cast<std::uint32_t>(class_of_set.size()))
                     .first->second;
  }
  return classes;
}

}  // namespace oasis::model
