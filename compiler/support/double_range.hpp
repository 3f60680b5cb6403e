#pragma once
// Can a catalog carry this value? The compiler is exact (GMP rationals); every catalog
// carrier (binary file, generated C++, JSON) holds IEEE-754 doubles, the nearest double to
// each exact value. Ordinary rounding (a relative error of at most 2^-53) is the contract of
// the catalog and goes unmentioned. Beyond it:
//  * a value larger in magnitude than the largest double (about 1.8e308) cannot be carried:
//    it would become infinite, and the runtime refuses non-finite tables;
//  * a non-zero value whose nearest double is 0 cannot be carried: a probability would leave
//    the support, a reward or a discount would vanish;
//  * a non-zero value below the smallest normal double (about 2.2e-308) is carried as a
//    subnormal with fewer significant bits: lossy, and the caller warns with the relative
//    error.
// Front ends call check_carried_value() where each number enters a model, so that `check`
// reports it at its file:line:col and `compile` never meets it.

#include <cstdint>
#include <string>
#include <string_view>

#include "support/diagnostics.hpp"
#include "support/rational.hpp"

namespace oasis {

enum class DoubleFit : std::uint8_t {
  kFaithful,   // zero, or a normal double within ordinary rounding
  kSubnormal,  // carried with a reduced precision (lossy)
  kUnderflow,  // non-zero, but the nearest double is 0
  kOverflow,   // beyond the largest finite double
};

[[nodiscard]] DoubleFit double_fit(const Rational& value);

// |nearest double - value| / |value|, for messages about lossy values (0 for value 0).
[[nodiscard]] double relative_rounding_error(const Rational& value);

// The message for a value that cannot be carried (kUnderflow, kOverflow) or is carried with a
// loss (kSubnormal), naming it as `what` ("the probability", "the reward"); empty when the
// value is faithful.
[[nodiscard]] std::string carried_value_message(const Rational& value, DoubleFit fit,
                                                std::string_view what);

// Reports `value` at `where`: an error when it cannot be carried, a warning saying how much
// is lost when it is subnormal. Returns false after an error.
bool check_carried_value(const Rational& value, std::string_view what, SourceRange where,
                         DiagnosticEngine& diagnostics);

}  // namespace oasis
