#include "prism/checker.hpp"

#include <algorithm>
#include <map>
#include <string>
#include <unordered_map>
#include <utility>

#include "prism/constant_overrides.hpp"
#include "prism/expression_lowering.hpp"
#include "prism/module_renaming.hpp"
#include "support/text.hpp"

namespace oasis::prism {
namespace {

using model::Expression;
using model::Type;

struct Symbol {
  enum class Kind { Constant, Formula, Variable } kind;
  std::size_t index;
  SourceRange range;
};

// Which names an expression may use: constants (and formulas over them) only, or also the
// variables, which make it depend on the state.
enum class Scope { Constants, State };

constexpr std::int64_t kGlobal = -1;

// How deeply formulas may use one another: a lowered expression is at most this many times
// as deep as the parser lets one expression be (limits::kMaxNesting).
constexpr int kMaxFormulaNesting = 24;

// Exploration recurses once per module taking part in a synchronised choice.
constexpr std::size_t kMaxModules = 1024;

class Checker {
 public:
  Checker(const ast::Program& tree, std::string name, DiagnosticEngine& diagnostics,
          const CheckOptions& options)
      : tree_(tree), diagnostics_(diagnostics), options_(options) {
    program_.name = std::move(name);
  }

  std::optional<Program> run() {
    const std::size_t errors_before = diagnostics_.error_count();
    const bool has_modules = check_has_modules();
    check_model_type();
    expand_modules();
    if (modules_.size() > kMaxModules) {
      diagnostics_.error(modules_[kMaxModules].range,
                         "more than " + std::to_string(kMaxModules) + " modules");
      return std::nullopt;
    }
    declare_constants_and_formulas();
    overrides_ = read_constant_overrides(options_.constants, diagnostics_);
    for (const ConstantOverride& given : options_.spec_constants) {
      const bool on_command_line =
          std::any_of(overrides_.begin(), overrides_.end(),
                      [&](const ConstantOverride& o) { return o.name == given.name; });
      if (!on_command_line) overrides_.push_back(given);
    }
    apply_overrides();
    evaluate_constants();
    declare_variables();
    if (has_modules) check_has_variables();
    collect_actions();
    lower_modules();
    lower_labels();
    lower_rewards();
    lower_init();
    collect_names();
    if (diagnostics_.error_count() != errors_before) return std::nullopt;
    return std::move(program_);
  }

 private:
  // --- Names -------------------------------------------------------------------------------

  // Renamed modules become copies; each copy's renaming is kept for the formulas it uses.
  void expand_modules() {
    renamings_.emplace_back();  // 0: names as written
    for (ExpandedModule& expanded :
         expand_renamed_modules(tree_.modules, tree_.formulas, diagnostics_)) {
      module_renaming_.push_back(expanded.renaming.empty() ? 0 : renamings_.size());
      if (!expanded.renaming.empty()) renamings_.push_back(std::move(expanded.renaming));
      modules_.push_back(std::move(expanded.module));
    }
  }

  [[nodiscard]] const std::string& renamed(const std::string& name, std::size_t renaming) const {
    const auto it = renamings_[renaming].find(name);
    return it == renamings_[renaming].end() ? name : it->second;
  }

  // PRISM refuses a program without a module ("There must be at least one module"), an empty
  // or comment-only file among them; exploring it would give one state and no behaviour. The
  // other checks still run, so that one run reports every error.
  bool check_has_modules() {
    if (!tree_.modules.empty()) return true;
    diagnostics_.error(start_of_program(),
                       std::string("the program declares no module: a PRISM program needs at "
                                   "least one") +
                           (tree_.type_given ? "" : ", after its model type (dtmc or mdp)"));
    return false;
  }

  // As PRISM: "There must be at least one variable".
  void check_has_variables() {
    if (!tree_.globals.empty()) return;
    for (const ast::Module& module : modules_)
      if (!module.variables.empty()) return;
    diagnostics_.error(start_of_program(),
                       "the program declares no variable: a PRISM program needs at least one");
  }

  // The model type if given, else the start of the file (not the end a comment-only file's
  // first token would be).
  [[nodiscard]] SourceRange start_of_program() const {
    if (tree_.type_given) return tree_.type_range;
    return SourceRange{SourceLocation{tree_.type_range.begin.file, 0}, 1};
  }

  void check_model_type() {
    program_.type = tree_.type == ast::ModelType::Dtmc ? ModelType::Dtmc : ModelType::Mdp;
    program_.range = tree_.type_range;
    // PRISM reads a program without a type as an MDP; so do we, and say so (unless the
    // program has no module, which is an error that says it).
    if (!tree_.type_given && !tree_.modules.empty()) {
      diagnostics_.warning(tree_.type_range,
                           "the program does not give its model type: read as "
                           "an mdp (start it with 'dtmc' or 'mdp')");
    }
  }

  bool declare(const std::string& name, Symbol symbol) {
    const auto [it, inserted] = symbols_.try_emplace(name, symbol);
    if (!inserted) {
      diagnostics_.error(symbol.range, quoted(name) + " is declared twice");
      diagnostics_.note(it->second.range, "first declared here");
    }
    return inserted;
  }

  void declare_constants_and_formulas() {
    for (std::size_t i = 0; i < tree_.constants.size(); ++i) {
      const ast::Constant& constant = tree_.constants[i];
      declare(constant.name, {Symbol::Kind::Constant, i, constant.range});
    }
    constants_.resize(tree_.constants.size());
    for (std::size_t i = 0; i < tree_.formulas.size(); ++i) {
      const ast::Formula& formula = tree_.formulas[i];
      declare(formula.name, {Symbol::Kind::Formula, i, formula.range});
    }
    formulas_.assign(renamings_.size(), std::vector<FormulaState>(tree_.formulas.size()));
  }

  // --- Constants -----------------------------------------------------------------------------

  struct ConstantState {
    enum class Status { Pending, Evaluating, Done, Failed } status = Status::Pending;
    std::optional<Expression> value;
    const ConstantOverride* given = nullptr;
  };

  void apply_overrides() {
    for (const ConstantOverride& given : overrides_) {
      const auto it = symbols_.find(given.name);
      if (it == symbols_.end() || it->second.kind != Symbol::Kind::Constant) {
        report_given(given, "the program has no constant " + quoted(given.name));
        continue;
      }
      const ast::Constant& constant = tree_.constants[it->second.index];
      if (constant.value) {
        diagnostics_.error(constant.range, "constant " + quoted(given.name) +
                                               " is defined here, so " +
                                               (given.given_at ? "the importing spec" : "--const") +
                                               " cannot set it");
        if (given.given_at) diagnostics_.note(*given.given_at, "the spec sets it here");
        continue;
      }
      constants_[it->second.index].given = &given;
    }
  }

  // A problem with a value given from outside the program: at the spec's `const` item, or
  // as a message about --const.
  void report_given(const ConstantOverride& given, const std::string& problem) {
    if (given.given_at)
      diagnostics_.error(*given.given_at, problem);
    else
      diagnostics_.plain_error("--const " + given.name + "=" + given.text + ": " + problem);
  }

  void evaluate_constants() {
    for (std::size_t i = 0; i < constants_.size(); ++i)
      constant_value(i);
  }

  std::optional<Expression> constant_value(std::size_t i) {
    ConstantState& state = constants_[i];
    const ast::Constant& constant = tree_.constants[i];
    switch (state.status) {
      case ConstantState::Status::Done:
        return state.value;
      case ConstantState::Status::Failed:
        return std::nullopt;
      case ConstantState::Status::Evaluating:
        diagnostics_.error(constant.range,
                           "constant " + quoted(constant.name) + " is defined in terms of itself");
        state.status = ConstantState::Status::Failed;
        return std::nullopt;
      case ConstantState::Status::Pending:
        break;
    }
    // Constants are evaluated in order, so only forward references nest; bound them.
    if (evaluating_constants_ >= limits::kMaxNesting) {
      diagnostics_.error(constant.range, "constants defined in terms of later ones more than " +
                                             std::to_string(limits::kMaxNesting) + " deep");
      state.status = ConstantState::Status::Failed;
      return std::nullopt;
    }
    state.status = ConstantState::Status::Evaluating;
    ++evaluating_constants_;
    std::optional<Expression> value = compute_constant(constant, state.given);
    --evaluating_constants_;
    if (constants_[i].status == ConstantState::Status::Failed) return std::nullopt;
    constants_[i].status = value ? ConstantState::Status::Done : ConstantState::Status::Failed;
    constants_[i].value = value;
    return value;
  }

  std::optional<Expression> compute_constant(const ast::Constant& constant,
                                             const ConstantOverride* given) {
    const Type wanted = constant.type == ast::ConstantType::Bool  ? Type::Bool
                        : constant.type == ast::ConstantType::Int ? Type::Int
                                                                  : Type::Real;
    if (!constant.value && given == nullptr) {
      const std::string where = options_.imported ? "in the importing spec ('const " +
                                                        constant.name + " = VALUE;') or with "
                                                  : "with ";
      diagnostics_.error(constant.range, "constant " + quoted(constant.name) +
                                             " has no value: define it here or give it " + where +
                                             "--const " + constant.name + "=VALUE");
      return std::nullopt;
    }
    if (given != nullptr) return overridden_value(constant, *given, wanted);
    auto value = lower(*constant.value, Scope::Constants, wanted,
                       "the value of constant " + quoted(constant.name));
    if (!value) return std::nullopt;
    if (!value->is_constant()) {
      diagnostics_.error(constant.value->range,
                         "the value of a constant must not depend on the state");
      return std::nullopt;
    }
    value->type = wanted;
    return value;
  }

  std::optional<Expression> overridden_value(const ast::Constant& constant,
                                             const ConstantOverride& given, Type wanted) {
    const bool is_bool = given.type == Type::Bool;
    const bool fits = wanted == Type::Bool  ? is_bool
                      : wanted == Type::Int ? !is_bool && given.value.get_den() == 1
                                            : !is_bool;
    if (!fits) {
      report_given(given, "constant " + quoted(constant.name) + " is " +
                              std::string(wanted == Type::Bool  ? "a bool"
                                          : wanted == Type::Int ? "an int"
                                                                : "a double"));
      return std::nullopt;
    }
    if (bit_size(given.value) > options_.max_number_bits) {
      report_given(given, too_long_message(given.value, options_.max_number_bits));
      return std::nullopt;
    }
    return Expression::make_constant(given.value, wanted, constant.range);
  }

  // Every name a property may use (Program::names), sorted. A formula the model does not use
  // is lowered here, and its errors reported, as PRISM checks every formula.
  void collect_names() {
    for (const auto& [name, symbol] : symbols_) {
      std::optional<Expression> value;
      switch (symbol.kind) {
        case Symbol::Kind::Constant:
          if (constants_[symbol.index].status == ConstantState::Status::Done)
            value = constants_[symbol.index].value;
          break;
        case Symbol::Kind::Formula:
          if (formula_as_written(symbol.index)) value = formulas_[0][symbol.index].value;
          break;
        case Symbol::Kind::Variable:
          value = variable_reference(symbol.index, symbol.range);
          break;
      }
      if (value) program_.names.emplace_back(name, std::move(*value));
    }
    std::sort(program_.names.begin(), program_.names.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
  }

  // --- Resolving names in expressions ------------------------------------------------------

  // Names in `expr` are read as written; the formulas it uses are read under the renaming of
  // the module being checked (current_renaming_).
  std::optional<Expression> lower(const ast::Expr& expr, Scope scope, Type wanted,
                                  const std::string& what) {
    ExpressionLowering lowering(diagnostics_, options_.max_number_bits,
                                [this, scope, renaming = current_renaming_](const ast::Expr& name) {
                                  return resolve(name, scope, renaming, /*in_formula=*/false);
                                });
    return lowering.lower_as(expr, wanted, what);
  }

  // `in_formula`: the name is inside a formula's definition, where the renaming applies.
  std::optional<Expression> resolve(const ast::Expr& name, Scope scope, std::size_t renaming,
                                    bool in_formula) {
    const std::string& text = in_formula ? renamed(name.text, renaming) : name.text;
    const auto it = symbols_.find(text);
    if (it == symbols_.end()) {
      diagnostics_.error(name.range, "unknown name " + quoted(text));
      return std::nullopt;
    }
    const Symbol& symbol = it->second;
    switch (symbol.kind) {
      case Symbol::Kind::Constant:
        return constant_value(symbol.index);
      case Symbol::Kind::Formula:
        return formula_value(symbol.index, name, scope, renaming);
      case Symbol::Kind::Variable:
        break;
    }
    if (scope == Scope::Constants) {
      diagnostics_.error(name.range, "variable " + quoted(text) +
                                         " cannot appear here: the value must be constant");
      return std::nullopt;
    }
    return variable_reference(symbol.index, name.range);
  }

  // A boolean variable is stored as 0 or 1; as an expression it reads `x = 1`.
  [[nodiscard]] Expression variable_reference(std::size_t slot, SourceRange range) const {
    Expression var;
    var.op = model::Op::Variable;
    var.type = Type::Int;
    var.slot = static_cast<std::uint32_t>(slot);
    var.range = range;
    if (!boolean_[slot]) return var;
    Expression test;
    test.op = model::Op::Equal;
    test.type = Type::Bool;
    test.range = range;
    test.operands = {std::move(var), Expression::make_constant(1, Type::Int, range)};
    return test;
  }

  struct FormulaState {
    bool expanding = false;
    bool failed = false;
    std::optional<Expression> value;  // lowered with variables
    int level = 0;                    // 1 + the deepest level of the formulas it uses
  };

  // Formula i with `renaming` applied to the names in its definition (PRISM expands formulas
  // before renaming modules), lowered once per renaming.
  std::optional<Expression> formula_value(std::size_t i, const ast::Expr& use, Scope scope,
                                          std::size_t renaming) {
    FormulaState& state = formulas_[renaming][i];
    const ast::Formula& formula = tree_.formulas[i];
    if (state.failed) return std::nullopt;
    if (state.expanding) {
      diagnostics_.error(formula.range, "formula " + quoted(formula.name) + " uses itself");
      state.failed = true;
      return std::nullopt;
    }
    const int outer_level = used_formula_level_;
    // A renamed module's base uses the formula as written: its problems (a cycle, a bad
    // name) are reported there, once, and not again for the copy.
    if (renaming != 0 && !formula_as_written(i)) return std::nullopt;
    if (!state.value && !expand_formula(i, renaming)) return std::nullopt;
    // The expression being lowered now reaches as deep as this formula does.
    used_formula_level_ = std::max(outer_level, state.level);
    if (scope == Scope::Constants && state.value->depends_on_state()) {
      diagnostics_.error(use.range, "formula " + quoted(formula.name) +
                                        " depends on the state; the value here must be constant");
      return std::nullopt;
    }
    return state.value;
  }

  bool formula_as_written(std::size_t i) {
    FormulaState& state = formulas_[0][i];
    if (state.failed) return false;
    return state.value || expand_formula(i, 0);
  }

  // Lowers formula i once. Formulas expand into one another, so the depth of a lowered
  // expression grows with how deeply they nest: that is bounded (kMaxFormulaNesting), and so
  // is the depth of every later pass over the expression (evaluation recurses).
  bool expand_formula(std::size_t i, std::size_t renaming) {
    const ast::Formula& formula = tree_.formulas[i];
    FormulaState& state = formulas_[renaming][i];
    if (++expanding_formulas_ > kMaxFormulaNesting) {
      diagnostics_.error(formula.range, "formulas nested more than " +
                                            std::to_string(kMaxFormulaNesting) +
                                            " deep, counted from formula " + quoted(formula.name));
      --expanding_formulas_;
      state.failed = true;
      return false;
    }
    state.expanding = true;
    used_formula_level_ = 0;
    ExpressionLowering lowering(diagnostics_, options_.max_number_bits,
                                [this, renaming](const ast::Expr& name) {
                                  return resolve(name, Scope::State, renaming, /*in_formula=*/true);
                                });
    auto value = lowering.lower(formula.value);
    --expanding_formulas_;
    state.expanding = false;
    state.level = used_formula_level_ + 1;
    if (value && state.level > kMaxFormulaNesting) {
      diagnostics_.error(formula.range, "formulas nested more than " +
                                            std::to_string(kMaxFormulaNesting) +
                                            " deep, counted from formula " + quoted(formula.name));
      value.reset();
    }
    if (!value) {
      state.failed = true;
      return false;
    }
    state.value = std::move(value);
    return true;
  }

  // --- Variables -------------------------------------------------------------------------

  void declare_variables() {
    for (const ast::Variable& var : tree_.globals)
      add_variable(var, kGlobal);
    for (std::size_t m = 0; m < modules_.size(); ++m) {
      current_renaming_ = module_renaming_[m];
      for (const ast::Variable& var : modules_[m].variables)
        add_variable(var, static_cast<std::int64_t>(m));
    }
    current_renaming_ = 0;
  }

  void add_variable(const ast::Variable& var, std::int64_t owner) {
    if (!declare(var.name, {Symbol::Kind::Variable, program_.variables.size(), var.range})) return;
    model::DiscreteVariable result;
    result.name = var.name;
    result.range = var.range;
    result.high = 1;
    if (!var.boolean) {
      const auto low = lower(var.low, Scope::Constants, Type::Int, "a variable's lower bound");
      const auto high = lower(var.high, Scope::Constants, Type::Int, "a variable's upper bound");
      if (low && high) {
        result.low = to_int(low->constant, var.low.range);
        result.high = to_int(high->constant, var.high.range);
        if (result.low > result.high) {
          diagnostics_.error(var.range, "the range of " + quoted(var.name) + " is empty: [" +
                                            std::to_string(result.low) + ".." +
                                            std::to_string(result.high) + "]");
        }
      }
    }
    result.init = result.low;
    if (var.init) initial_value(var, result);
    program_.variables.push_back(std::move(result));
    boolean_.push_back(var.boolean);
    owner_.push_back(owner);
  }

  void initial_value(const ast::Variable& var, model::DiscreteVariable& result) {
    if (tree_.init) {
      diagnostics_.error(var.init->range,
                         "a variable's 'init' cannot be given as well as "
                         "'init ... endinit'");
      return;
    }
    const auto init = lower(*var.init, Scope::Constants, var.boolean ? Type::Bool : Type::Int,
                            "the initial value of " + quoted(var.name));
    if (!init) return;
    result.init = to_int(init->constant, var.init->range);
    if (result.init < result.low || result.init > result.high) {
      diagnostics_.error(var.init->range, "initial value " + std::to_string(result.init) +
                                              " is outside the range of " + quoted(var.name));
    }
  }

  std::int64_t to_int(const Rational& value, SourceRange where) {
    // Ranges are kept well inside 64 bits so that their width never overflows.
    constexpr std::int64_t kLimit = std::int64_t{1} << 60;
    if (value.get_den() != 1 || !value.get_num().fits_slong_p() || value > kLimit ||
        value < -kLimit) {
      diagnostics_.error(where, "value " + describe(value) + " is not an integer within +-2^60");
      return 0;
    }
    return value.get_num().get_si();
  }

  // --- Modules ---------------------------------------------------------------------------

  void collect_actions() {
    std::unordered_map<std::string, std::uint32_t> index;
    for (const ast::Module& module : modules_) {
      for (const ast::Command& command : module.commands) {
        if (command.action.empty()) continue;
        if (index.try_emplace(command.action, program_.actions.size()).second)
          program_.actions.push_back(command.action);
      }
    }
    action_index_ = std::move(index);
  }

  void lower_modules() {
    for (std::size_t m = 0; m < modules_.size(); ++m) {
      current_renaming_ = module_renaming_[m];
      Module module;
      module.name = modules_[m].name;
      module.alphabet.assign(program_.actions.size(), false);
      for (const ast::Command& command : modules_[m].commands) {
        if (auto lowered = lower_command(command, static_cast<std::int64_t>(m))) {
          if (lowered->action) module.alphabet[*lowered->action] = true;
          lowered->serial = next_serial_++;
          module.commands.push_back(std::move(*lowered));
        }
      }
      program_.modules.push_back(std::move(module));
    }
    current_renaming_ = 0;
  }

  std::optional<Command> lower_command(const ast::Command& command, std::int64_t module) {
    Command result;
    result.range = command.range;
    if (!command.action.empty()) result.action = action_index_.at(command.action);
    auto guard = lower(command.guard, Scope::State, Type::Bool, "a guard");
    bool ok = guard.has_value();
    if (guard) result.guard = std::move(*guard);
    Rational constant_sum = 0;
    for (const ast::Update& update : command.updates) {
      auto lowered = lower_update(update, module, command);
      if (!lowered) {
        ok = false;
        continue;
      }
      if (lowered->probability.is_constant()) {
        constant_sum += lowered->probability.constant;
      } else {
        result.constant_probabilities = false;
      }
      result.updates.push_back(std::move(*lowered));
    }
    if (ok && result.constant_probabilities && constant_sum != 1) {
      diagnostics_.error(command.range, "the probabilities of this command sum to " +
                                            describe(constant_sum) + ", not 1");
      ok = false;
    }
    if (!ok) return std::nullopt;
    return result;
  }

  std::optional<Update> lower_update(const ast::Update& update, std::int64_t module,
                                     const ast::Command& command) {
    Update result;
    result.range = update.range;
    bool ok = true;
    if (update.probability) {
      auto p = lower(*update.probability, Scope::State, Type::Real, "a probability");
      if (!p) return std::nullopt;
      if (p->is_constant() && (p->constant < 0 || p->constant > 1)) {
        diagnostics_.error(update.probability->range,
                           "probability " + describe(p->constant) + " is not in [0, 1]");
        return std::nullopt;
      }
      result.probability = std::move(*p);
    } else {
      result.probability = Expression::make_constant(1, Type::Real, update.range);
    }
    std::vector<bool> assigned(program_.variables.size(), false);
    for (const ast::Assignment& assignment : update.assignments) {
      auto lowered = lower_assignment(assignment, module, command, assigned);
      if (!lowered) {
        ok = false;
        continue;
      }
      result.assignments.push_back(std::move(*lowered));
    }
    if (!ok) return std::nullopt;
    return result;
  }

  std::optional<model::Update> lower_assignment(const ast::Assignment& assignment,
                                                std::int64_t module, const ast::Command& command,
                                                std::vector<bool>& assigned) {
    const auto it = symbols_.find(assignment.variable);
    if (it == symbols_.end() || it->second.kind != Symbol::Kind::Variable) {
      diagnostics_.error(
          assignment.variable_range,
          quoted(assignment.variable) + " is not a variable, so it cannot be updated");
      return std::nullopt;
    }
    const std::size_t slot = it->second.index;
    if (owner_[slot] != kGlobal && owner_[slot] != module) {
      diagnostics_.error(assignment.variable_range,
                         "module " + quoted(modules_[module].name) + " cannot update " +
                             quoted(assignment.variable) + ", a variable of module " +
                             quoted(modules_[owner_[slot]].name));
      return std::nullopt;
    }
    // PRISM refuses any labelled command that updates a global (ModulesFileSemanticCheck):
    // otherwise two modules synchronising on the action could both write it, and which write
    // wins would depend on the order of the modules.
    if (owner_[slot] == kGlobal && !command.action.empty()) {
      diagnostics_.error(assignment.variable_range,
                         "global variable " + quoted(assignment.variable) +
                             " cannot be updated by a command with action " +
                             quoted(command.action) +
                             ": PRISM allows updates of globals only in unlabelled commands");
      return std::nullopt;
    }
    if (assigned[slot]) {
      diagnostics_.error(assignment.variable_range,
                         quoted(assignment.variable) + " is updated twice in one update");
      return std::nullopt;
    }
    assigned[slot] = true;
    auto value = lower(assignment.value, Scope::State, boolean_[slot] ? Type::Bool : Type::Int,
                       "the new value of " + quoted(assignment.variable));
    if (!value) return std::nullopt;
    if (boolean_[slot]) value = as_zero_one(std::move(*value));
    return model::Update{static_cast<std::uint32_t>(slot), std::move(*value),
                         assignment.variable_range};
  }

  // A boolean as the 0 or 1 a boolean variable stores.
  static Expression as_zero_one(Expression value) {
    if (value.is_constant()) {
      value.type = Type::Int;
      return value;
    }
    const SourceRange range = value.range;
    Expression choice;
    choice.op = model::Op::IfThenElse;
    choice.type = Type::Int;
    choice.range = range;
    choice.operands = {std::move(value), Expression::make_constant(1, Type::Int, range),
                       Expression::make_constant(0, Type::Int, range)};
    return choice;
  }

  // --- Labels, rewards, initial states -----------------------------------------------------

  void lower_labels() {
    std::map<std::string, SourceRange> seen;
    for (const ast::Label& label : tree_.labels) {
      if (label.name == "init" || label.name == "deadlock") {
        diagnostics_.error(label.range, "label " + quoted(label.name) +
                                            " is built in (the initial states, the states with "
                                            "no enabled command) and cannot be redefined");
        continue;
      }
      if (const auto [it, inserted] = seen.try_emplace(label.name, label.range); !inserted) {
        diagnostics_.error(label.range, "label " + quoted(label.name) + " is defined twice");
        diagnostics_.note(it->second, "first defined here");
        continue;
      }
      if (auto holds = lower(label.value, Scope::State, Type::Bool, "a label"))
        program_.labels.push_back({label.name, std::move(*holds)});
    }
  }

  void lower_rewards() {
    std::map<std::string, SourceRange> seen;
    for (std::size_t r = 0; r < tree_.rewards.size(); ++r) {
      const ast::Rewards& rewards = tree_.rewards[r];
      RewardStructure structure;
      structure.range = rewards.range;
      structure.name = rewards.name.empty() ? "rewards" + std::to_string(r + 1) : rewards.name;
      if (const auto [it, inserted] = seen.try_emplace(structure.name, rewards.range); !inserted) {
        diagnostics_.error(rewards.range,
                           "reward structure " + quoted(structure.name) + " is defined twice");
        diagnostics_.note(it->second, "first defined here");
        continue;
      }
      for (const ast::RewardItem& item : rewards.items) {
        if (auto lowered = lower_reward_item(item)) structure.items.push_back(std::move(*lowered));
      }
      program_.rewards.push_back(std::move(structure));
    }
    select_rewards();
  }

  // Keeps the structures --rewards selects, in the program's order.
  void select_rewards() {
    const model::LabelSelection& selection = options_.rewards;
    using Kind = model::LabelSelection::Kind;
    if (selection.kind == Kind::kAll) return;
    std::vector<RewardStructure> kept;
    for (std::size_t i = 0; i < selection.names.size(); ++i) {
      const std::string& name = selection.names[i];
      const auto found = std::find_if(program_.rewards.begin(), program_.rewards.end(),
                                      [&](const RewardStructure& r) { return r.name == name; });
      if (found != program_.rewards.end()) continue;
      std::string known;
      for (const RewardStructure& r : program_.rewards)
        known += (known.empty() ? "" : ", ") + quoted(r.name);
      const std::string problem =
          "the program has no reward structure " + quoted(name) +
          (known.empty() ? std::string(" (it has none)") : " (it has " + known + ")");
      if (i < options_.reward_ranges.size())
        diagnostics_.error(options_.reward_ranges[i], problem);
      else
        diagnostics_.plain_error("--rewards: " + problem);
    }
    for (RewardStructure& structure : program_.rewards) {
      const bool named = std::find(selection.names.begin(), selection.names.end(),
                                   structure.name) != selection.names.end();
      if (selection.kind == Kind::kNamed && named) kept.push_back(std::move(structure));
    }
    program_.rewards = std::move(kept);
  }

  std::optional<RewardItem> lower_reward_item(const ast::RewardItem& item) {
    RewardItem result;
    if (item.action) {
      if (item.action->empty()) {
        result.kind = RewardItem::Kind::Unlabelled;
      } else {
        const auto it = action_index_.find(*item.action);
        if (it == action_index_.end()) {
          diagnostics_.error(item.action_range, "no module has action " + quoted(*item.action));
          return std::nullopt;
        }
        result.kind = RewardItem::Kind::Action;
        result.action = it->second;
      }
    }
    auto guard = lower(item.guard, Scope::State, Type::Bool, "a reward's guard");
    auto value = lower(item.value, Scope::State, Type::Real, "a reward");
    if (!guard || !value) return std::nullopt;
    result.guard = std::move(*guard);
    result.value = std::move(*value);
    return result;
  }

  void lower_init() {
    if (!tree_.init) return;
    program_.init_predicate =
        lower(*tree_.init, Scope::State, Type::Bool, "the initial states' predicate");
  }

  const ast::Program& tree_;
  DiagnosticEngine& diagnostics_;
  const CheckOptions& options_;
  Program program_;
  std::vector<ast::Module> modules_;          // renamed modules expanded
  std::vector<std::size_t> module_renaming_;  // per module: its index into renamings_
  std::vector<Renaming> renamings_;           // [0]: none; then one per renamed copy
  std::size_t current_renaming_ = 0;          // of the module whose parts are being lowered
  std::unordered_map<std::string, Symbol> symbols_;
  std::vector<ConstantOverride> overrides_;
  std::vector<ConstantState> constants_;
  std::vector<std::vector<FormulaState>> formulas_;  // [renaming][formula]
  int used_formula_level_ = 0;       // the deepest formula level the current lowering uses
  int expanding_formulas_ = 0;       // formulas being lowered, one inside another
  int evaluating_constants_ = 0;     // constants being evaluated, one inside another
  std::vector<bool> boolean_;        // per variable
  std::vector<std::int64_t> owner_;  // per variable: its module, or kGlobal
  std::unordered_map<std::string, std::uint32_t> action_index_;
  std::uint32_t next_serial_ = 0;
};

}  // namespace

std::optional<Program> check(const ast::Program& tree, std::string name,
                             DiagnosticEngine& diagnostics, const CheckOptions& options) {
  return Checker(tree, std::move(name), diagnostics, options).run();
}

}  // namespace oasis::prism
