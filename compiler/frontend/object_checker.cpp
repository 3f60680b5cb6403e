#include "frontend/object_checker.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "support/text.hpp"

namespace oasis::frontend {
namespace {

using Polynomial = std::array<Rational, 3>;  // c0 + c1 d + c2 d^2

constexpr std::string_view kDistance = "d";

bool mentions_distance(const ast::Expr& expr) {
  if (expr.kind == ast::ExprKind::Name && expr.text == kDistance) return true;
  for (const auto& operand : expr.operands)
    if (mentions_distance(*operand)) return true;
  return false;
}

// sigma(d) read as a polynomial of degree at most 2 in the distance `d`: sums, differences,
// products and quotients by constants of numbers, constants and d.
class SigmaReader {
 public:
  SigmaReader(DiagnosticEngine& diagnostics, ExpressionChecker& expressions)
      : diagnostics_(diagnostics), expressions_(expressions) {}

  std::optional<Polynomial> read(const ast::Expr& expr) {
    if (!mentions_distance(expr)) {
      const auto value = expressions_.constant_number(expr, "sigma(d)");
      if (!value) return std::nullopt;
      return Polynomial{*value, 0, 0};
    }
    if (expr.kind == ast::ExprKind::Name) return Polynomial{0, 1, 0};
    if (expr.kind == ast::ExprKind::Unary && expr.op == TokenKind::Minus) {
      auto inner = read(*expr.operands[0]);
      if (inner)
        for (Rational& c : *inner)
          c = -c;
      return inner;
    }
    if (expr.kind == ast::ExprKind::Binary) return binary(expr);
    return refuse(expr);
  }

 private:
  std::optional<Polynomial> binary(const ast::Expr& expr) {
    const ast::Expr& left_expr = *expr.operands[0];
    const ast::Expr& right_expr = *expr.operands[1];
    if (expr.op == TokenKind::Slash && mentions_distance(right_expr)) return refuse(expr);
    if (expr.op != TokenKind::Plus && expr.op != TokenKind::Minus && expr.op != TokenKind::Star &&
        expr.op != TokenKind::Slash)
      return refuse(expr);
    const auto left = read(left_expr);
    const auto right = read(right_expr);
    if (!left || !right) return std::nullopt;
    Polynomial out{0, 0, 0};
    switch (expr.op) {
      case TokenKind::Plus:
      case TokenKind::Minus:
        for (std::size_t k = 0; k < 3; ++k)
          out[k] = expr.op == TokenKind::Plus ? Rational((*left)[k] + (*right)[k])
                                              : Rational((*left)[k] - (*right)[k]);
        return out;
      case TokenKind::Slash:
        if ((*right)[0] == 0) {
          diagnostics_.error(right_expr.range, "division by zero");
          return std::nullopt;
        }
        for (std::size_t k = 0; k < 3; ++k)
          out[k] = (*left)[k] / (*right)[0];
        return out;
      default:
        return product(expr, *left, *right);
    }
  }

  std::optional<Polynomial> product(const ast::Expr& expr, const Polynomial& left,
                                    const Polynomial& right) {
    Polynomial out{0, 0, 0};
    for (std::size_t i = 0; i < 3; ++i) {
      for (std::size_t j = 0; j < 3; ++j) {
        if (left[i] == 0 || right[j] == 0) continue;
        if (i + j > 2) {
          diagnostics_.error(expr.range,
                             "sigma(d) must be at most quadratic in the distance d: a + b * d + "
                             "c * d * d");
          return std::nullopt;
        }
        out[i + j] += left[i] * right[j];
      }
    }
    return out;
  }

  std::optional<Polynomial> refuse(const ast::Expr& expr) {
    diagnostics_.error(expr.range,
                       "sigma(d) is a polynomial in the distance d: numbers, constants, d, "
                       "'+', '-', '*' and division by a number (a + b * d + c * d * d)");
    return std::nullopt;
  }

  DiagnosticEngine& diagnostics_;
  ExpressionChecker& expressions_;
};

// The farthest an object's point can be from the origin within the variables' bounds.
double farthest_distance(const model::ModelIR& ir, const std::vector<std::uint32_t>& variables) {
  double squared = 0.0;
  for (const std::uint32_t v : variables) {
    const double low = std::fabs(to_double(ir.continuous[v].low));
    const double high = std::fabs(to_double(ir.continuous[v].high));
    squared += std::max(low, high) * std::max(low, high);
  }
  return std::sqrt(squared);
}

// sigma(d) >= 0 on [0, farthest]: at both ends and at the parabola's vertex if inside.
std::optional<double> negative_at(const Polynomial& sigma, double farthest) {
  const double a = to_double(sigma[0]);
  const double b = to_double(sigma[1]);
  const double c = to_double(sigma[2]);
  std::vector<double> probes{0.0, farthest};
  if (c != 0.0 && -b / (2 * c) > 0.0 && -b / (2 * c) < farthest) probes.push_back(-b / (2 * c));
  for (const double d : probes)
    if (a + b * d + c * d * d < 0.0) return d;
  return std::nullopt;
}

std::string short_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

struct ObjectChecker {
  const Scope& scope;
  model::ModelIR& ir;
  DiagnosticEngine& diagnostics;
  ExpressionChecker& expressions;
  std::vector<const ast::Name*> measured_by;  // per continuous variable

  std::optional<std::uint32_t> variable(const ast::Name& name) {
    const auto* entry = scope.find(name.text);
    if (entry == nullptr || entry->value.kind != SymbolKind::ContinuousVariable) {
      diagnostics.error(name.range, entry == nullptr
                                        ? "unknown variable " + quoted(name.text)
                                        : std::string(describe(entry->value.kind)) + " " +
                                              quoted(name.text) + " is not a continuous variable");
      return std::nullopt;
    }
    const std::uint32_t index = entry->value.index;
    if (measured_by[index] != nullptr) {
      diagnostics.error(name.range,
                        "variable " + quoted(name.text) + " is already measured by another object");
      diagnostics.note(measured_by[index]->range, "first measured here");
      return std::nullopt;
    }
    measured_by[index] = &name;
    return index;
  }

  // `reach_known`: the object's variables checked, so its distance range is known.
  bool sigma(const ast::ObjectDecl& decl, model::MeasuredObject& object, bool reach_known) {
    if (!decl.noise) return true;  // no noise: only missed detections
    SigmaReader reader(diagnostics, expressions);
    const auto polynomial = reader.read(*decl.noise);
    if (!polynomial) return false;
    if (!reach_known) return true;
    const double farthest = farthest_distance(ir, object.variables);
    if (const auto at = negative_at(*polynomial, farthest)) {
      diagnostics.error(decl.noise->range, "sigma(d) is negative at d = " + short_number(*at) +
                                               ", within the object's reach (d from 0 to " +
                                               short_number(farthest) + ")");
      return false;
    }
    object.sigma = *polynomial;
    return true;
  }

  bool detection(const ast::ObjectDecl& decl, model::MeasuredObject& object) {
    if (!decl.detection) return true;
    const auto p = expressions.constant_number(*decl.detection, "the detection probability");
    if (!p) return false;
    if (*p <= 0 || *p > 1) {
      diagnostics.error(decl.detection->range,
                        "the detection probability must be in (0, 1], not " + describe(*p));
      return false;
    }
    object.detection = *p;
    return true;
  }

  std::optional<model::MeasuredObject> check(const ast::ObjectDecl& decl) {
    model::MeasuredObject object;
    object.name = std::string(decl.name.text);
    object.sigma = {0, 0, 0};
    bool ok = true;
    for (const ast::Name& name : decl.variables) {
      const auto index = variable(name);
      ok = ok && index.has_value();
      if (index) object.variables.push_back(*index);
    }
    const bool sigma_ok = sigma(decl, object, ok);
    const bool detection_ok = detection(decl, object);
    if (!ok || !sigma_ok || !detection_ok) return std::nullopt;
    return object;
  }
};

}  // namespace

bool check_objects(const ast::ObservationDecl& decl, const Scope& scope, model::ModelIR& ir,
                   DiagnosticEngine& diagnostics, ExpressionChecker& expressions) {
  ObjectChecker checker{scope, ir, diagnostics, expressions,
                        std::vector<const ast::Name*>(ir.continuous.size(), nullptr)};
  std::vector<model::MeasuredObject> objects;
  std::vector<const ast::Name*> names;
  bool ok = true;
  for (const ast::ObjectDecl& object : decl.objects) {
    for (const ast::Name* other : names) {
      if (other->text != object.name.text) continue;
      diagnostics.error(object.name.range,
                        "object " + quoted(object.name.text) + " is already declared");
      diagnostics.note(other->range, "first declared here");
      ok = false;
    }
    names.push_back(&object.name);
    auto checked = checker.check(object);
    ok = ok && checked.has_value();
    if (checked) objects.push_back(std::move(*checked));
  }
  if (ok) ir.observation.objects = std::move(objects);
  return ok;
}

}  // namespace oasis::frontend
