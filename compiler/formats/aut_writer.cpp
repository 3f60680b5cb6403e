#include "formats/aut_writer.hpp"

#include <unordered_map>

#include "formats/aut_label.hpp"
#include "formats/value_text.hpp"

namespace oasis::formats {
namespace {

using model::ActionIndex;
using model::EdgeIndex;
using model::StateIndex;

// Quoted labels per (action, state reward id, choice reward id): the label text depends only
// on these, and R(s, a) is a GMP sum we do not want to redo for each of 10^7 lines.
class LabelTable {
 public:
  LabelTable(const model::ExplicitModel& model, const model::RewardTable& rewards)
      : model_(model), rewards_(rewards) {}

  std::string_view operator()(StateIndex s, ActionIndex a) {
    const ValueId state_reward = rewards_.state.empty() ? RationalPool::kZero : rewards_.state[s];
    const ValueId choice_reward = rewards_.choice.empty()
                                      ? RationalPool::kZero
                                      : rewards_.choice[std::size_t{s} * model_.num_actions() + a];
    const Key key{a, state_reward, choice_reward};
    auto found = labels_.find(key);
    if (found == labels_.end()) {
      const Rational reward = model_.values[state_reward] + model_.values[choice_reward];
      found = labels_.emplace(key, '"' + format_aut_label(model_.actions[a], reward) + '"').first;
    }
    return found->second;
  }

 private:
  struct Key {
    ActionIndex action;
    ValueId state_reward;
    ValueId choice_reward;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& key) const {
      return (std::size_t{key.action} * 0x9e3779b97f4a7c15ULL) ^
             (std::size_t{key.state_reward} * 0xc2b2ae3d27d4eb4fULL) ^ key.choice_reward;
    }
  };

  const model::ExplicitModel& model_;
  const model::RewardTable& rewards_;
  std::unordered_map<Key, std::string, KeyHash> labels_;
};

void write_header(const model::ExplicitModel& model, std::size_t transitions, AtomicFile& out) {
  const std::vector<StateIndex>& initial = model.states.initial;
  out.append("des (");
  if (initial.size() <= 1) {
    out.append_number(initial.empty() ? 0U : initial.front());
  } else {
    // t0 p t1 p ... tk: each fraction is the probability of the state before it.
    const std::string share = "1/" + std::to_string(initial.size());
    for (std::size_t i = 0; i < initial.size(); ++i) {
      if (i > 0) {
        out.append(' ');
        out.append(share);
        out.append(' ');
      }
      out.append_number(initial[i]);
    }
  }
  out.append(',');
  out.append_number(transitions);
  out.append(',');
  out.append_number(model.num_states());
  out.append(")\n");
}

void write_distribution(const model::TransitionMatrix& matrix, EdgeIndex begin, EdgeIndex end,
                        ValueText& probability, AtomicFile& out) {
  out.append_number(matrix.edge_target[begin]);
  for (EdgeIndex e = begin + 1; e < end; ++e) {
    out.append(' ');
    out.append(probability(matrix.edge_probability[e - 1]));
    out.append(' ');
    out.append_number(matrix.edge_target[e]);
  }
}

}  // namespace

bool write_aut(const model::ExplicitModel& model, std::size_t context, AtomicFile& out,
               std::string& error) {
  for (const std::string& action : model.actions) {
    if (auto problem = aut_action_problem(action)) {
      error = "cannot write an .aut file: " + *problem;
      return false;
    }
  }
  const model::Context& selected = model.contexts.at(context);
  const model::TransitionMatrix& matrix = *selected.transitions;
  write_header(model, matrix.num_enabled_choices(), out);
  LabelTable label(model, selected.rewards);
  ValueText probability(model.values, ValueStyle::Fraction);
  for (StateIndex s = 0; s < matrix.num_states; ++s) {
    for (ActionIndex a = 0; a < matrix.num_actions; ++a) {
      const EdgeIndex begin = matrix.edges_begin(s, a);
      const EdgeIndex end = matrix.edges_end(s, a);
      if (begin == end) continue;
      out.append('(');
      out.append_number(s);
      out.append(',');
      out.append(label(s, a));
      out.append(',');
      write_distribution(matrix, begin, end, probability, out);
      out.append(")\n");
    }
  }
  if (!out.good()) {
    error = out.error();
    return false;
  }
  return true;
}

bool write_aut_file(const model::ExplicitModel& model, std::size_t context, const std::string& path,
                    std::string& error) {
  return write_atomically(path, error, [&](AtomicFile& out, std::string& why) {
    return write_aut(model, context, out, why);
  });
}

}  // namespace oasis::formats
