#pragma once
// The syntax tree of PRISM's property language (docs/properties.md), as written. A property is
// a PRISM expression (prism/ast.hpp) whose Extension nodes are the operators below, kept in
// one table per file: `P=? [F "one"]` is an Extension node whose index names a Quantifier.

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "prism/ast.hpp"

namespace oasis::property {

// A path formula, inside P[...]: X psi, phi U psi, F psi, G psi, with an optional step bound
// (`F<=k`, `U<=k`; `<k` is read as `<=k-1`, as PRISM reads it).
struct PathFormula {
  enum class Kind { kNext, kUntil, kEventually, kGlobally };
  Kind kind = Kind::kEventually;
  std::optional<prism::ast::Expr> left;  // kUntil only
  prism::ast::Expr right;
  std::optional<prism::ast::Expr> steps;  // the bound k
  bool strict_bound = false;              // `<k`
  SourceRange range;
};

// A reward formula, inside R[...]: F psi (reachability), C<=k (cumulative), I=k (instant).
struct RewardFormula {
  enum class Kind { kReachability, kCumulative, kInstantaneous };
  Kind kind = Kind::kReachability;
  std::optional<prism::ast::Expr> target;  // kReachability
  std::optional<prism::ast::Expr> steps;   // kCumulative, kInstantaneous
  SourceRange range;
};

// P or R with its optimum and its comparison: `Pmax=? [...]`, `P>=0.5 [...]`,
// `R{"time"}min=? [F "done"]`.
struct Quantifier {
  enum class Optimum { kNone, kMin, kMax };
  enum class Comparison { kQuery, kLess, kLessEqual, kGreater, kGreaterEqual };
  bool reward = false;  // R rather than P
  Optimum optimum = Optimum::kNone;
  Comparison comparison = Comparison::kQuery;
  std::optional<prism::ast::Expr> bound;   // the b of P>=b
  std::optional<std::string> reward_name;  // R{"name"}; none: the first structure
  SourceRange reward_name_range;
  PathFormula path;              // P
  RewardFormula reward_formula;  // R
  SourceRange range;             // the whole operator
  SourceRange head_range;        // `Pmax=?`, `R{"time"}>=3`
};

// A label, `"goal"`: the states where it holds.
struct LabelReference {
  std::string name;
  SourceRange range;
};

// filter(op, property[, states]): PRISM's filters. Without states a filter reads every state;
// a property without a filter is read as filter(first, property, "init") (a number) or
// filter(forall, property, "init") (a truth value).
struct Filter {
  enum class Op { kFirst, kMin, kMax, kAvg, kSum, kCount, kForall, kExists };
  Op op = Op::kFirst;
  prism::ast::Expr property;
  std::optional<prism::ast::Expr> states;  // none: every state, or the initial ones (below)
  bool initial_states = false;             // the implicit filter of a property
  SourceRange range;
};

using Extension = std::variant<Quantifier, LabelReference, Filter>;

struct Property {
  std::optional<std::string> name;  // `"name": P=? [...]`
  prism::ast::Expr expression;
  std::string text;  // as written, for the answer's line
  SourceRange range;
};

// `const int k = 3;` or `label "safe" = x < 4;` in a properties file: a name its
// properties may use, defined there. A constant must have its value (`--const` sets the
// program's constants only).
struct Definition {
  std::string name;
  prism::ast::Expr value;
  SourceRange range;  // the name
};

struct PropertiesFile {
  std::vector<Property> properties;
  std::vector<Extension> extensions;  // indexed by the Extension nodes' text
  std::vector<Definition> constants;
  std::vector<Definition> labels;
};

}  // namespace oasis::property
