#include "support/double_range.hpp"

#include <cfloat>
#include <cmath>
#include <cstdio>

namespace oasis {

DoubleFit double_fit(const Rational& value) {
  if (sgn(value) == 0) return DoubleFit::kFaithful;
  // Compared exactly: a double converts to a rational without rounding.
  static const Rational largest(DBL_MAX);
  static const Rational smallest_normal(DBL_MIN);
  const Rational magnitude = abs(value);
  if (magnitude > largest) return DoubleFit::kOverflow;
  if (magnitude >= smallest_normal) return DoubleFit::kFaithful;
  return to_double(value) == 0 ? DoubleFit::kUnderflow : DoubleFit::kSubnormal;
}

double relative_rounding_error(const Rational& value) {
  if (sgn(value) == 0) return 0;
  const double nearest = to_double(value);
  if (!std::isfinite(nearest)) return HUGE_VAL;
  return to_double(abs((Rational(nearest) - value) / value));
}

std::string carried_value_message(const Rational& value, DoubleFit fit, std::string_view what) {
  const std::string subject = std::string(what) + " " + describe(value);
  switch (fit) {
    case DoubleFit::kFaithful:
      return {};
    case DoubleFit::kOverflow:
      return subject + " is beyond the largest double (about 1.8e+308): a catalog cannot " +
             "carry it";
    case DoubleFit::kUnderflow:
      return subject + " is below the smallest positive double (about 4.9e-324): a catalog " +
             "would carry it as 0";
    case DoubleFit::kSubnormal: {
      char loss[64];
      std::snprintf(loss, sizeof loss, "%.3g", relative_rounding_error(value));
      return subject + " is below the smallest normal double (about 2.2e-308): a catalog " +
             "carries it with a relative error of " + loss;
    }
  }
  return {};
}

bool check_carried_value(const Rational& value, std::string_view what, SourceRange where,
                         DiagnosticEngine& diagnostics) {
  const DoubleFit fit = double_fit(value);
  if (fit == DoubleFit::kFaithful) return true;
  const std::string message = carried_value_message(value, fit, what);
  if (fit == DoubleFit::kSubnormal) {
    diagnostics.warning(where, message);
    return true;
  }
  diagnostics.error(where, message);
  return false;
}

}  // namespace oasis
