#pragma once
// Values for a program's constants from the command line (--const N=4,p=0.1,fair=true), as
// PRISM's -const takes them: numbers are exact (0.1 is 1/10; 1/3 may be written as such).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/expression.hpp"

namespace oasis::prism {

struct ConstantOverride {
  std::string name;
  std::string text;                      // as given
  model::Type type = model::Type::Real;  // Bool for true/false; Int/Real for numbers
  Rational value;                        // booleans: 0 or 1
  // Where a spec that imports the program gave it (`const N = 4;`); none: the command line.
  std::optional<SourceRange> given_at;
};

// Reports malformed entries and names given twice with diagnostics.plain_error().
std::vector<ConstantOverride> read_constant_overrides(std::string_view text,
                                                      DiagnosticEngine& diagnostics);

}  // namespace oasis::prism
