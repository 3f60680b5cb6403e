#include "prism/module_renaming.hpp"

#include <algorithm>
#include <string>
#include <unordered_map>

#include "support/text.hpp"

namespace oasis::prism {
namespace {

void rename(std::string& name, const Renaming& renaming) {
  if (const auto it = renaming.find(name); it != renaming.end()) name = it->second;
}

void rename(ast::Expr& expr, const Renaming& renaming) {
  if (expr.kind == ast::Expr::Kind::Name) rename(expr.text, renaming);
  for (ast::Expr& operand : expr.operands)
    rename(operand, renaming);
}

void rename(ast::Variable& var, const Renaming& renaming) {
  rename(var.name, renaming);
  if (!var.boolean) {
    rename(var.low, renaming);
    rename(var.high, renaming);
  }
  if (var.init) rename(*var.init, renaming);
}

void rename(ast::Command& command, const Renaming& renaming) {
  if (!command.action.empty()) rename(command.action, renaming);
  rename(command.guard, renaming);
  for (ast::Update& update : command.updates) {
    if (update.probability) rename(*update.probability, renaming);
    for (ast::Assignment& assignment : update.assignments) {
      rename(assignment.variable, renaming);
      rename(assignment.value, renaming);
    }
  }
}

const ast::Module* find_base(const std::vector<ast::Module>& modules, const ast::Module& copy,
                             DiagnosticEngine& diagnostics) {
  const auto base = std::find_if(modules.begin(), modules.end(),
                                 [&](const ast::Module& m) { return m.name == *copy.base; });
  if (base == modules.end()) {
    diagnostics.error(copy.base_range, "no module " + quoted(*copy.base) + " to copy");
    return nullptr;
  }
  if (base->base) {
    diagnostics.error(copy.base_range, "module " + quoted(*copy.base) +
                                           " is itself a renamed copy; copy " +
                                           quoted(*base->base) + " instead");
    return nullptr;
  }
  return &*base;
}

bool is_formula(const std::vector<ast::Formula>& formulas, const std::string& name) {
  return std::any_of(formulas.begin(), formulas.end(),
                     [&](const ast::Formula& f) { return f.name == name; });
}

std::optional<Renaming> renaming_of(const ast::Module& copy,
                                    const std::vector<ast::Formula>& formulas,
                                    DiagnosticEngine& diagnostics) {
  Renaming renaming;
  bool ok = true;
  for (const ast::Rename& rename : copy.renames) {
    if (is_formula(formulas, rename.from)) {
      diagnostics.error(rename.range, "formula " + quoted(rename.from) +
                                          " cannot be renamed: formulas are expanded before "
                                          "renaming, so rename the names it uses");
      ok = false;
    } else if (!renaming.try_emplace(rename.from, rename.to).second) {
      diagnostics.error(rename.range, quoted(rename.from) + " is renamed twice");
      ok = false;
    }
  }
  if (!ok) return std::nullopt;
  return renaming;
}

}  // namespace

std::vector<ExpandedModule> expand_renamed_modules(const std::vector<ast::Module>& modules,
                                                   const std::vector<ast::Formula>& formulas,
                                                   DiagnosticEngine& diagnostics) {
  std::vector<ExpandedModule> result;
  for (const ast::Module& module : modules) {
    if (!module.base) {
      result.push_back({module, {}});
      continue;
    }
    const ast::Module* base = find_base(modules, module, diagnostics);
    auto renaming = renaming_of(module, formulas, diagnostics);
    if (base == nullptr || !renaming) continue;
    ast::Module copy = *base;
    copy.name = module.name;
    copy.range = module.range;
    for (ast::Variable& var : copy.variables)
      rename(var, *renaming);
    for (ast::Command& command : copy.commands)
      rename(command, *renaming);
    result.push_back({std::move(copy), std::move(*renaming)});
  }
  return result;
}

}  // namespace oasis::prism
