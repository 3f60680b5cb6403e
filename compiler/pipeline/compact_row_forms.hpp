#pragma once
// The two forms of compact rows behind the one interface the proof and the solver read
// (pipeline/product_form.hpp, CompactRows): the grid path's product rows
// (geom/grid_product_rows.hpp) and the polytope path's tree walks
// (geom/polytope_walk_rows.hpp).

#include <string>
#include <vector>

#include "geom/grid_product_rows.hpp"
#include "geom/polytope_walk_rows.hpp"
#include "pipeline/product_form.hpp"

namespace oasis::pipeline {

// The exact rows of each form as a finite MDP.
model::ExplicitModel materialise(const geom::ProductRows& rows, const std::string& name,
                                 const std::vector<std::string>& actions,
                                 const model::Objective& objective);
model::ExplicitModel materialise(const geom::PolytopeWalkRows& rows, const std::string& name,
                                 const std::vector<std::string>& actions,
                                 const model::Objective& objective);

template <class Rows>
class CompactRowsOf final : public CompactRows {
 public:
  explicit CompactRowsOf(const Rows& rows) : rows_(rows) {}
  [[nodiscard]] std::uint32_t num_states() const override { return rows_.num_states(); }
  [[nodiscard]] std::uint32_t num_actions() const override { return rows_.num_actions(); }
  [[nodiscard]] ValueId state_reward(std::uint32_t s) const override {
    return rows_.state_reward(s);
  }
  [[nodiscard]] const RationalPool& values() const override { return rows_.values(); }
  void prepare(const double* x) const override {
    if constexpr (requires { rows_.prepare(x); }) rows_.prepare(x);
  }
  [[nodiscard]] double expectation(std::uint32_t s, std::uint32_t a,
                                   const double* x) const override {
    return rows_.expectation(s, a, x);
  }
  [[nodiscard]] std::uint32_t rounding_depth() const override { return rows_.rounding_depth(); }
  [[nodiscard]] double smallest_term() const override { return rows_.smallest_term(); }
  [[nodiscard]] model::ExplicitModel materialise(const std::string& name,
                                                 const std::vector<std::string>& actions,
                                                 const model::Objective& objective) const override {
    return pipeline::materialise(rows_, name, actions, objective);
  }

 private:
  const Rows& rows_;
};

}  // namespace oasis::pipeline
