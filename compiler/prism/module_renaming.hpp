#pragma once
// Module renaming: `module m2 = m1 [x1=x2, a=b] endmodule` is a copy of m1 in which every
// name the renaming lists (variables, actions, constants, formulas) is replaced.

#include <vector>

#include "prism/ast.hpp"

namespace oasis::prism {

// The modules with every renamed one replaced by its copy. A renaming of a module that does
// not exist, or of another renamed module, is reported and that module left out.
std::vector<ast::Module> expand_renamed_modules(const std::vector<ast::Module>& modules,
                                                DiagnosticEngine& diagnostics);

}  // namespace oasis::prism
