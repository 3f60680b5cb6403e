#include "formats/explicit_writer.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <vector>

#include "formats/choice_order.hpp"
#include "formats/explicit_reader.hpp"
#include "formats/value_text.hpp"
#include "support/atomic_file.hpp"
#include "support/atomic_file_set.hpp"
#include "support/text.hpp"

namespace oasis::formats {
namespace {

using model::ActionIndex;
using model::EdgeIndex;
using model::StateIndex;

constexpr std::uint32_t kNotWritten = std::numeric_limits<std::uint32_t>::max();

std::optional<std::string> action_problem(const std::string& name) {
  if (name.empty()) return std::string("an action name is empty");
  if (name.find_first_of(" \t\r\n") != std::string::npos || name.front() == '#') {
    return "action name '" + name + "' has blanks or starts with '#'";
  }
  return std::nullopt;
}

// What read_prism's .lab reader refuses (formats/explicit_labels.cpp), or what would end the
// name early: a label is written as N="name" on the first line.
std::optional<std::string> label_problem(const std::string& name) {
  if (name.empty()) return std::string("a label name is empty");
  const bool unwritable = std::any_of(name.begin(), name.end(), [](char c) {
    const auto byte = static_cast<unsigned char>(c);
    return byte < 0x20 || byte == 0x7f || c == '"';
  });
  if (unwritable) return "label name " + quoted(name) + " holds a '\"' or a control character";
  return std::nullopt;
}

class PrismWriter {
 public:
  PrismWriter(const model::ExplicitModel& model, std::size_t context, std::string base)
      : model_(model),
        context_(model.contexts.at(context)),
        matrix_(*context_.transitions),
        order_(model, matrix_),
        base_(std::move(base)),
        values_(model.values, ValueStyle::Decimal) {}

  bool write(std::string& error) {
    for (const std::string& name : model_.actions) {
      if (auto problem = action_problem(name)) {
        error = "cannot write PRISM files: " + *problem;
        return false;
      }
    }
    for (const std::string& name : model_.labels.names) {
      if (auto problem = label_problem(name)) {
        error = "cannot write PRISM files: " + *problem;
        return false;
      }
    }
    const bool with_states = !model_.states.variables.empty();
    const bool with_choice_rewards = has_choice_rewards();
    AtomicFileSet set;
    std::vector<AtomicFile*> files;
    const auto add = [&](const char* extension) {
      files.push_back(set.add(base_ + extension, error));
      return files.back() != nullptr;
    };
    if (!add(".tra") || !add(".lab") || !add(".srew") || (with_states && !add(".sta")) ||
        (with_choice_rewards && !add(".trew"))) {
      return false;
    }
    write_transitions(*files[0]);
    write_labels(*files[1]);
    write_state_rewards(*files[2]);
    if (with_states) write_states(*files[3]);
    if (with_choice_rewards) write_choice_rewards(*files.back());
    // A stale sibling would be read back as part of this model.
    if (!with_states) set.remove_at_commit(base_ + ".sta");
    if (!with_choice_rewards) set.remove_at_commit(base_ + ".trew");
    return set.commit(error);
  }

 private:
  [[nodiscard]] bool has_choice_rewards() const {
    if (context_.rewards.choice.empty()) return false;
    for (std::size_t c = 0; c < context_.rewards.choice.size(); ++c) {
      const auto s = static_cast<StateIndex>(c / model_.num_actions());
      const auto a = static_cast<ActionIndex>(c % model_.num_actions());
      if (context_.rewards.choice[c] != RationalPool::kZero && matrix_.enabled(s, a)) return true;
    }
    return false;
  }

  void write_transitions(AtomicFile& out) {
    out.append_number(model_.num_states());
    out.append(' ');
    out.append_number(matrix_.num_enabled_choices());
    out.append(' ');
    out.append_number(matrix_.num_edges());
    out.append('\n');
    for (StateIndex s = 0; s < model_.num_states(); ++s) {
      order_(s, order_buffer_, unlabelled_);
      for (std::uint32_t j = 0; j < order_buffer_.size(); ++j) {
        const ActionIndex a = order_buffer_[j];
        for (EdgeIndex e = matrix_.edges_begin(s, a); e < matrix_.edges_end(s, a); ++e) {
          write_row_start(out, s, j, matrix_.edge_target[e]);
          out.append(values_(matrix_.edge_probability[e]));
          if (!unlabelled_[j]) {
            out.append(' ');
            out.append(model_.actions[a]);
          }
          out.append('\n');
        }
      }
    }
  }

  static void write_row_start(AtomicFile& out, StateIndex s, std::uint32_t j, StateIndex target) {
    out.append_number(s);
    out.append(' ');
    out.append_number(j);
    out.append(' ');
    out.append_number(target);
    out.append(' ');
  }

  // Where "deadlock" holds: the model's own label when it has one (a PRISM program's deadlocked
  // states have a self-loop, so they are not deadlocked in the matrix), else PRISM's meaning,
  // the states without an enabled choice.
  [[nodiscard]] std::vector<bool> deadlocked() const {
    std::vector<bool> result(model_.num_states(), false);
    if (const auto label = model_.labels.find("deadlock")) {
      for (StateIndex s = 0; s < model_.num_states(); ++s) {
        const auto held = model_.labels.of(s);
        result[s] = std::find(held.begin(), held.end(), *label) != held.end();
      }
      return result;
    }
    for (StateIndex s = 0; s < model_.num_states(); ++s) {
      bool none = true;
      for (ActionIndex a = 0; a < model_.num_actions() && none; ++a)
        none = !matrix_.enabled(s, a);
      result[s] = none;
    }
    return result;
  }

  // "init" and "deadlock", as PRISM writes them and the reader expects them, then the model's
  // own labels (its atomic propositions, model/state_labels.hpp), so that the model read back
  // has the labels this one has.
  void write_labels(AtomicFile& out) {
    std::vector<std::uint32_t> written_as(model_.labels.names.size(), kNotWritten);
    std::uint32_t next = 2;
    out.append("0=\"init\" 1=\"deadlock\"");
    for (std::uint32_t k = 0; k < model_.labels.names.size(); ++k) {
      const std::string& name = model_.labels.names[k];
      if (name == "init" || name == "deadlock") continue;  // written from the model itself
      written_as[k] = next;
      out.append(' ');
      out.append_number(next++);
      out.append("=\"" + name + "\"");
    }
    out.append('\n');
    std::vector<bool> initial(model_.num_states(), false);
    for (StateIndex s : model_.states.initial)
      initial[s] = true;
    const std::vector<bool> deadlocks = deadlocked();
    std::vector<std::uint32_t> held;
    for (StateIndex s = 0; s < model_.num_states(); ++s) {
      const bool deadlock = deadlocks[s];
      held.clear();
      for (std::uint32_t label : model_.labels.of(s))
        if (written_as[label] != kNotWritten) held.push_back(written_as[label]);
      if (!initial[s] && !deadlock && held.empty()) continue;
      out.append_number(s);
      out.append(':');
      if (initial[s]) out.append(" 0");
      if (deadlock) out.append(" 1");
      std::sort(held.begin(), held.end());
      for (std::uint32_t label : held) {
        out.append(' ');
        out.append_number(label);
      }
      out.append('\n');
    }
  }

  void write_state_rewards(AtomicFile& out) {
    const std::vector<ValueId>& rewards = context_.rewards.state;
    std::size_t nonzero = 0;
    for (ValueId id : rewards)
      nonzero += id != RationalPool::kZero ? 1 : 0;
    out.append_number(model_.num_states());
    out.append(' ');
    out.append_number(nonzero);
    out.append('\n');
    for (StateIndex s = 0; s < rewards.size(); ++s) {
      if (rewards[s] == RationalPool::kZero) continue;
      out.append_number(s);
      out.append(' ');
      out.append(values_(rewards[s]));
      out.append('\n');
    }
  }

  // One row per target of each choice with a non-zero reward, as PRISM writes MDP rewards.
  void write_choice_rewards(AtomicFile& out) {
    const std::vector<ValueId>& rewards = context_.rewards.choice;
    std::size_t rows = 0;
    for (StateIndex s = 0; s < model_.num_states(); ++s) {
      for (ActionIndex a = 0; a < model_.num_actions(); ++a) {
        if (rewards[std::size_t{s} * model_.num_actions() + a] == RationalPool::kZero) continue;
        rows += matrix_.edges_end(s, a) - matrix_.edges_begin(s, a);
      }
    }
    out.append_number(model_.num_states());
    out.append(' ');
    out.append_number(matrix_.num_enabled_choices());
    out.append(' ');
    out.append_number(rows);
    out.append('\n');
    for (StateIndex s = 0; s < model_.num_states(); ++s) {
      order_(s, order_buffer_, unlabelled_);
      for (std::uint32_t j = 0; j < order_buffer_.size(); ++j) {
        const ActionIndex a = order_buffer_[j];
        const ValueId reward = rewards[std::size_t{s} * model_.num_actions() + a];
        if (reward == RationalPool::kZero) continue;
        for (EdgeIndex e = matrix_.edges_begin(s, a); e < matrix_.edges_end(s, a); ++e) {
          write_row_start(out, s, j, matrix_.edge_target[e]);
          out.append(values_(reward));
          out.append('\n');
        }
      }
    }
  }

  void write_states(AtomicFile& out) {
    const std::vector<std::string>& variables = model_.states.variables;
    out.append('(');
    for (std::size_t v = 0; v < variables.size(); ++v) {
      if (v > 0) out.append(',');
      out.append(variables[v]);
    }
    out.append(")\n");
    for (StateIndex s = 0; s < model_.num_states(); ++s) {
      out.append_number(s);
      out.append(":(");
      for (std::size_t v = 0; v < variables.size(); ++v) {
        if (v > 0) out.append(',');
        out.append_number(model_.states.valuations[s * variables.size() + v]);
      }
      out.append(")\n");
    }
  }

  const model::ExplicitModel& model_;
  const model::Context& context_;
  const model::TransitionMatrix& matrix_;
  ChoiceOrder order_;
  std::string base_;
  ValueText values_;
  std::vector<ActionIndex> order_buffer_;
  std::vector<bool> unlabelled_;
};

}  // namespace

bool write_prism(const model::ExplicitModel& model, std::size_t context, const std::string& base,
                 std::string& error) {
  const bool has_extension = base.size() > 4 && base.ends_with(".tra");  // not a bare ".tra"
  return PrismWriter(model, context, has_extension ? base.substr(0, base.size() - 4) : base)
      .write(error);
}

}  // namespace oasis::formats
