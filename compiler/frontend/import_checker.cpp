#include "frontend/import_checker.hpp"

#include <string>

#include "frontend/catalog_checker.hpp"
#include "frontend/expression_checker.hpp"
#include "frontend/objective_checker.hpp"
#include "frontend/observation_checker.hpp"
#include "frontend/scope.hpp"
#include "support/text.hpp"

namespace oasis::frontend {
namespace {

class ImportChecker {
 public:
  ImportChecker(const ast::SpecFile& spec, DiagnosticEngine& diagnostics,
                std::size_t max_number_bits)
      : spec_(spec),
        import_(spec.imports.front()),
        diagnostics_(diagnostics),
        expressions_(scope_, diagnostics, max_number_bits) {}

  std::optional<model::ModelIR> run() {
    refuse_second_models();
    // Explored like a factored spec: states are valuations of the program's variables.
    ir_.kind = model::ModelKind::Factored;
    ir_.name = model_name();
    ir_.range = import_.range;
    ir_.objective_range = import_.path.range;
    ir_.imported = model::ImportedProgram{std::string(import_.path.text), import_.path.range, {}};
    check_constants();
    check_objective(import_.discount, import_.horizon, ir_, diagnostics_, expressions_);
    check_catalog();
    if (diagnostics_.has_errors()) return std::nullopt;
    return std::move(ir_);
  }

 private:
  void refuse_second_models() {
    for (std::size_t i = 1; i < spec_.imports.size(); ++i)
      diagnostics_.error(spec_.imports[i].path.range, "a spec imports at most one program");
    for (const ast::MdpDecl& mdp : spec_.mdps) {
      diagnostics_.error(mdp.name.range,
                         "a spec imports its model or declares it in an 'mdp' block, not both");
    }
    for (std::size_t i = 1; i < spec_.catalogs.size(); ++i)
      diagnostics_.error(spec_.catalogs[i].range, "a spec holds at most one 'catalog'");
  }

  // The file's name without its folder and extension, as `oasisc quotient robot.nm` names it.
  std::string model_name() const {
    std::string_view name = import_.path.text;
    if (const auto slash = name.find_last_of('/'); slash != std::string_view::npos)
      name.remove_prefix(slash + 1);
    if (const auto dot = name.find_last_of('.'); dot != std::string_view::npos && dot > 0)
      name = name.substr(0, dot);
    return name.empty() ? std::string("imported") : std::string(name);
  }

  // `const N = 4;`: values for the program's constants. A later one may use an earlier one.
  void check_constants() {
    for (const ast::ConstDecl& constant : import_.constants) {
      const auto value = declare_constant(constant, scope_, expressions_, diagnostics_);
      if (!value) continue;
      ir_.imported->constants.push_back(
          {std::string(constant.name.text), value->constant, value->type, constant.range});
    }
  }

  void check_catalog() {
    if (spec_.catalogs.empty()) {
      // One context, the program without rewards, as `oasisc compile robot.nm` builds it.
      model::ContextIR context;
      context.name = "default";
      context.range = import_.path.range;
      ir_.contexts.push_back(std::move(context));
      ir_.switching.matrix = {Rational(1)};
      ir_.switching.prior = {Rational(1)};
      return;
    }
    const ast::CatalogDecl& catalog = spec_.catalogs.front();
    if (!check_context_count(catalog, diagnostics_)) return;
    NameTable<std::uint32_t> names;
    for (const ast::ContextDecl& decl : catalog.contexts) {
      const auto index = static_cast<std::uint32_t>(ir_.contexts.size());
      if (!names.declare(decl.name.text, decl.name.range, index, "context", diagnostics_)) continue;
      if (!decl.reward_structure && !decl.is_base) {
        diagnostics_.error(decl.range,
                           "a context of an imported program takes one of its reward structures: "
                           "write 'context " +
                               std::string(decl.name.text) + " = rewards \"NAME\";'");
        continue;
      }
      model::ContextIR context;
      context.name = std::string(decl.name.text);
      context.range = decl.range;
      if (decl.reward_structure) {
        context.reward_structure = std::string(decl.reward_structure->text);
        context.reward_structure_range = decl.reward_structure->range;
      }
      ir_.contexts.push_back(std::move(context));
    }
    if (diagnostics_.has_errors()) return;
    check_switching_and_prior(catalog, names, ir_, diagnostics_, expressions_);
    check_properties(catalog, /*continuous=*/false, ir_, diagnostics_);
    if (catalog.observation)
      check_observation(*catalog.observation, scope_, ir_, diagnostics_, expressions_);
  }

  const ast::SpecFile& spec_;
  const ast::ImportDecl& import_;
  DiagnosticEngine& diagnostics_;
  Scope scope_;
  ExpressionChecker expressions_;
  model::ModelIR ir_;
};

}  // namespace

std::optional<model::ModelIR> check_import_spec(const ast::SpecFile& spec,
                                                DiagnosticEngine& diagnostics,
                                                std::size_t max_number_bits) {
  return ImportChecker(spec, diagnostics, max_number_bits).run();
}

}  // namespace oasis::frontend
