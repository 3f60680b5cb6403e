// The UMB writer (umb_writer.hpp). What the reader would refuse or read differently is
// refused before a byte is written; the arrays are built in memory, then archived.

#include "formats/umb_writer.hpp"

#include <algorithm>
#include <optional>
#include <set>
#include <vector>

#include <nlohmann/json.hpp>

#include "formats/choice_order.hpp"
#include "formats/drn_writer.hpp"
#include "formats/umb_archive.hpp"
#include "formats/umb_binary.hpp"
#include "formats/umb_index.hpp"
#include "formats/umb_valuations.hpp"

namespace oasis::formats {
namespace {

using Json = nlohmann::ordered_json;
using model::ActionIndex;
using model::EdgeIndex;
using model::StateIndex;

bool all_zero(const model::Context& context) {
  const auto zero = [](ValueId id) { return id == RationalPool::kZero; };
  return std::all_of(context.rewards.state.begin(), context.rewards.state.end(), zero) &&
         std::all_of(context.rewards.choice.begin(), context.rewards.choice.end(), zero);
}

// An annotation identifier ([0-9a-z_-]+, unique in its group) for `name`, which its alias
// keeps whole: lower-case letters, digits, '_' and '-' stay, upper-case letters are lowered,
// anything else becomes '_'; a clash gets "-2", "-3", ...
std::string identifier(const std::string& name, std::set<std::string>& taken) {
  std::string id;
  for (const char c : name.substr(0, 64)) {
    if ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-') {
      id.push_back(c);
    } else if (c >= 'A' && c <= 'Z') {
      id.push_back(static_cast<char>(c - 'A' + 'a'));
    } else {
      id.push_back('_');
    }
  }
  if (id.empty()) id = "_";
  std::string unique = id;
  for (int k = 2; !taken.insert(unique).second; ++k)
    unique = id + "-" + std::to_string(k);
  return unique;
}

// Numbers of one array as rationals of the smallest common size.
class RationalArray {
 public:
  explicit RationalArray(const RationalPool& pool) : pool_(pool) {}

  void add(ValueId id) { ids_.push_back(id); }
  [[nodiscard]] std::uint64_t bits() const {
    std::uint64_t bits = 128;
    std::vector<bool> seen(pool_.size());
    for (const ValueId id : ids_) {
      if (seen[id]) continue;
      seen[id] = true;
      bits = std::max(bits, umb::rational_bits(pool_[id]));
    }
    return bits;
  }
  // The bytes, with values of `bits` bits (at least bits()); each distinct value encoded once.
  [[nodiscard]] std::string bytes(std::uint64_t bits) const {
    std::vector<std::string> encoded(pool_.size());
    std::string out;
    out.reserve(ids_.size() * (bits / 8));
    for (const ValueId id : ids_) {
      std::string& value = encoded[id];
      if (value.empty()) umb::append_rational(value, pool_[id], bits);
      out += value;
    }
    return out;
  }

 private:
  const RationalPool& pool_;
  std::vector<ValueId> ids_;
};

Json rational_type(std::uint64_t bits) {
  return Json{{"type", "rational"}, {"size", bits}};
}

class UmbWriter {
 public:
  UmbWriter(const model::ExplicitModel& model, std::span<const std::size_t> contexts)
      : model_(model), matrix_(*model.contexts.at(contexts.front()).transitions) {
    for (const std::size_t c : contexts)
      contexts_.push_back(&model.contexts.at(c));
    // A lone context "default" without rewards is what a file without rewards reads as.
    if (contexts_.size() == 1 && contexts_[0]->name == "default" && all_zero(*contexts_[0]))
      contexts_.clear();
  }

  [[nodiscard]] std::optional<std::string> problem() const {
    if (model_.type == model::ModelType::kMdp) {
      for (const std::string& name : model_.actions) {
        if (name.empty()) return std::string("an action name is empty");
        if (!is_umb_name(name))
          return "action name '" + name + "' is not UTF-8 text without control characters";
      }
    }
    for (const std::string& name : model_.labels.names) {
      if (name.empty() || !is_umb_name(name) || name.find('"') != std::string::npos)
        return "label name '" + name + "' is empty or holds a '\"' or a control character";
    }
    for (const model::Context* context : contexts_) {
      if (context->name.empty() || !is_umb_name(context->name))
        return "context name '" + context->name + "' is empty or holds a control character";
    }
    if (model_.type != model::ModelType::kDtmc) return std::nullopt;
    for (StateIndex s = 0; s < model_.num_states(); ++s) {
      std::uint32_t enabled = 0;
      for (ActionIndex a = 0; a < model_.num_actions(); ++a)
        enabled += matrix_.enabled(s, a) ? 1 : 0;
      if (enabled > 1) {
        return "state " + std::to_string(s) +
               " of the Markov chain has several choices; a DTMC has one per state";
      }
    }
    return std::nullopt;
  }

  std::vector<UmbEntry> entries() {
    list_choices();
    std::vector<UmbEntry> files;
    files.push_back({"index.json", {}});  // first, as the format asks; filled last
    write_transitions(files);
    write_initial_states(files);
    const std::uint64_t actions = write_actions(files);
    Json annotations = Json::object();
    write_labels(files, annotations);
    write_rewards(files, annotations);
    Json valuations = write_valuations(files);
    files.front().bytes = index(actions, annotations, valuations).dump(2) + "\n";
    return files;
  }

 private:
  // The choices in the order they are written: by state, then in ChoiceOrder.
  void list_choices() {
    const ChoiceOrder order(model_, matrix_);
    std::vector<ActionIndex> actions;
    std::vector<bool> unlabelled;
    state_choices_.push_back(0);
    for (StateIndex s = 0; s < model_.num_states(); ++s) {
      order(s, actions, unlabelled);
      for (std::size_t j = 0; j < actions.size(); ++j)
        choices_.push_back({s, actions[j], unlabelled[j]});
      state_choices_.push_back(choices_.size());
    }
  }

  void write_transitions(std::vector<UmbEntry>& files) {
    const bool one_each =
        std::all_of(state_choices_.begin() + 1, state_choices_.end(),
                    [n = std::uint64_t{0}](std::uint64_t end) mutable { return end == ++n; });
    if (model_.type == model::ModelType::kMdp || !one_each) {
      UmbEntry& states = files.emplace_back(UmbEntry{"state-to-choices.bin", {}});
      for (const std::uint64_t offset : state_choices_)
        umb::append_u64(states.bytes, offset);
    }
    std::string branches;
    std::string targets;
    RationalArray probabilities(model_.values);
    umb::append_u64(branches, 0);
    for (const Choice& choice : choices_) {
      for (EdgeIndex e = matrix_.edges_begin(choice.state, choice.action);
           e < matrix_.edges_end(choice.state, choice.action); ++e) {
        umb::append_u64(targets, matrix_.edge_target[e]);
        probabilities.add(matrix_.edge_probability[e]);
        ++num_branches_;
      }
      umb::append_u64(branches, num_branches_);
    }
    probability_bits_ = probabilities.bits();
    files.push_back({"choice-to-branches.bin", std::move(branches)});
    files.push_back({"branch-to-target.bin", std::move(targets)});
    files.push_back({"branch-to-probability.bin", probabilities.bytes(probability_bits_)});
  }

  std::string bitset(const std::vector<StateIndex>& states) const {
    std::string bytes(umb::bitset_bytes(model_.num_states()), '\0');
    for (const StateIndex s : states)
      bytes[s / 8] = static_cast<char>(static_cast<unsigned char>(bytes[s / 8]) | (1U << (s % 8)));
    return bytes;
  }

  void write_initial_states(std::vector<UmbEntry>& files) {
    std::vector<StateIndex> initial = model_.states.initial;
    std::sort(initial.begin(), initial.end());
    initial.erase(std::unique(initial.begin(), initial.end()), initial.end());
    num_initial_ = initial.size();
    files.push_back({"state-is-initial.bin", bitset(initial)});
  }

  // actions/choices/: the empty string first when a choice is unlabelled, then the names of
  // labelled choices in the model's action order. Returns "#choice-actions".
  std::uint64_t write_actions(std::vector<UmbEntry>& files) {
    if (model_.type == model::ModelType::kDtmc || choices_.empty()) return 0;
    const bool any_unlabelled =
        std::any_of(choices_.begin(), choices_.end(), [](const Choice& c) { return c.unlabelled; });
    std::vector<std::uint32_t> number(model_.num_actions(), UINT32_MAX);
    for (const Choice& choice : choices_) {
      if (!choice.unlabelled) number[choice.action] = 0;  // used: numbered below
    }
    std::vector<std::string_view> names;
    if (any_unlabelled) names.emplace_back();
    for (ActionIndex a = 0; a < model_.num_actions(); ++a) {
      if (number[a] == UINT32_MAX) continue;
      number[a] = static_cast<std::uint32_t>(names.size());
      names.emplace_back(model_.actions[a]);
    }
    std::string values;
    for (const Choice& choice : choices_)
      umb::append_u32(values, choice.unlabelled ? 0 : number[choice.action]);
    std::string mapping;
    std::string strings;
    umb::append_u64(mapping, 0);
    for (const std::string_view name : names) {
      strings += name;
      umb::append_u64(mapping, strings.size());
    }
    files.push_back({"actions/choices/values.bin", std::move(values)});
    files.push_back({"actions/choices/string-mapping.bin", std::move(mapping)});
    files.push_back({"actions/choices/strings.bin", std::move(strings)});
    return names.size();
  }

  void write_labels(std::vector<UmbEntry>& files, Json& annotations) {
    std::vector<std::uint32_t> order;
    for (std::uint32_t l = 0; l < model_.labels.names.size(); ++l) {
      if (model_.labels.names[l] != "init") order.push_back(l);
    }
    if (order.empty()) return;
    std::sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) {
      return model_.labels.names[x] < model_.labels.names[y];
    });
    std::vector<std::vector<StateIndex>> states(model_.labels.names.size());
    for (StateIndex s = 0; s < model_.num_states(); ++s) {
      for (const std::uint32_t l : model_.labels.of(s))
        states[l].push_back(s);
    }
    std::set<std::string> taken;
    Json aps = Json::object();
    for (const std::uint32_t l : order) {
      const std::string& name = model_.labels.names[l];
      const std::string id = identifier(name, taken);
      aps[id] = Json{{"alias", name},
                     {"applies-to", Json::array({"states"})},
                     {"type", Json{{"type", "bool"}, {"size", 1}}}};
      files.push_back({"annotations/aps/" + id + "/states/values.bin", bitset(states[l])});
    }
    annotations["aps"] = std::move(aps);
  }

  void write_rewards(std::vector<UmbEntry>& files, Json& annotations) {
    if (contexts_.empty()) return;
    std::set<std::string> taken;
    Json rewards = Json::object();
    for (const model::Context* context : contexts_) {
      const std::string id = identifier(context->name, taken);
      RationalArray state(model_.values);
      RationalArray choice(model_.values);
      bool state_nonzero = false;
      bool choice_nonzero = false;
      for (StateIndex s = 0; s < model_.num_states(); ++s) {
        state.add(context->rewards.state[s]);
        state_nonzero = state_nonzero || context->rewards.state[s] != RationalPool::kZero;
      }
      for (const Choice& c : choices_) {
        const ValueId value = context->rewards.choice.empty()
                                  ? RationalPool::kZero
                                  : context->rewards.choice[matrix_.choice(c.state, c.action)];
        choice.add(value);
        choice_nonzero = choice_nonzero || value != RationalPool::kZero;
      }
      // A context without any reward still needs an array to be a reward annotation.
      const bool states = state_nonzero || !choice_nonzero;
      const std::uint64_t bits = std::max(states ? state.bits() : std::uint64_t{128},
                                          choice_nonzero ? choice.bits() : std::uint64_t{128});
      Json applies = Json::array();
      if (states) applies.push_back("states");
      if (choice_nonzero) applies.push_back("choices");
      rewards[id] = Json{{"alias", context->name},
                         {"applies-to", std::move(applies)},
                         {"type", rational_type(bits)}};
      const std::string folder = "annotations/rewards/" + id + "/";
      if (states) files.push_back({folder + "states/values.bin", state.bytes(bits)});
      if (choice_nonzero) files.push_back({folder + "choices/values.bin", choice.bytes(bits)});
    }
    annotations["rewards"] = std::move(rewards);
  }

  // The states' variables, bit-packed in the fewest bits (umb_valuations.hpp); null when the
  // model has none (or names the reader would not take back).
  Json write_valuations(std::vector<UmbEntry>& files) const {
    const std::optional<UmbValuationClass> shape = umb_valuation_class(model_.states);
    if (!shape) return nullptr;
    Json variables = Json::array();
    for (const UmbField& field : shape->fields) {
      if (field.kind == UmbField::Kind::kPadding) {
        variables.push_back(Json{{"padding", field.bits}});
        continue;
      }
      const char* type = field.kind == UmbField::Kind::kInt ? "int" : "uint";
      variables.push_back(
          Json{{"name", field.name}, {"type", Json{{"type", type}, {"size", field.bits}}}});
    }
    files.push_back(
        {"valuations/states/valuations.bin", encode_umb_valuations(model_.states, *shape)});
    return Json{{"states", Json{{"unique", false},
                                {"classes", Json::array({Json{{"variables", variables}}})}}}};
  }

  [[nodiscard]] Json index(std::uint64_t actions, Json& annotations, Json& valuations) const {
    Json ts = Json::object();
    ts["time"] = "discrete";
    ts["#players"] = model_.type == model::ModelType::kDtmc ? 0 : 1;
    ts["#states"] = model_.num_states();
    ts["#initial-states"] = num_initial_;
    ts["#choices"] = choices_.size();
    ts["#choice-actions"] = actions;
    ts["#branches"] = num_branches_;
    ts["#branch-actions"] = 0;
    ts["#observations"] = 0;
    ts["branch-probability-type"] = rational_type(probability_bits_);
    Json json = Json::object();
    json["format-version"] = 1;
    json["format-revision"] = 0;
    json["file-data"] = Json{{"tool", "oasisc"}, {"tool-version", OASIS_VERSION}};
    json["transition-system"] = std::move(ts);
    if (!annotations.empty()) json["annotations"] = std::move(annotations);
    if (!valuations.is_null()) json["valuations"] = std::move(valuations);
    return json;
  }

  struct Choice {
    StateIndex state;
    ActionIndex action;
    bool unlabelled;
  };

  const model::ExplicitModel& model_;
  const model::TransitionMatrix& matrix_;
  std::vector<const model::Context*> contexts_;
  std::vector<Choice> choices_;
  std::vector<std::uint64_t> state_choices_;
  std::uint64_t num_branches_ = 0;
  std::uint64_t num_initial_ = 0;
  std::uint64_t probability_bits_ = 128;
};

}  // namespace

bool write_umb_bytes(const model::ExplicitModel& model, std::span<const std::size_t> contexts,
                     std::string& bytes, std::string& error) {
  if (contexts.empty()) {
    error = "cannot write a UMB file: no context chosen";
    return false;
  }
  for (const std::size_t c : contexts) {
    if (!same_transitions(model, contexts.front(), c)) {
      error = "cannot write a UMB file: contexts '" + model.contexts.at(contexts.front()).name +
              "' and '" + model.contexts.at(c).name +
              "' have different transitions; choose one with --context";
      return false;
    }
  }
  UmbWriter writer(model, contexts);
  if (auto problem = writer.problem()) {
    error = "cannot write a UMB file: " + *problem;
    return false;
  }
  bytes.clear();
  return write_umb_archive(writer.entries(), bytes, error);
}

bool write_umb(const model::ExplicitModel& model, std::span<const std::size_t> contexts,
               AtomicFile& out, std::string& error) {
  std::string bytes;
  if (!write_umb_bytes(model, contexts, bytes, error)) return false;
  out.append(bytes);
  if (out.good()) return true;
  error = out.error();
  return false;
}

bool write_umb_file(const model::ExplicitModel& model, std::span<const std::size_t> contexts,
                    const std::string& path, std::string& error) {
  return write_atomically(path, error, [&](AtomicFile& out, std::string& why) {
    return write_umb(model, contexts, out, why);
  });
}

}  // namespace oasis::formats
