#pragma once
// Module renaming: `module m2 = m1 [x1=x2, a=b] endmodule` is a copy of m1 in which every
// name the renaming lists (variables, actions, constants) is replaced. As in PRISM, formulas
// are expanded before renaming: a formula the copy uses reads its expansion renamed (the
// checker applies `renaming` to the names inside it), and a formula's own name cannot be renamed.

#include <string>
#include <unordered_map>
#include <vector>

#include "prism/ast.hpp"

namespace oasis::prism {

using Renaming = std::unordered_map<std::string, std::string>;

struct ExpandedModule {
  ast::Module module;  // as written, or the renamed copy
  Renaming renaming;   // empty for a module as written
};

// The modules with every renamed one replaced by its copy. A renaming of a module that does
// not exist, of another renamed module, or of a formula is reported and that module left out.
std::vector<ExpandedModule> expand_renamed_modules(const std::vector<ast::Module>& modules,
                                                   const std::vector<ast::Formula>& formulas,
                                                   DiagnosticEngine& diagnostics);

}  // namespace oasis::prism
