#include "model/enclosure_program.hpp"

#include <algorithm>
#include <bit>
#include <limits>
#include <stdexcept>
#include <utility>

#include "model/enclosure.hpp"
#include "model/enclosure_rules.hpp"

namespace oasis::model {
namespace rules = enclosure_rules;
using Code = EnclosureProgram::Code;
using Instruction = EnclosureProgram::Instruction;
using Failure = EnclosureProgram::Failure;

namespace {

constexpr Interval kZero{0, 0};
constexpr Interval kMinusOne{-1, -1};

// What instructions read besides their operands' slots.
struct Tables {
  std::span<const Interval> loaded;
  std::span<const Interval> loaded_gradients;
  std::span<const Failure> failures;
  std::span<const SourceRange> locations;
  std::size_t dimension;
};

[[noreturn]] void raise(const Failure& failure) {
  if (failure.located) throw EnclosureError(failure.where, failure.message);
  throw std::invalid_argument(failure.message);
}

// The same check as enclose_natural's: finite, non-empty sides.
void check_box(std::span<const Interval> box) {
  for (const Interval& side : box) {
    if (!side.is_finite() || side.lo > side.hi) {
      throw std::invalid_argument("an enclosure's box needs finite, non-empty intervals, not " +
                                  to_string(side));
    }
  }
}

// An instruction's range, from its operands' ranges in `values` (the tree walk's `natural`).
Interval value_of(const Instruction& in, std::span<const Interval> values,
                  std::span<const Interval> box, const Tables& tables) {
  switch (in.code) {
    case Code::kLoad:
      return tables.loaded[in.a];
    case Code::kVariable:
      return box[in.a];
    case Code::kUnary:
      return rules::unary(in.op, values[in.a]);
    case Code::kBinary:
      return rules::binary(in.op, values[in.a], values[in.b]);
    case Code::kPower:
      return power(values[in.a], in.exponent);
    case Code::kFail:
      break;
  }
  raise(tables.failures[in.a]);
}

// ---- Gradients, sparse ----
// An instruction's `mask` says which partial derivatives may be nonzero (bit j: d/dx_j; every
// bit when there are more than 64 variables). The others are exactly [+0, +0] in the tree
// walk: a zero partial times any finite factor, or plus another zero partial, is [+0, +0]
// again, and such an operation cannot throw. So only the partials in the mask are computed
// (each by the tree walk's formula, an operand's partial outside its mask read as [+0, +0])
// and the rest are neither computed nor stored.

constexpr std::size_t kMaskBits = 64;

bool has(std::uint64_t mask, std::size_t j) {
  return j >= kMaskBits || ((mask >> j) & 1U) != 0;
}

// Calls visit(j) for each partial in `mask` below d.
template <typename Visit>
void for_each_partial(std::uint64_t mask, std::size_t d, Visit visit) {
  if (d > kMaskBits) {
    for (std::size_t j = 0; j < d; ++j)
      visit(j);
    return;
  }
  for (std::uint64_t m = d == kMaskBits ? mask : mask & ((std::uint64_t{1} << d) - 1); m != 0;
       m &= m - 1) {
    visit(static_cast<std::size_t>(std::countr_zero(m)));
  }
}

// An operand's gradient: its stored partials, and [+0, +0] outside its mask.
struct Partials {
  const Interval* stored;
  std::uint64_t mask;
  Interval operator[](std::size_t j) const { return has(mask, j) ? stored[j] : kZero; }
};

// g = du * factor, componentwise (the tree walk's `scaled`).
void scale(Partials du, Interval factor, Interval* g, std::uint64_t mask, std::size_t d) {
  for_each_partial(mask, d, [&](std::size_t j) { g[j] = du[j] * factor; });
}

// The gradient of min (is_min) or max: one operand's where their ranges do not overlap, the
// hull of both at a possible kink.
void extremum_gradient(bool is_min, Interval u, Interval v, Partials du, Partials dv, Interval* g,
                       std::uint64_t mask, std::size_t d) {
  const bool first = is_min ? u.hi <= v.lo : u.lo >= v.hi;
  const bool second = is_min ? v.hi <= u.lo : v.lo >= u.hi;
  for_each_partial(mask, d, [&](std::size_t j) {
    g[j] = first ? du[j] : second ? dv[j] : hull(du[j], dv[j]);
  });
}

// The product, quotient and sum rules, in the order of the tree walk's binary_gradient.
void binary_gradient(Op op, Interval u, Interval v, Interval value, Partials du, Partials dv,
                     Interval* g, std::uint64_t mask, std::size_t d) {
  switch (op) {
    case Op::Add:
      for_each_partial(mask, d, [&](std::size_t j) { g[j] = du[j] + dv[j]; });
      return;
    case Op::Subtract:
      for_each_partial(mask, d, [&](std::size_t j) { g[j] = du[j] + dv[j] * kMinusOne; });
      return;
    case Op::Multiply:
      for_each_partial(mask, d, [&](std::size_t j) { g[j] = du[j] * v + dv[j] * u; });
      return;
    case Op::Divide: {  // (u' - (u / v) v') / v
      const Interval minus_quotient = -value;
      const Interval reciprocal = rules::kOne / v;
      for_each_partial(
          mask, d, [&](std::size_t j) { g[j] = (du[j] + dv[j] * minus_quotient) * reciprocal; });
      return;
    }
    default:
      extremum_gradient(op == Op::Min, u, v, du, dv, g, mask, d);
  }
}

// (u^n)' = n u^(n-1) u', refused for the one n whose n - 1 does not exist.
void power_gradient(const Instruction& in, Interval u, Partials du, Interval* g,
                    const Tables& tables) {
  if (in.exponent == 0) {  // a zero gradient: its mask is empty unless the masks are dense
    for_each_partial(in.mask, tables.dimension, [&](std::size_t j) { g[j] = kZero; });
    return;
  }
  if (in.exponent == std::numeric_limits<std::int64_t>::min()) {
    throw EnclosureError(tables.locations[in.where], "the exponent is too large to differentiate");
  }
  scale(du, in.exponent_factor * power(u, in.exponent - 1), g, in.mask, tables.dimension);
}

// The gradient of code[slot] (the tree walk's `differentiate`), from the ranges in `values`
// and the operands' gradients, `dimension` intervals per slot in `gradients`.
void gradient_of(std::span<const Instruction> code, std::size_t slot,
                 std::span<const Interval> values, std::span<Interval> gradients,
                 const Tables& tables) {
  const Instruction& in = code[slot];
  const std::size_t d = tables.dimension;
  Interval* g = gradients.data() + slot * d;
  auto operand = [&](std::uint32_t k) { return Partials{gradients.data() + k * d, code[k].mask}; };
  switch (in.code) {
    case Code::kLoad: {
      const Interval* stored = tables.loaded_gradients.data() + in.a * d;
      for_each_partial(in.mask, d, [&](std::size_t j) { g[j] = stored[j]; });
      return;
    }
    case Code::kVariable:
      for_each_partial(in.mask, d, [&](std::size_t j) { g[j] = kZero; });
      g[in.a] = rules::kOne;
      return;
    case Code::kUnary:
      scale(operand(in.a), rules::unary_derivative(in.op, values[in.a], values[slot]), g, in.mask,
            d);
      return;
    case Code::kBinary:
      binary_gradient(in.op, values[in.a], values[in.b], values[slot], operand(in.a), operand(in.b),
                      g, in.mask, d);
      return;
    case Code::kPower:
      power_gradient(in, values[in.a], operand(in.a), g, tables);
      return;
    case Code::kFail:
      raise(tables.failures[in.a]);
  }
}

// Each instruction's mask, from its operands' (a load's from the partials it holds).
void set_masks(std::span<Instruction> code, std::span<const Interval> loaded_gradients,
               std::size_t d) {
  const bool dense = d > kMaskBits;
  for (Instruction& in : code) {
    std::uint64_t mask = 0;
    switch (in.code) {
      case Code::kLoad:
        for (std::size_t j = 0; j < std::min(d, kMaskBits); ++j) {
          const Interval partial = loaded_gradients[in.a * d + j];
          const bool zero = std::bit_cast<std::uint64_t>(partial.lo) == 0 &&
                            std::bit_cast<std::uint64_t>(partial.hi) == 0;  // +0, not -0
          if (!zero) mask |= std::uint64_t{1} << j;
        }
        break;
      case Code::kVariable:
        mask = std::uint64_t{1} << in.a;
        break;
      case Code::kUnary:
        mask = code[in.a].mask;
        break;
      case Code::kPower:
        mask = in.exponent == 0 ? 0 : code[in.a].mask;
        break;
      case Code::kBinary:
        mask = code[in.a].mask | code[in.b].mask;
        break;
      case Code::kFail:
        break;
    }
    in.mask = dense ? ~std::uint64_t{0} : mask;
  }
}

// Whether an instruction's value depends on the box: those that do not are bound once.
std::vector<bool> box_dependence(std::span<const Instruction> code) {
  std::vector<bool> depends(code.size(), false);
  for (std::size_t i = 0; i < code.size(); ++i) {
    const Instruction& in = code[i];
    if (in.code == Code::kVariable) depends[i] = true;
    if (in.code == Code::kUnary || in.code == Code::kPower) depends[i] = depends[in.a];
    if (in.code == Code::kBinary) depends[i] = depends[in.a] || depends[in.b];
  }
  return depends;
}

// An instruction: its code, op, operand slots and location.
Instruction instruction(Code code, Op op, std::uint32_t a, std::uint32_t b, std::uint32_t where) {
  Instruction in;
  in.code = code;
  in.op = op;
  in.a = a;
  in.b = b;
  in.where = where;
  return in;
}

}  // namespace

// Translates a component's tree into its full program (one instruction per node, post-order,
// a refusal where the tree walk would throw), then binds what does not depend on the box.
class ProgramBuilder {
 public:
  ProgramBuilder(EnclosureProgram& program, std::span<const Interval> inputs)
      : program_(program), inputs_(inputs) {}

  std::vector<Instruction> build(const Expression& component) {
    code_.clear();
    (void)translate(component);
    const std::vector<Instruction> full = std::move(code_);
    code_.clear();  // relinked() emits the bound program here
    std::vector<Instruction> code = bound(full);
    set_masks(code, program_.loaded_gradients_, program_.dimension_);
    return code;
  }

 private:
  Tables tables() const {
    return {program_.loaded_, program_.loaded_gradients_, program_.failures_, program_.locations_,
            program_.dimension_};
  }

  std::uint32_t emit(Instruction in) {
    code_.push_back(in);
    return static_cast<std::uint32_t>(code_.size() - 1);
  }

  std::uint32_t location(const SourceRange& where) {
    program_.locations_.push_back(where);
    return static_cast<std::uint32_t>(program_.locations_.size() - 1);
  }

  std::uint32_t fail(bool located, SourceRange where, std::string message) {
    program_.failures_.push_back({located, where, std::move(message)});
    const auto index = static_cast<std::uint32_t>(program_.failures_.size() - 1);
    return emit(instruction(Code::kFail, Op::Constant, index, 0, 0));
  }

  // A value fixed before any box is seen, with its gradient.
  std::uint32_t load(Interval value, std::span<const Interval> gradient) {
    program_.loaded_.push_back(value);
    program_.loaded_gradients_.insert(program_.loaded_gradients_.end(), gradient.begin(),
                                      gradient.end());
    const auto index = static_cast<std::uint32_t>(program_.loaded_.size() - 1);
    return emit(instruction(Code::kLoad, Op::Constant, index, 0, 0));
  }

  std::uint32_t load_leaf(Interval value) {
    const std::vector<Interval> zero(program_.dimension_, kZero);
    return load(value, zero);
  }

  // What the tree walk throws for a variable it has no range for (a bug of the caller).
  std::uint32_t fail_beyond(const Expression& f) {
    return fail(false, f.range,
                "a variable's slot " + std::to_string(f.slot) + " is beyond the ranges given");
  }

  // Variables read the box (or the inputs, fixed here); constants are converted once.
  std::uint32_t translate_leaf(const Expression& f) {
    if (f.op == Op::ContinuousVariable) {
      if (f.slot >= program_.dimension_) return fail_beyond(f);
      return emit(instruction(Code::kVariable, f.op, f.slot, 0, 0));
    }
    if (f.op == Op::InputVariable) {
      if (f.slot >= inputs_.size()) return fail_beyond(f);
      return load_leaf(inputs_[f.slot]);
    }
    try {
      return load_leaf(from_rational(f.constant));
    } catch (const IntervalError& error) {
      return fail(true, f.range, error.what());
    }
  }

  // Operand i, or the refusal of a tree that lacks it.
  std::uint32_t translate_operand(const Expression& f, std::size_t i) {
    const Expression* child = nullptr;
    try {
      child = &rules::operand(f, i);
    } catch (const std::invalid_argument& error) {
      return fail(false, f.range, error.what());
    }
    return translate(*child);
  }

  std::uint32_t translate_power(const Expression& f, std::uint32_t base) {
    std::int64_t n = 0;
    try {
      n = rules::exponent(f);
    } catch (const EnclosureError& error) {
      return fail(true, error.where, error.what());
    } catch (const std::invalid_argument& error) {
      return fail(false, f.range, error.what());
    }
    Instruction in = instruction(Code::kPower, f.op, base, 0, location(f.range));
    in.exponent = n;
    in.exponent_factor = from_rational(Rational(static_cast<long>(n)));
    return emit(in);
  }

  // The tree walk's order: the node's own check, operand 0, the exponent, operand 1, the node.
  std::uint32_t translate(const Expression& f) {
    if (!rules::is_allowed(f.op)) {
      return fail(true, f.range,
                  std::string(rules::disallowed_name(f.op)) + " is not allowed in dynamics");
    }
    if (rules::is_leaf(f.op)) return translate_leaf(f);
    const std::uint32_t x = translate_operand(f, 0);
    if (f.op == Op::Power) return translate_power(f, x);
    if (rules::is_unary(f.op))
      return emit(instruction(Code::kUnary, f.op, x, 0, location(f.range)));
    const std::uint32_t y = translate_operand(f, 1);
    return emit(instruction(Code::kBinary, f.op, x, y, location(f.range)));
  }

  // The program with every box-independent instruction evaluated (value and gradient) and
  // turned into a load where a box-dependent one reads it; `full` itself when one of them
  // fails, so that the failure happens at run time in the tree walk's order.
  std::vector<Instruction> bound(const std::vector<Instruction>& full) {
    const std::vector<bool> depends = box_dependence(full);
    const std::size_t d = program_.dimension_;
    std::vector<Interval> values(full.size());
    std::vector<Interval> gradients(full.size() * d);
    try {
      const Tables view = tables();
      for (std::size_t i = 0; i < full.size(); ++i) {
        if (depends[i]) continue;
        values[i] = value_of(full[i], values, {}, view);
        gradient_of(full, i, values, gradients, view);  // dense: masks are set afterwards
      }
    } catch (const std::exception&) {
      return full;
    }
    return relinked(full, depends, values, gradients);
  }

  std::vector<Instruction> relinked(const std::vector<Instruction>& full,
                                    const std::vector<bool>& depends,
                                    const std::vector<Interval>& values,
                                    const std::vector<Interval>& gradients) {
    const std::size_t d = program_.dimension_;
    constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> moved(full.size(), kNone);
    auto slot = [&](std::uint32_t old) {
      if (moved[old] == kNone) {
        moved[old] = load(values[old], std::span(gradients).subspan(old * d, d));
      }
      return moved[old];
    };
    for (std::size_t i = 0; i < full.size(); ++i) {
      if (!depends[i]) continue;
      Instruction in = full[i];
      if (in.code != Code::kVariable) in.a = slot(in.a);
      if (in.code == Code::kBinary) in.b = slot(in.b);
      moved[i] = emit(in);
    }
    (void)slot(static_cast<std::uint32_t>(full.size() - 1));  // the root, even when bound
    return code_;
  }

  EnclosureProgram& program_;
  std::span<const Interval> inputs_;
  std::vector<Instruction> code_;
};

EnclosureProgram::EnclosureProgram(std::span<const Expression> f, std::size_t dimension,
                                   std::span<const Interval> inputs)
    : dimension_(dimension) {
  check_box(inputs);
  ProgramBuilder builder(*this, inputs);
  for (const Expression& expression : f) {
    const std::vector<Instruction> code = builder.build(expression);
    components_.push_back({static_cast<std::uint32_t>(code_.size()),
                           static_cast<std::uint32_t>(code.size()), expression.range});
    code_.insert(code_.end(), code.begin(), code.end());
    largest_ = std::max(largest_, code.size());
  }
}

std::span<const Instruction> EnclosureProgram::code_of(std::size_t component) const {
  const Component& c = components_.at(component);
  return std::span(code_).subspan(c.first, c.size);
}

// The box checked, the scratch grown to this program (allocating only the first time), and
// the box's midpoint, as enclose_mean_value takes it.
void EnclosureProgram::prepare(std::span<const Interval> box, EnclosureScratch& scratch) const {
  if (box.size() != dimension_) {
    throw std::invalid_argument("an enclosure program for " + std::to_string(dimension_) +
                                " variables was given a box of " + std::to_string(box.size()));
  }
  check_box(box);
  if (scratch.values.size() < largest_) {
    scratch.values.resize(largest_);
    scratch.centre_values.resize(largest_);
  }
  if (scratch.gradients.size() < largest_ * dimension_)
    scratch.gradients.resize(largest_ * dimension_);
  scratch.centre.resize(dimension_);
  for (std::size_t j = 0; j < dimension_; ++j)
    scratch.centre[j] = Interval::point(box[j].midpoint());
}

// Each instruction's range; an interval error is placed at the instruction's node.
void EnclosureProgram::run_values(std::span<const Instruction> code, std::span<const Interval> box,
                                  std::span<Interval> values) const {
  const Tables view{loaded_, loaded_gradients_, failures_, locations_, dimension_};
  std::size_t i = 0;
  try {
    for (; i < code.size(); ++i)
      values[i] = value_of(code[i], values, box, view);
  } catch (const IntervalError& error) {
    throw EnclosureError(locations_[code[i].where], error.what());
  }
}

// Each instruction's gradient, the ranges being known.
void EnclosureProgram::run_gradients(std::span<const Instruction> code,
                                     std::span<const Interval> values,
                                     std::span<Interval> gradients) const {
  const Tables view{loaded_, loaded_gradients_, failures_, locations_, dimension_};
  std::size_t i = 0;
  try {
    for (; i < code.size(); ++i)
      gradient_of(code, i, values, gradients, view);
  } catch (const IntervalError& error) {
    throw EnclosureError(locations_[code[i].where], error.what());
  }
}

// Range and gradient instruction by instruction, so that the first failure is the one the tree
// walk's `differentiate` meets.
void EnclosureProgram::run_dual(std::span<const Instruction> code, std::span<const Interval> box,
                                std::span<Interval> values, std::span<Interval> gradients) const {
  const Tables view{loaded_, loaded_gradients_, failures_, locations_, dimension_};
  std::size_t i = 0;
  try {
    for (; i < code.size(); ++i) {
      values[i] = value_of(code[i], values, box, view);
      gradient_of(code, i, values, gradients, view);
    }
  } catch (const IntervalError& error) {
    throw EnclosureError(locations_[code[i].where], error.what());
  }
}

// f(c) + sum_j df/dx_j(box) * (box_j - c_j), its errors placed at the component.
Interval EnclosureProgram::mean_value_sum(const Component& component,
                                          std::span<const Instruction> code, Interval at_centre,
                                          std::span<const Interval> gradients,
                                          std::span<const Interval> box,
                                          std::span<const Interval> centre) const {
  const std::size_t root = code.size() - 1;
  const Partials gradient{gradients.data() + root * dimension_, code[root].mask};
  try {
    Interval range = at_centre;
    for (std::size_t j = 0; j < dimension_; ++j)  // every partial, zero or not, as the tree walk
      range = range + gradient[j] * (box[j] - centre[j]);
    return range;
  } catch (const IntervalError& error) {
    throw EnclosureError(component.where, error.what());
  }
}

Interval EnclosureProgram::natural(std::size_t component, std::span<const Interval> box,
                                   EnclosureScratch& scratch) const {
  const std::span<const Instruction> code = code_of(component);
  prepare(box, scratch);
  run_values(code, box, scratch.values);
  return scratch.values[code.size() - 1];
}

Interval EnclosureProgram::mean_value(std::size_t component, std::span<const Interval> box,
                                      EnclosureScratch& scratch) const {
  const std::span<const Instruction> code = code_of(component);
  prepare(box, scratch);
  run_values(code, scratch.centre, scratch.centre_values);
  run_dual(code, box, scratch.values, scratch.gradients);
  const std::size_t root = code.size() - 1;
  return mean_value_sum(components_[component], code, scratch.centre_values[root],
                        scratch.gradients, box, scratch.centre);
}

// Per component, as enclose_map: the natural range (its errors propagate), then the
// mean-value form, whose errors leave the natural range alone. The ranges over the box serve
// both forms: the tree walk computes them twice, with the same result.
void EnclosureProgram::enclose(std::span<const Interval> box, EnclosureScratch& scratch,
                               std::span<Interval> out) const {
  if (out.size() != components_.size())
    throw std::invalid_argument("an enclosure's output needs one interval per component");
  prepare(box, scratch);
  for (std::size_t c = 0; c < components_.size(); ++c) {
    const std::span<const Instruction> code = code_of(c);
    const std::size_t root = code.size() - 1;
    run_values(code, box, scratch.values);
    const Interval natural_range = scratch.values[root];
    Interval mean_value_range;
    try {
      run_values(code, scratch.centre, scratch.centre_values);
      run_gradients(code, scratch.values, scratch.gradients);
      mean_value_range = mean_value_sum(components_[c], code, scratch.centre_values[root],
                                        scratch.gradients, box, scratch.centre);
    } catch (const EnclosureError&) {
      out[c] = natural_range;
      continue;
    }
    const std::optional<Interval> common = intersection(natural_range, mean_value_range);
    if (!common) {
      throw std::logic_error("the natural and the mean-value enclosures " +
                             to_string(natural_range) + " and " + to_string(mean_value_range) +
                             " are disjoint: one of them is unsound");
    }
    out[c] = *common;
  }
}

}  // namespace oasis::model
