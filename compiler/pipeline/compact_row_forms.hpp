#pragma once
// The two forms of compact rows (pipeline/product_form.hpp, CompactRows): the grid path's
// product rows and the polytope path's tree walks, each behind the one interface the proof
// and the solver read.

#include <string>
#include <vector>

#include "geom/grid_product_rows.hpp"
#include "geom/polytope_walk_rows.hpp"
#include "pipeline/product_form.hpp"

namespace oasis::pipeline {

class GridCompactRows final : public CompactRows {
 public:
  explicit GridCompactRows(const geom::ProductRows& rows) : rows_(rows) {}
  [[nodiscard]] std::uint32_t num_states() const override { return rows_.num_states(); }
  [[nodiscard]] std::uint32_t num_actions() const override { return rows_.num_actions(); }
  [[nodiscard]] ValueId state_reward(std::uint32_t s) const override {
    return rows_.state_reward(s);
  }
  [[nodiscard]] const RationalPool& values() const override { return rows_.values(); }
  [[nodiscard]] double expectation(std::uint32_t s, std::uint32_t a,
                                   const double* x) const override {
    return rows_.expectation(s, a, x);
  }
  [[nodiscard]] std::uint32_t rounding_depth() const override { return rows_.rounding_depth(); }
  [[nodiscard]] double smallest_term() const override { return rows_.smallest_term(); }
  [[nodiscard]] model::ExplicitModel materialise(const std::string& name,
                                                 const std::vector<std::string>& actions,
                                                 const model::Objective& objective) const override;

 private:
  const geom::ProductRows& rows_;
};

class PolytopeCompactRows final : public CompactRows {
 public:
  explicit PolytopeCompactRows(const geom::PolytopeWalkRows& rows) : rows_(rows) {}
  [[nodiscard]] std::uint32_t num_states() const override { return rows_.num_states(); }
  [[nodiscard]] std::uint32_t num_actions() const override { return rows_.num_actions(); }
  [[nodiscard]] ValueId state_reward(std::uint32_t s) const override {
    return rows_.state_reward(s);
  }
  [[nodiscard]] const RationalPool& values() const override { return rows_.values(); }
  void prepare(const double* x) const override { rows_.prepare(x); }
  [[nodiscard]] double expectation(std::uint32_t s, std::uint32_t a,
                                   const double* x) const override {
    return rows_.expectation(s, a, x);
  }
  [[nodiscard]] std::uint32_t rounding_depth() const override { return rows_.rounding_depth(); }
  [[nodiscard]] double smallest_term() const override { return rows_.smallest_term(); }
  [[nodiscard]] model::ExplicitModel materialise(const std::string& name,
                                                 const std::vector<std::string>& actions,
                                                 const model::Objective& objective) const override {
    return rows_.materialise(name, actions, objective);
  }

 private:
  const geom::PolytopeWalkRows& rows_;
};

}  // namespace oasis::pipeline
