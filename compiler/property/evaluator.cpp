#include "property/evaluator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "prism/expression_lowering.hpp"
#include "property/quotient_solve.hpp"
#include "property/value_reduction.hpp"
#include "support/text.hpp"

namespace oasis::property {
namespace {

namespace ast = prism::ast;
using modelcheck::Optimum;
using modelcheck::StateSet;
using modelcheck::Value;

// How many times a bounded operator's precision is tightened (1000-fold each) before a value
// too close to its bound to decide in sound mode is reported.
constexpr int kRefinements = 3;

// The column `slot` read as a boolean: `slot = 1`.
model::Expression column_holds(std::uint32_t slot, SourceRange range) {
  model::Expression var;
  var.op = model::Op::Variable;
  var.type = model::Type::Int;
  var.slot = slot;
  var.range = range;
  model::Expression test;
  test.op = model::Op::Equal;
  test.type = model::Type::Bool;
  test.range = range;
  test.operands = {std::move(var), model::Expression::make_constant(1, model::Type::Int, range)};
  return test;
}

// Sets one engine option for as long as it lives. The old value comes back however the scope
// ends: an error in a property leaves through it (Failed), and the next property must find the
// options as the command set them.
template <typename T>
class OptionOverride {
 public:
  OptionOverride(T& slot, T value) : slot_(slot), saved_(slot) { slot_ = value; }
  ~OptionOverride() { slot_ = saved_; }
  OptionOverride(const OptionOverride&) = delete;
  OptionOverride& operator=(const OptionOverride&) = delete;

 private:
  T& slot_;
  T saved_;
};

Optimum opposite(Optimum optimum) {
  if (optimum == Optimum::kMin) return Optimum::kMax;
  if (optimum == Optimum::kMax) return Optimum::kMin;
  return Optimum::kNone;
}

StateSet complement(StateSet set) {
  set.flip();
  return set;
}

// 1 - v in every state, the interval turned around and rounded outward.
void one_minus(std::vector<Value>& values) {
  for (Value& v : values) {
    v.exact = 1 - v.exact;
    const double lower = std::nextafter(1.0 - v.upper, -1.0);
    const double upper = std::nextafter(1.0 - v.lower, 2.0);
    v.lower = std::clamp(lower, 0.0, 1.0);
    v.upper = std::clamp(upper, 0.0, 1.0);
  }
}

const char* optimum_word(Optimum optimum) {
  return optimum == Optimum::kMin ? "min" : optimum == Optimum::kMax ? "max" : "";
}

}  // namespace

Evaluator::Evaluator(const model::ExplicitModel& model, const Names& names,
                     const PropertiesFile& file, DiagnosticEngine& diagnostics,
                     const modelcheck::Options& options)
    : model_(model),
      names_(names),
      file_(file),
      diagnostics_(diagnostics),
      options_(options),
      width_(static_cast<std::uint32_t>(model.states.variables.size())) {}

std::optional<Answer> Evaluator::answer(const Property& property) {
  method_.clear();
  defining_ = 0;
  try {
    Answer result = answer_expression(property.expression);
    result.mode = options_.mode;
    return result;
  } catch (const Failed&) {
    return std::nullopt;
  } catch (const modelcheck::ExactLimitExceeded& e) {
    if (!sound_fallback_ || options_.mode != modelcheck::Mode::kExact) {
      diagnostics_.error(property.range, e.what());
      return std::nullopt;
    }
    diagnostics_.note(property.range, std::string(e.what()) + "; answering in sound mode");
    const OptionOverride<modelcheck::Mode> sound(options_.mode, modelcheck::Mode::kSound);
    return answer(property);
  }
}

void Evaluator::fail(SourceRange where, const std::string& message) {
  diagnostics_.error(where, message);
  throw Failed{};
}

Answer Evaluator::answer_expression(const ast::Expr& expr) {
  if (expr.kind == ast::Expr::Kind::Extension) {
    const Extension& node = file_.extensions.at(std::stoul(expr.text));
    if (const auto* filter = std::get_if<Filter>(&node)) return answer_filter(*filter);
    const auto* q = std::get_if<Quantifier>(&node);
    if (q != nullptr && q->comparison == Quantifier::Comparison::kQuery) {
      Filter first;
      first.initial_states = true;
      first.property = expr;
      first.range = expr.range;
      return answer_filter(first);
    }
  }
  Filter forall;
  forall.initial_states = true;
  forall.op = Filter::Op::kForall;
  forall.property = expr;
  forall.range = expr.range;
  return answer_filter(forall);
}

Answer Evaluator::answer_filter(const Filter& filter) {
  StateSet states(model_.num_states(), !filter.initial_states);
  if (filter.states) {
    states = states_of(*filter.states);
  } else if (filter.initial_states) {
    for (const model::StateIndex s : model_.states.initial)
      states[s] = true;
  }
  if (std::find(states.begin(), states.end(), true) == states.end())
    fail(filter.range, "the filter reads no state (its state formula holds nowhere)");
  const ast::Expr& inner = filter.property;
  const Quantifier* query = nullptr;
  if (inner.kind == ast::Expr::Kind::Extension) {
    const Extension& node = file_.extensions.at(std::stoul(inner.text));
    if (std::holds_alternative<Filter>(node))
      fail(inner.range, "a filter cannot stand inside another filter");
    query = std::get_if<Quantifier>(&node);
    if (query != nullptr && query->comparison != Quantifier::Comparison::kQuery) query = nullptr;
  }
  Answer answer;
  if (query != nullptr) {
    modelcheck::Result result = quantify(*query, options_.want_scheduler);
    answer.kind = Answer::Kind::kNumber;
    if (!reduce_values(filter.op, result.values, states, options_.mode, answer.value)) {
      fail(filter.range, "the filter '" + filter_name(filter.op) +
                             "' reads a truth value; the property here is a number");
    }
    answer.state_values = std::move(result.values);
    answer.scheduler = std::move(result.scheduler);
    answer.method = std::move(result.method);
    return answer;
  }
  const StateSet truth = states_of(inner);
  answer.kind = Answer::Kind::kTruth;
  for (model::StateIndex s = 0; s < model_.num_states(); ++s) {
    if (!states[s]) continue;
    ++answer.considered;
    if (truth[s]) {
      ++answer.holding;
    } else if (!answer.first_failing) {
      answer.first_failing = s;
    }
  }
  switch (filter.op) {
    case Filter::Op::kForall:
      answer.verdict = answer.holding == answer.considered;
      break;
    case Filter::Op::kExists:
      answer.verdict = answer.holding > 0;
      break;
    case Filter::Op::kFirst: {
      const auto first = std::find(states.begin(), states.end(), true) - states.begin();
      answer.verdict = truth[static_cast<std::size_t>(first)];
      break;
    }
    case Filter::Op::kCount:
      answer.kind = Answer::Kind::kNumber;
      answer.value.exact = answer.holding;
      answer.value.lower = answer.value.upper = answer.holding;
      break;
    default:
      fail(filter.range, "the filter '" + filter_name(filter.op) +
                             "' reads numbers; the property here is a state formula");
  }
  answer.method = method_.empty() ? "exact: a state formula" : method_;
  return answer;
}

modelcheck::Result Evaluator::quantify(const Quantifier& q, bool want_scheduler) {
  const Optimum optimum = optimum_of(q);
  const OptionOverride<bool> scheduler(options_.want_scheduler,
                                       want_scheduler && optimum != Optimum::kNone);
  modelcheck::Result result = q.reward ? reward(q, optimum) : probability(q, optimum);
  method_ = result.method;
  return result;
}

Optimum Evaluator::optimum_of(const Quantifier& q) {
  const char* letter = q.reward ? "R" : "P";
  if (model_.type == model::ModelType::kDtmc) {
    if (q.optimum != Quantifier::Optimum::kNone) {
      fail(q.head_range, std::string(letter) +
                             (q.optimum == Quantifier::Optimum::kMin ? "min" : "max") +
                             " asks for an optimum over choices, and a Markov chain has none: "
                             "write " +
                             letter + (q.bound ? "" : "=?") + " instead, as PRISM requires");
    }
    return Optimum::kNone;
  }
  if (q.optimum == Quantifier::Optimum::kMin) return Optimum::kMin;
  if (q.optimum == Quantifier::Optimum::kMax) return Optimum::kMax;
  switch (q.comparison) {
    case Quantifier::Comparison::kQuery:
      fail(q.head_range, std::string("in an MDP the value depends on the scheduler: write ") +
                             letter + "min=? or " + letter + "max=?");
    case Quantifier::Comparison::kGreater:
    case Quantifier::Comparison::kGreaterEqual:
      return Optimum::kMin;  // the bound must hold under every scheduler
    case Quantifier::Comparison::kLess:
    case Quantifier::Comparison::kLessEqual:
      return Optimum::kMax;
  }
  return Optimum::kNone;
}

modelcheck::Result Evaluator::probability(const Quantifier& q, Optimum optimum) {
  const PathFormula& path = q.path;
  EngineCall call;
  call.optimum = optimum;
  const std::optional<std::uint32_t> steps =
      path.steps ? std::optional(steps_of(*path.steps, path.strict_bound)) : std::nullopt;
  call.steps = steps.value_or(0);
  switch (path.kind) {
    case PathFormula::Kind::kNext:
      call.op = EngineCall::Op::kNext;
      call.psi = states_of(path.right);
      return solve(call);
    case PathFormula::Kind::kEventually:
    case PathFormula::Kind::kUntil:
      call.op = steps ? EngineCall::Op::kBoundedUntil : EngineCall::Op::kUntil;
      call.phi = path.left ? states_of(*path.left) : StateSet(model_.num_states(), true);
      call.psi = states_of(path.right);
      return solve(call);
    case PathFormula::Kind::kGlobally: {
      // G phi is the complement of F !phi, under the opposite optimum.
      call.op = steps ? EngineCall::Op::kBoundedUntil : EngineCall::Op::kUntil;
      call.optimum = opposite(optimum);
      call.phi = StateSet(model_.num_states(), true);
      call.psi = complement(states_of(path.right));
      modelcheck::Result result = solve(call);
      one_minus(result.values);
      result.method += ", as 1 - P" + std::string(optimum_word(call.optimum)) + "(F !phi)";
      return result;
    }
  }
  return {};
}

modelcheck::Result Evaluator::reward(const Quantifier& q, Optimum optimum) {
  EngineCall call;
  call.optimum = optimum;
  call.rewards = &reward_table(q);
  const RewardFormula& formula = q.reward_formula;
  switch (formula.kind) {
    case RewardFormula::Kind::kReachability:
      call.op = EngineCall::Op::kReachabilityReward;
      call.psi = states_of(*formula.target);
      break;
    case RewardFormula::Kind::kCumulative:
      call.op = EngineCall::Op::kCumulative;
      call.steps = steps_of(*formula.steps, false);
      break;
    case RewardFormula::Kind::kInstantaneous:
      call.op = EngineCall::Op::kInstantaneous;
      call.steps = steps_of(*formula.steps, false);
      break;
  }
  return solve(call);
}

modelcheck::Result Evaluator::solve(const EngineCall& call) {
  modelcheck::Result result;
  if (bisimulation_) {
    QuotientSize size;
    result = solve_on_quotient(model_, call, options_, size);
  } else {
    result = run(call, *model_.contexts.front().transitions, model_.values, call.rewards, options_);
  }
  if (result.scheduler && !result.scheduler->action.empty()) {
    // The scheduler is checked on the model itself, whether it was computed there or lifted.
    if (!scheduler_reproduces(model_, call, result, options_))
      throw std::logic_error("the optimal scheduler does not reproduce its values on the model");
    result.method += "; its scheduler re-checked on the model";
  }
  return result;
}

const model::RewardTable& Evaluator::reward_table(const Quantifier& q) {
  if (!q.reward_name) {
    if (model_.contexts.empty()) fail(q.head_range, "the model has no reward structure");
    return model_.contexts.front().rewards;
  }
  for (const model::Context& context : model_.contexts)
    if (context.name == *q.reward_name) return context.rewards;
  std::string known;
  for (const model::Context& context : model_.contexts)
    known += (known.empty() ? "" : ", ") + quoted(context.name);
  fail(q.reward_name_range,
       "the model has no reward structure " + quoted(*q.reward_name) + " (it has " + known + ")");
}

StateSet Evaluator::states_of(const ast::Expr& expr) {
  prism::ExpressionLowering lowering(diagnostics_, options_.max_number_bits,
                                     [this](const ast::Expr& name) { return resolve(name); });
  const std::optional<model::Expression> lowered =
      lowering.lower_as(expr, model::Type::Bool, "a state formula");
  if (!lowered) throw Failed{};
  const std::uint32_t n = model_.num_states();
  StateSet set(n, false);
  std::vector<std::int64_t> valuation(width_ + columns_.size());
  try {
    for (model::StateIndex s = 0; s < n; ++s) {
      if (width_ > 0) {
        const auto* row = model_.states.valuations.data() + std::size_t{s} * width_;
        std::copy(row, row + width_, valuation.begin());
      }
      for (std::size_t c = 0; c < columns_.size(); ++c)
        valuation[width_ + c] = columns_[c][s];
      set[s] = model::evaluate_bool(*lowered, valuation);
    }
  } catch (const model::EvaluationError& e) {
    fail(e.where, e.what());
  }
  return set;
}

// A factored spec's variable (a PRISM program's come with its names): its valuation column.
std::optional<model::Expression> Evaluator::spec_variable(const ast::Expr& name) const {
  const auto& variables = model_.states.variables;
  const auto found = std::find(variables.begin(), variables.end(), name.text);
  if (found == variables.end()) return std::nullopt;
  model::Expression variable;
  variable.op = model::Op::Variable;
  variable.type = model::Type::Int;
  variable.slot = static_cast<std::uint32_t>(found - variables.begin());
  variable.range = name.range;
  return variable;
}

std::optional<model::Expression> Evaluator::resolve(const ast::Expr& name) {
  if (name.kind == ast::Expr::Kind::Name) {
    for (const Definition& constant : file_.constants) {
      if (constant.name == name.text) return constant_definition(constant);
    }
    const auto it = std::lower_bound(
        names_.begin(), names_.end(), name.text,
        [](const auto& entry, const std::string& key) { return entry.first < key; });
    if (it != names_.end() && it->first == name.text) return it->second;
    if (auto variable = spec_variable(name)) return variable;
    diagnostics_.error(name.range, "unknown name " + quoted(name.text) +
                                       (names_.empty() && model_.states.variables.empty()
                                            ? " (this model's states are read through "
                                              "its labels, written in quotes: \"goal\")"
                                            : ""));
    return std::nullopt;
  }
  const Extension& node = file_.extensions.at(std::stoul(name.text));
  if (const auto* label = std::get_if<LabelReference>(&node))
    return column_holds(label_slot(*label), name.range);
  if (const auto* q = std::get_if<Quantifier>(&node)) {
    if (q->comparison == Quantifier::Comparison::kQuery) {
      diagnostics_.error(q->head_range,
                         "a query (=?) gives a number, not a state formula: compare it with a "
                         "bound instead, as in P>=0.5 [ ... ]");
      return std::nullopt;
    }
    return column_holds(quantifier_slot(*q), name.range);
  }
  diagnostics_.error(name.range, "a filter can only be the whole property");
  return std::nullopt;
}

std::optional<model::Expression> Evaluator::constant_definition(const Definition& constant) {
  if (++defining_ > static_cast<int>(file_.labels.size() + file_.constants.size())) {
    --defining_;
    diagnostics_.error(constant.range, "constant " + quoted(constant.name) + " uses itself");
    return std::nullopt;
  }
  prism::ExpressionLowering lowering(diagnostics_, options_.max_number_bits,
                                     [this](const ast::Expr& name) { return resolve(name); });
  std::optional<model::Expression> value = lowering.lower(constant.value);
  --defining_;
  if (value && value->depends_on_state()) {
    diagnostics_.error(constant.range,
                       "constant " + quoted(constant.name) + " depends on the state");
    return std::nullopt;
  }
  return value;
}

std::uint32_t Evaluator::label_slot(const LabelReference& label) {
  // A label's states never change: its column is made once, however often properties read it.
  if (const auto known = label_slots_.find(label.name); known != label_slots_.end())
    return known->second;
  const std::uint32_t n = model_.num_states();
  std::vector<std::int64_t> column(n, 0);
  const auto defined = std::find_if(file_.labels.begin(), file_.labels.end(),
                                    [&](const Definition& d) { return d.name == label.name; });
  if (defined != file_.labels.end()) {
    if (++defining_ > static_cast<int>(file_.labels.size() + file_.constants.size()))
      fail(defined->range, "label \"" + label.name + "\" uses itself");
    const StateSet set = states_of(defined->value);
    --defining_;
    for (model::StateIndex s = 0; s < n; ++s)
      column[s] = set[s] ? 1 : 0;
  } else if (const auto index = model_.labels.find(label.name)) {
    for (model::StateIndex s = 0; s < n; ++s) {
      const auto held = model_.labels.of(s);
      column[s] = std::find(held.begin(), held.end(), *index) != held.end() ? 1 : 0;
    }
  } else if (label.name == "init") {
    for (const model::StateIndex s : model_.states.initial)
      column[s] = 1;
  } else if (const auto state =
                 std::find(model_.states.names.begin(), model_.states.names.end(), label.name);
             state != model_.states.names.end()) {
    // A spec's named state is a label that holds in it alone (docs/properties.md).
    column[static_cast<std::size_t>(state - model_.states.names.begin())] = 1;
  } else {
    std::string known;
    for (const std::string& name : model_.labels.names)
      known += (known.empty() ? "" : ", ") + ("\"" + name + "\"");
    for (const std::string& name : model_.states.names)
      known += (known.empty() ? "" : ", ") + ("\"" + name + "\"");
    fail(label.range,
         "unknown label \"" + label.name + "\"" +
             (!known.empty() ? " (known: " + known + ")"
              : model_.states.variables.empty()
                  ? " (the model has no labels)"
                  : " (the model has no labels; its variables say which states, as in " +
                        model_.states.variables.front() + "=0)"));
  }
  columns_.push_back(std::move(column));
  const std::uint32_t slot = width_ + static_cast<std::uint32_t>(columns_.size() - 1);
  label_slots_.emplace(label.name, slot);
  return slot;
}

std::uint32_t Evaluator::quantifier_slot(const Quantifier& q) {
  const StateSet set = holds(q);
  std::vector<std::int64_t> column(set.size());
  for (std::size_t s = 0; s < set.size(); ++s)
    column[s] = set[s] ? 1 : 0;
  columns_.push_back(std::move(column));
  return width_ + static_cast<std::uint32_t>(columns_.size() - 1);
}

StateSet Evaluator::holds(const Quantifier& q) {
  const Rational bound = constant_number(*q.bound, "the bound");
  if (!q.reward && (bound < 0 || bound > 1)) {
    fail(q.bound->range, "a probability bound must lie in [0, 1], not " + describe(bound));
  }
  const double saved_precision = options_.precision;
  const OptionOverride<double> precision(options_.precision, saved_precision);
  for (int round = 0; round <= kRefinements; ++round) {
    const modelcheck::Result result = quantify(q, false);
    StateSet set(result.values.size(), false);
    if (compare_with_bound(result.values, q.comparison, bound, options_.mode, set)) return set;
    options_.precision /= 1000;
  }
  fail(q.range,
       "cannot decide the bound in sound mode: in some state the value is still on "
       "both sides of it at precision " +
           scientific(Rational(saved_precision / 1e9)) + "; use --mode exact");
}

std::uint32_t Evaluator::steps_of(const ast::Expr& expr, bool strict) {
  const Rational value = constant_number(expr, "a step bound");
  if (value.get_den() != 1 || value < 0)
    fail(expr.range, "a step bound must be a non-negative integer, not " + describe(value));
  if (strict && value == 0) fail(expr.range, "'<0' steps leaves no path: write '<=0' or more");
  const Rational steps = strict ? value - 1 : value;
  if (steps > std::numeric_limits<std::uint32_t>::max() / 2)
    fail(expr.range, "a step bound must be below 2^31, not " + describe(value));
  return static_cast<std::uint32_t>(steps.get_num().get_ui());
}

Rational Evaluator::constant_number(const ast::Expr& expr, const std::string& what) {
  prism::ExpressionLowering lowering(diagnostics_, options_.max_number_bits,
                                     [this](const ast::Expr& name) { return resolve(name); });
  const std::optional<model::Expression> lowered = lowering.lower_as(expr, model::Type::Real, what);
  if (!lowered) throw Failed{};
  if (lowered->depends_on_state() || !lowered->is_constant())
    fail(expr.range, what + " must be a constant, not depend on the state");
  return lowered->constant;
}

}  // namespace oasis::property
