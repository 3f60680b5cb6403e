// The DRN writer (drn_writer.hpp). What the reader would refuse or read differently is
// refused before a byte is written.

#include "formats/drn_writer.hpp"

#include <algorithm>
#include <optional>
#include <vector>

#include "formats/choice_order.hpp"
#include "formats/value_text.hpp"

namespace oasis::formats {
namespace {

using model::ActionIndex;
using model::EdgeIndex;
using model::StateIndex;

constexpr std::string_view kNoLabel = "__NOLABEL__";

bool has_blank(std::string_view name) {
  return name.find_first_of(" \t\r\n") != std::string_view::npos;
}

bool has_control_or_quote(std::string_view name) {
  return std::any_of(name.begin(), name.end(), [](char c) {
    const auto byte = static_cast<unsigned char>(c);
    return byte < 0x20 || byte == 0x7f || c == '"';
  });
}

std::optional<std::string> action_problem(const std::string& name) {
  if (name.empty()) return std::string("an action name is empty");
  if (has_blank(name)) return "action name '" + name + "' has blanks";
  if (name == kNoLabel) return "action name '" + name + "' is Storm's mark of an unlabelled choice";
  return std::nullopt;
}

std::optional<std::string> label_problem(const std::string& name) {
  if (name.empty()) return std::string("a label name is empty");
  if (has_control_or_quote(name)) {
    return "label name '" + name + "' holds a '\"' or a control character";
  }
  return std::nullopt;
}

std::optional<std::string> reward_model_problem(const std::string& name) {
  if (name.empty() || has_blank(name))
    return "context name '" + name + "' cannot name a reward model (it is empty or has blanks)";
  return std::nullopt;
}

bool all_zero(const model::Context& context) {
  const auto zero = [](ValueId id) { return id == RationalPool::kZero; };
  return std::all_of(context.rewards.state.begin(), context.rewards.state.end(), zero) &&
         std::all_of(context.rewards.choice.begin(), context.rewards.choice.end(), zero);
}

class DrnWriter {
 public:
  DrnWriter(const model::ExplicitModel& model, std::span<const std::size_t> contexts,
            AtomicFile& out)
      : model_(model),
        matrix_(*model.contexts.at(contexts.front()).transitions),
        order_(model, matrix_),
        out_(out),
        values_(model.values, ValueStyle::Decimal) {
    for (const std::size_t c : contexts)
      contexts_.push_back(&model.contexts.at(c));
    // A lone context "default" without rewards is what a file without reward models reads as.
    if (contexts_.size() == 1 && contexts_[0]->name == "default" && all_zero(*contexts_[0]))
      contexts_.clear();
  }

  [[nodiscard]] std::optional<std::string> problem() const {
    for (const std::string& name : model_.actions) {
      if (auto problem = action_problem(name)) return problem;
    }
    for (const std::string& name : model_.labels.names) {
      if (auto problem = label_problem(name)) return problem;
    }
    for (const model::Context* context : contexts_) {
      if (auto problem = reward_model_problem(context->name)) return problem;
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

  void write() {
    write_header();
    std::vector<ActionIndex> order;
    std::vector<bool> unlabelled;
    for (StateIndex s = 0; s < model_.num_states(); ++s) {
      write_state(s);
      order_(s, order, unlabelled);
      for (std::uint32_t j = 0; j < order.size(); ++j)
        write_choice(s, order[j], unlabelled[j]);
    }
  }

 private:
  void write_header() {
    out_.append("// Written by oasisc\n@type: ");
    out_.append(model_.type == model::ModelType::kDtmc ? "DTMC" : "MDP");
    out_.append("\n@value_type: rational\n@parameters\n\n@reward_models\n");
    for (std::size_t r = 0; r < contexts_.size(); ++r) {
      if (r > 0) out_.append(' ');
      out_.append(contexts_[r]->name);
    }
    out_.append("\n@nr_states\n");
    out_.append_number(model_.num_states());
    out_.append("\n@nr_choices\n");
    out_.append_number(matrix_.num_enabled_choices());
    out_.append("\n@model\n");
  }

  void write_state(StateIndex s) {
    out_.append("state ");
    out_.append_number(s);
    if (!contexts_.empty()) {
      write_rewards([&](const model::Context& context) { return context.rewards.state[s]; });
    }
    if (std::binary_search(initial_.begin(), initial_.end(), s)) out_.append(" init");
    for (const std::string* name : labels_of(s)) {
      out_.append(' ');
      if (has_blank(*name)) {
        out_.append('"');
        out_.append(*name);
        out_.append('"');
      } else {
        out_.append(*name);
      }
    }
    out_.append('\n');
  }

  // The labels of state `s` but "init" (written from the initial states), sorted by name.
  std::vector<const std::string*>& labels_of(StateIndex s) {
    held_.clear();
    for (const std::uint32_t label : model_.labels.of(s)) {
      if (model_.labels.names[label] != "init") held_.push_back(&model_.labels.names[label]);
    }
    std::sort(held_.begin(), held_.end(),
              [](const std::string* x, const std::string* y) { return *x < *y; });
    return held_;
  }

  template <typename Reward>
  void write_rewards(const Reward& reward) {
    out_.append(" [");
    for (std::size_t r = 0; r < contexts_.size(); ++r) {
      if (r > 0) out_.append(", ");
      out_.append(values_(reward(*contexts_[r])));
    }
    out_.append(']');
  }

  void write_choice(StateIndex s, ActionIndex a, bool unlabelled) {
    out_.append("\taction ");
    if (model_.type == model::ModelType::kDtmc) {
      out_.append('0');
    } else {
      out_.append(unlabelled ? kNoLabel : std::string_view(model_.actions[a]));
    }
    if (!contexts_.empty()) {
      const std::size_t c = matrix_.choice(s, a);
      write_rewards([&](const model::Context& context) {
        return context.rewards.choice.empty() ? RationalPool::kZero : context.rewards.choice[c];
      });
    }
    out_.append('\n');
    for (EdgeIndex e = matrix_.edges_begin(s, a); e < matrix_.edges_end(s, a); ++e) {
      out_.append("\t\t");
      out_.append_number(matrix_.edge_target[e]);
      out_.append(" : ");
      out_.append(values_(matrix_.edge_probability[e]));
      out_.append('\n');
    }
  }

  const model::ExplicitModel& model_;
  const model::TransitionMatrix& matrix_;
  ChoiceOrder order_;
  AtomicFile& out_;
  ValueText values_;
  std::vector<const model::Context*> contexts_;
  std::vector<StateIndex> initial_ = sorted_initial(model_);
  std::vector<const std::string*> held_;

  static std::vector<StateIndex> sorted_initial(const model::ExplicitModel& model) {
    std::vector<StateIndex> initial = model.states.initial;
    std::sort(initial.begin(), initial.end());
    return initial;
  }
};

}  // namespace

bool same_transitions(const model::ExplicitModel& model, std::size_t a, std::size_t b) {
  const model::TransitionMatrix& x = *model.contexts.at(a).transitions;
  const model::TransitionMatrix& y = *model.contexts.at(b).transitions;
  return &x == &y || (x.choice_begin == y.choice_begin && x.edge_target == y.edge_target &&
                      x.edge_probability == y.edge_probability);
}

bool write_drn(const model::ExplicitModel& model, std::span<const std::size_t> contexts,
               AtomicFile& out, std::string& error) {
  if (contexts.empty()) {
    error = "cannot write a DRN file: no context chosen";
    return false;
  }
  for (const std::size_t c : contexts) {
    if (!same_transitions(model, contexts.front(), c)) {
      error = "cannot write a DRN file: contexts '" + model.contexts.at(contexts.front()).name +
              "' and '" + model.contexts.at(c).name +
              "' have different transitions; choose one with --context";
      return false;
    }
  }
  DrnWriter writer(model, contexts, out);
  if (auto problem = writer.problem()) {
    error = "cannot write a DRN file: " + *problem;
    return false;
  }
  writer.write();
  if (!out.good()) {
    error = out.error();
    return false;
  }
  return true;
}

bool write_drn_file(const model::ExplicitModel& model, std::span<const std::size_t> contexts,
                    const std::string& path, std::string& error) {
  return write_atomically(path, error, [&](AtomicFile& out, std::string& why) {
    return write_drn(model, contexts, out, why);
  });
}

}  // namespace oasis::formats
