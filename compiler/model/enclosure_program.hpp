#pragma once
// A compiled form of the enclosures of model/enclosure.hpp, for the abstraction, which encloses
// the same map over every cell of a grid and every input (guarantee/interval_mdp.cpp). The
// tree-walking functions there are the reference: this form gives bit-identical enclosures and
// the same errors (same type, message and location), only faster:
//  * each component is translated once into a flat program, one instruction per node in the
//    order the tree walk evaluates them, each writing its own slot;
//  * constants are converted to outward-rounded intervals once, and the inputs are bound when
//    the program is built: every sub-expression that depends on no continuous variable
//    (tan(u1), atan(tan(u1) / 2), ...) is evaluated then, with its gradient, and becomes a load
//    (when such a sub-expression fails for these inputs, the component keeps its full program,
//    so the failure shows where and when the tree walk meets it);
//  * evaluation writes into an EnclosureScratch that the caller keeps across calls: nothing is
//    allocated once it has grown to the largest program.
// The results are identical because every instruction runs the interval operations of
// model/enclosure_rules.hpp on the same operands in the same order as the tree walk, and a
// bound sub-expression's value and gradient do not depend on the box.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "model/expression.hpp"
#include "model/interval.hpp"
#include "support/diagnostics.hpp"

namespace oasis::model {

// What one evaluating thread reuses from call to call.
struct EnclosureScratch {
  std::vector<Interval> values;         // per slot, its range over the box
  std::vector<Interval> centre_values;  // per slot, its range at the box's midpoint
  std::vector<Interval> gradients;      // per slot, `dimension` partial derivatives
  std::vector<Interval> centre;         // the box's midpoint, as point intervals
};

class EnclosureProgram {
 public:
  // The components of f over boxes of `dimension` continuous variables, with the inputs fixed
  // (std::invalid_argument when an input is not a finite, non-empty interval).
  EnclosureProgram(std::span<const Expression> f, std::size_t dimension,
                   std::span<const Interval> inputs);

  [[nodiscard]] std::size_t components() const { return components_.size(); }
  [[nodiscard]] std::size_t dimension() const { return dimension_; }
  // How many instructions a component runs per evaluation, bound sub-expressions loaded.
  [[nodiscard]] std::size_t instructions(std::size_t component) const {
    return components_.at(component).size;
  }

  // As enclose_natural, enclose_mean_value and enclose_map with this program's inputs; the box
  // must have `dimension` sides (std::invalid_argument otherwise).
  [[nodiscard]] Interval natural(std::size_t component, std::span<const Interval> box,
                                 EnclosureScratch& scratch) const;
  [[nodiscard]] Interval mean_value(std::size_t component, std::span<const Interval> box,
                                    EnclosureScratch& scratch) const;
  // `out` holds one interval per component.
  void enclose(std::span<const Interval> box, EnclosureScratch& scratch,
               std::span<Interval> out) const;

  // What an instruction does (public for the translation in enclosure_program.cpp).
  enum class Code : std::uint8_t {
    kLoad,      // loaded_[a], and its gradient
    kVariable,  // the box's side a
    kUnary,     // op over slot a
    kBinary,    // op over slots a and b
    kPower,     // slot a to the power `exponent`
    kFail,      // throws failures_[a]: what the tree walk throws at this point
  };
  struct Instruction {
    Code code = Code::kLoad;
    Op op = Op::Constant;
    std::uint32_t a = 0;
    std::uint32_t b = 0;
    std::uint32_t where = 0;  // index into locations_: where an interval error is placed
    std::int64_t exponent = 0;
    Interval exponent_factor;  // the exponent as an interval: the power rule's factor
    // Bit j: d/dx_j may be nonzero (the others are exactly [+0, +0] and not computed); every
    // bit until the program is complete, and when there are more than 64 variables.
    std::uint64_t mask = ~std::uint64_t{0};
  };
  // A refusal found while translating: an EnclosureError at `where`, or a malformed tree
  // (std::invalid_argument).
  struct Failure {
    bool located = true;
    SourceRange where;
    std::string message;
  };
  struct Component {
    std::uint32_t first = 0;  // its instructions are code_[first, first + size)
    std::uint32_t size = 0;
    SourceRange where;  // the component's expression: where the mean-value sum's errors go
  };

 private:
  friend class ProgramBuilder;

  [[nodiscard]] std::span<const Instruction> code_of(std::size_t component) const;
  void prepare(std::span<const Interval> box, EnclosureScratch& scratch) const;
  void run_values(std::span<const Instruction> code, std::span<const Interval> box,
                  std::span<Interval> values) const;
  void run_gradients(std::span<const Instruction> code, std::span<const Interval> values,
                     std::span<Interval> gradients) const;
  void run_dual(std::span<const Instruction> code, std::span<const Interval> box,
                std::span<Interval> values, std::span<Interval> gradients) const;
  [[nodiscard]] Interval mean_value_sum(const Component& component,
                                        std::span<const Instruction> code, Interval at_centre,
                                        std::span<const Interval> gradients,
                                        std::span<const Interval> box,
                                        std::span<const Interval> centre) const;

  std::size_t dimension_ = 0;
  std::size_t largest_ = 0;  // the most instructions of a component: the scratch's size
  std::vector<Instruction> code_;
  std::vector<Interval> loaded_;
  std::vector<Interval> loaded_gradients_;  // dimension_ per entry of loaded_
  std::vector<Failure> failures_;
  std::vector<SourceRange> locations_;
  std::vector<Component> components_;
};

}  // namespace oasis::model
