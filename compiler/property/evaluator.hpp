#pragma once
// Answers properties on an explicit model: every state formula becomes a set of states (labels
// from the model, variables from its valuations, constants and formulas from the program), every
// P and R operator a call of the numeric engine (modelcheck/engine.hpp), and the property's
// value is read in the initial states, as PRISM's default filter(first, ..., "init") reads it.
//
// Checks as PRISM does, each error located in the property: an unknown label, variable or
// reward structure; Pmin/Pmax/Rmin/Rmax on a Markov chain; P=? or R=? without min or max on an
// MDP; a probability bound outside [0, 1]; a negative step bound; a value (P=?) where a state
// formula is needed.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "model/explicit_model.hpp"
#include "model/expression.hpp"
#include "modelcheck/engine.hpp"
#include "property/engine_call.hpp"
#include "property/property.hpp"

namespace oasis::property {

// The names a property may use besides labels: a PRISM program's constants, formulas and
// variables (prism::Program::names); empty for imported models.
using Names = std::vector<std::pair<std::string, model::Expression>>;

// The answer to one property.
struct Answer {
  enum class Kind { kNumber, kTruth };
  Kind kind = Kind::kNumber;
  // kNumber: the value the filter reads (the first initial state's by default).
  modelcheck::Value value;
  // kTruth: the verdict; in how many of the states the filter reads it holds, and of how many.
  bool verdict = false;
  std::uint32_t holding = 0;
  std::uint32_t considered = 0;
  std::optional<model::StateIndex> first_failing;
  // Per state, the value of the outermost P or R operator (for --all-states), and its
  // scheduler when one was asked for.
  std::vector<modelcheck::Value> state_values;
  std::optional<modelcheck::Scheduler> scheduler;
  std::string method;                                // the engine's, or "exact: a state formula"
  modelcheck::Mode mode = modelcheck::Mode::kExact;  // what the answer is: rationals or intervals
};

class Evaluator {
 public:
  Evaluator(const model::ExplicitModel& model, const Names& names, const PropertiesFile& file,
            DiagnosticEngine& diagnostics, const modelcheck::Options& options);

  // nullopt after reporting an error located in the property.
  std::optional<Answer> answer(const Property& property);
  // In exact mode, a property whose exact solve is refused (modelcheck::ExactLimitExceeded) is
  // answered soundly instead, with a note, rather than reported as an error.
  void allow_sound_fallback(bool allow) { sound_fallback_ = allow; }
  // Every engine call is solved on the coarsest bisimulation quotient that respects its state
  // sets and rewards, and lifted back (quotient_solve.hpp).
  void use_bisimulation(bool use) { bisimulation_ = use; }

 private:
  struct Failed {};  // raised after an error was reported

  Answer answer_expression(const prism::ast::Expr& expr);
  Answer answer_filter(const Filter& filter);
  modelcheck::Result quantify(const Quantifier& q, bool want_scheduler);
  modelcheck::Result probability(const Quantifier& q, modelcheck::Optimum optimum);
  modelcheck::Result reward(const Quantifier& q, modelcheck::Optimum optimum);
  modelcheck::Result solve(const EngineCall& call);
  modelcheck::Optimum optimum_of(const Quantifier& q);
  modelcheck::StateSet states_of(const prism::ast::Expr& expr);
  modelcheck::StateSet holds(const Quantifier& q);
  std::uint32_t steps_of(const prism::ast::Expr& expr, bool strict);
  Rational constant_number(const prism::ast::Expr& expr, const std::string& what);
  const model::RewardTable& reward_table(const Quantifier& q);
  std::optional<model::Expression> resolve(const prism::ast::Expr& name);
  std::optional<model::Expression> spec_variable(const prism::ast::Expr& name) const;
  std::uint32_t label_slot(const LabelReference& label);
  std::optional<model::Expression> constant_definition(const Definition& constant);
  std::uint32_t quantifier_slot(const Quantifier& q);
  [[noreturn]] void fail(SourceRange where, const std::string& message);

  const model::ExplicitModel& model_;
  const Names& names_;
  const PropertiesFile& file_;
  DiagnosticEngine& diagnostics_;
  modelcheck::Options options_;
  // Extra valuation columns, one per label or bounded operator a state formula reads: a state
  // formula is lowered to a model expression over the valuation and these columns.
  std::uint32_t width_ = 0;  // the model's own variables
  std::vector<std::vector<std::int64_t>> columns_;
  std::map<std::string, std::uint32_t, std::less<>> label_slots_;  // label name -> its column
  std::string method_;  // the last engine call's, for a state formula's answer
  bool sound_fallback_ = false;
  bool bisimulation_ = false;
  int defining_ = 0;  // definitions being expanded, one inside another (a cycle passes the count)
};

}  // namespace oasis::property
