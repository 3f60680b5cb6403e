// oasis/rt/catalog_validation.hpp: validate(), the check of every invariant that
// catalog_view.hpp states, for a catalog read from a file or a network (a generated table is
// trusted). It is kept apart from the view types so that a program that only reads a trusted
// catalog includes just the schema.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>

#include "oasis/rt/catalog_view.hpp"

namespace oasis::rt {

namespace detail {

inline bool fail(std::string* why, const std::string& message) {
  if (why != nullptr) *why = message;
  return false;
}

inline bool is_probability(double p) noexcept {
  return std::isfinite(p) && p >= 0.0 && p <= 1.0;
}

inline bool sums_to_one(double sum) noexcept {
  return std::isfinite(sum) && std::fabs(sum - 1.0) <= kProbabilityTolerance;
}

/// Checks a CSR relation with `sources` sources and `destinations` destinations.
inline bool validate_csr(const TransitionsCsr& csr, std::uint32_t sources,
                         std::uint32_t num_actions, std::uint32_t destinations,
                         const std::string& where, std::string* why) {
  if (csr.choice_begin == nullptr) return fail(why, where + ": choice_begin is null");
  if (csr.num_edges > 0 && (csr.target == nullptr || csr.probability == nullptr))
    return fail(why, where + ": target or probability is null");
  const std::size_t rows = static_cast<std::size_t>(sources) * num_actions;
  if (csr.choice_begin[0] != 0) return fail(why, where + ": choice_begin[0] != 0");
  for (std::size_t row = 0; row < rows; ++row) {
    const std::uint32_t begin = csr.choice_begin[row];
    const std::uint32_t end = csr.choice_begin[row + 1];
    if (end < begin || end > csr.num_edges)
      return fail(why, where + ": choice_begin not non-decreasing or past num_edges at row " +
                           std::to_string(row));
    double sum = 0.0;
    for (std::uint32_t e = begin; e < end; ++e) {
      if (csr.target[e] >= destinations)
        return fail(why, where + ": target out of range at edge " + std::to_string(e));
      const double p = csr.probability[e];
      if (!is_probability(p) || p == 0.0)
        return fail(why, where + ": probability not in (0, 1] at edge " + std::to_string(e));
      sum += p;
    }
    if (end > begin && !sums_to_one(sum))
      return fail(why, where + ": row " + std::to_string(row) + " sums to " + std::to_string(sum) +
                           ", not 1");
  }
  if (csr.choice_begin[rows] != csr.num_edges)
    return fail(why, where + ": choice_begin[last] != num_edges");
  return true;
}

inline bool csr_is_empty(const TransitionsCsr& csr) noexcept {
  return csr.choice_begin == nullptr && csr.target == nullptr && csr.probability == nullptr &&
         csr.num_edges == 0;
}

}  // namespace detail

namespace detail {

inline bool validate_names(const CatalogView& catalog, std::string* why) {
  if (catalog.format != kCatalogFormat)
    return fail(why, "format " + std::to_string(catalog.format) + " is not " +
                         std::to_string(kCatalogFormat));
  if (catalog.name == nullptr) return fail(why, "name is null");
  if (catalog.compiler_version == nullptr) return fail(why, "compiler_version is null");
  if (catalog.is_continuous()) {
    if (catalog.num_states != 0 || catalog.state_names != nullptr)
      return fail(why, "a continuous catalog has explicit states");
    if (catalog.has_robust_section()) return fail(why, "a continuous catalog has a robust section");
  } else if (catalog.num_states == 0) {
    return fail(why, "num_states is 0");
  }
  if (catalog.num_actions == 0) return fail(why, "num_actions is 0");
  if (catalog.num_abstractions == 0) return fail(why, "num_abstractions is 0");
  if (catalog.action_names == nullptr) return fail(why, "action_names is null");
  for (std::uint32_t a = 0; a < catalog.num_actions; ++a)
    if (catalog.action_names[a] == nullptr)
      return fail(why, "action name " + std::to_string(a) + " is null");
  if (catalog.state_names != nullptr)
    for (std::uint32_t s = 0; s < catalog.num_states; ++s)
      if (catalog.state_names[s] == nullptr)
        return fail(why, "state name " + std::to_string(s) + " is null");
  if (catalog.variable_names != nullptr)
    for (std::uint32_t v = 0; v < catalog.state_dimension; ++v)
      if (catalog.variable_names[v] == nullptr)
        return fail(why, "variable name " + std::to_string(v) + " is null");
  return true;
}

inline bool validate_switching(const CatalogView& catalog, std::string* why) {
  const std::uint32_t n = catalog.num_abstractions;
  if (catalog.switching == nullptr) return fail(why, "switching is null");
  for (std::uint32_t i = 0; i < n; ++i) {
    double sum = 0.0;
    for (std::uint32_t j = 0; j < n; ++j) {
      const double p = catalog.switching[static_cast<std::size_t>(i) * n + j];
      if (!is_probability(p))
        return fail(why, "switching[" + std::to_string(i) + "][" + std::to_string(j) +
                             "] not a probability");
      sum += p;
    }
    if (!sums_to_one(sum))
      return fail(why, "switching row " + std::to_string(i) + " does not sum to 1");
  }
  if (catalog.prior == nullptr) return fail(why, "prior is null");
  double prior_sum = 0.0;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (!is_probability(catalog.prior[i]))
      return fail(why, "prior[" + std::to_string(i) + "] not a probability");
    prior_sum += catalog.prior[i];
  }
  if (!sums_to_one(prior_sum)) return fail(why, "prior does not sum to 1");
  return true;
}

inline bool validate_observation(const CatalogView& catalog, std::string* why) {
  const ObservationModel& obs = catalog.observation;
  const std::uint32_t num_states = catalog.num_states;
  switch (obs.kind) {
    case ObservationKind::kNone:
      if (obs.confusion != nullptr) return fail(why, "confusion given without kMatrix");
      return true;
    case ObservationKind::kSymmetric:
      if (obs.confusion != nullptr) return fail(why, "confusion given without kMatrix");
      if (!is_probability(obs.p_correct)) return fail(why, "p_correct not in [0, 1]");
      if (num_states == 1 && obs.p_correct != 1.0)
        return fail(why, "p_correct must be 1 with a single state");
      return true;
    case ObservationKind::kMatrix:
      if (obs.confusion == nullptr) return fail(why, "kMatrix without confusion matrix");
      for (std::uint32_t s = 0; s < num_states; ++s) {
        double sum = 0.0;
        for (std::uint32_t o = 0; o < num_states; ++o) {
          const double p = obs.confusion[static_cast<std::size_t>(s) * num_states + o];
          if (!is_probability(p))
            return fail(why, "confusion[" + std::to_string(s) + "][" + std::to_string(o) +
                                 "] not a probability");
          sum += p;
        }
        if (!sums_to_one(sum))
          return fail(why, "confusion row " + std::to_string(s) + " does not sum to 1");
      }
      return true;
  }
  return fail(why, "unknown observation kind");
}

inline bool validate_position_noise(const CatalogView& catalog, std::string* why) {
  const PositionNoise& noise = catalog.observation.position;
  if (noise.num_objects == 0) {
    if (noise.object_of != nullptr || noise.sigma != nullptr || noise.detection != nullptr)
      return fail(why, "position noise arrays given without objects");
    return true;
  }
  if (!catalog.is_continuous()) return fail(why, "position noise in a discrete catalog");
  if (noise.object_of == nullptr || noise.sigma == nullptr || noise.detection == nullptr)
    return fail(why, "position noise: a required array is null");
  for (std::uint32_t v = 0; v < catalog.state_dimension; ++v)
    if (noise.object_of[v] != kExactVariable && noise.object_of[v] >= noise.num_objects)
      return fail(why, "position noise: object_of[" + std::to_string(v) + "] out of range");
  for (std::uint32_t k = 0; k < noise.num_objects; ++k) {
    const std::string where = "position noise: object " + std::to_string(k);
    const double* c = noise.sigma + static_cast<std::size_t>(k) * 3;
    if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2]) || c[0] < 0.0)
      return fail(why, where + ": sigma(d) coefficients not finite with a >= 0");
    if (!(noise.detection[k] > 0.0 && noise.detection[k] <= 1.0))
      return fail(why, where + ": detection probability not in (0, 1]");
  }
  return true;
}

// block_of in range and every block holding a state, counted with a byte map (a std::string,
// the only allocation validate() makes besides the message). O(num_states).
inline bool validate_blocks(const AbstractionView& abs, std::uint32_t num_states,
                            const std::string& where, std::string* why) {
  for (std::uint32_t s = 0; s < num_states; ++s)
    if (abs.block_of[s] >= abs.num_blocks)
      return fail(why, where + ": block_of[" + std::to_string(s) + "] out of range");
  std::uint32_t first_occurrences = 0;
  std::string seen(abs.num_blocks, '\0');
  for (std::uint32_t s = 0; s < num_states; ++s) {
    char& mark = seen[abs.block_of[s]];
    if (mark == '\0') {
      mark = '\1';
      ++first_occurrences;
    }
  }
  if (first_occurrences != abs.num_blocks) return fail(why, where + ": a block holds no state");
  return true;
}

inline bool validate_numbers(const AbstractionView& abs, std::uint32_t num_actions,
                             const std::string& where, std::string* why) {
  for (std::uint32_t z = 0; z < abs.num_blocks; ++z) {
    if (!std::isfinite(abs.block_reward[z]))
      return fail(why, where + ": block_reward[" + std::to_string(z) + "] not finite");
    if (!std::isfinite(abs.value[z]))
      return fail(why, where + ": value[" + std::to_string(z) + "] not finite");
    for (std::uint32_t a = 0; a < num_actions; ++a)
      if (!std::isfinite(abs.reward[static_cast<std::size_t>(z) * num_actions + a]))
        return fail(why, where + ": reward[" + std::to_string(z) + "][" + std::to_string(a) +
                             "] not finite");
  }
  return true;
}

// Every policy entry names an action; with the quotient present, an enabled one (and
// kNoAction exactly where none is enabled).
inline bool validate_policy(const AbstractionView& abs, std::uint32_t num_actions,
                            const std::string& where, std::string* why) {
  const bool has_quotient = !csr_is_empty(abs.quotient);
  for (std::uint32_t z = 0; z < abs.num_blocks; ++z) {
    const std::uint32_t action = abs.policy[z];
    if (!has_quotient) {
      if (action != kNoAction && action >= num_actions)
        return fail(why, where + ": policy[" + std::to_string(z) + "] not an action");
      continue;
    }
    const std::size_t row0 = static_cast<std::size_t>(z) * num_actions;
    const std::uint32_t* begin = abs.quotient.choice_begin;
    bool any_enabled = false;
    for (std::uint32_t a = 0; a < num_actions; ++a)
      any_enabled = any_enabled || begin[row0 + a + 1] > begin[row0 + a];
    if (action == kNoAction) {
      if (any_enabled)
        return fail(why, where + ": policy[" + std::to_string(z) +
                             "] is kNoAction but an action is enabled");
    } else if (action >= num_actions || begin[row0 + action + 1] == begin[row0 + action]) {
      return fail(why, where + ": policy[" + std::to_string(z) + "] not an enabled action");
    }
  }
  return true;
}

// A continuous abstraction: a valid grid (and BSP) over the state vector, every cell's block in
// range, every block holding a cell or being the outside block.
inline bool validate_cells(const CatalogView& catalog, const AbstractionView& abs,
                           const std::string& where, std::string* why) {
  if (abs.block_of != nullptr) return fail(why, where + ": block_of in a continuous catalog");
  if (!validate_grid(abs.grid, catalog.state_dimension))
    return fail(why, where + ": malformed grid");
  if (abs.cell_block == nullptr) return fail(why, where + ": cell_block is null");
  if (abs.outside_block >= abs.num_blocks) return fail(why, where + ": outside_block out of range");
  if (!std::isfinite(abs.epsilon) || abs.epsilon < 0)
    return fail(why, where + ": epsilon not a finite bound");
  const std::uint64_t cells = partition_cells(abs);
  if (abs.bsp.num_nodes != 0) {
    std::string scratch(abs.bsp.num_cells, '\0');
    if (grid_cells(abs.grid) != 1 ||
        !validate_bsp(abs.bsp, abs.grid.dimension,
                      reinterpret_cast<unsigned char*>(scratch.data())))
      return fail(why, where + ": malformed BSP");
  }
  if (abs.num_blocks > cells + 1) return fail(why, where + ": more blocks than cells");
  std::string seen(abs.num_blocks, '\0');
  seen[abs.outside_block] = '\1';
  for (std::uint64_t c = 0; c < cells; ++c) {
    if (abs.cell_block[c] >= abs.num_blocks)
      return fail(why, where + ": cell_block[" + std::to_string(c) + "] out of range");
    seen[abs.cell_block[c]] = '\1';
  }
  if (seen.find('\0') != std::string::npos) return fail(why, where + ": a block holds no cell");
  return true;
}

// The stated properties: named, and per abstraction an interval per value, lower <= upper
// (+infinity for a reward that is infinite; a probability's interval lies in [0, 1], but the
// view does not say which property is which, so the compiler's checks, not these, hold that).
inline bool validate_properties(const CatalogView& catalog, std::string* why) {
  const PropertyStatements& properties = catalog.properties;
  if (properties.count == 0) {
    for (std::uint32_t i = 0; i < catalog.num_abstractions; ++i)
      if (catalog.abstractions[i].guarantee != nullptr)
        return fail(why, "abstraction " + std::to_string(i) + ": guarantees without properties");
    return true;
  }
  if (properties.names == nullptr || properties.texts == nullptr)
    return fail(why, "property names or texts are null");
  for (std::uint32_t k = 0; k < properties.count; ++k)
    if (properties.names[k] == nullptr || properties.texts[k] == nullptr)
      return fail(why, "property " + std::to_string(k) + ": name or text is null");
  for (std::uint32_t i = 0; i < catalog.num_abstractions; ++i) {
    const double* guarantee = catalog.abstractions[i].guarantee;
    const std::string where = "abstraction " + std::to_string(i);
    if (guarantee == nullptr) return fail(why, where + ": the stated properties have no values");
    for (std::uint32_t k = 0; k < properties.count * kGuaranteeFields; k += 2) {
      const double lower = guarantee[k];
      const double upper = guarantee[k + 1];
      // +infinity both ways is an expected reward that is infinite; nothing is -infinity.
      if (std::isnan(lower) || std::isnan(upper) || !(lower <= upper) || upper == -HUGE_VAL)
        return fail(why, where + ": the value of property " + std::to_string(k / kGuaranteeFields) +
                             " is not an interval");
    }
  }
  return true;
}

inline bool validate_abstraction(const CatalogView& catalog, std::uint32_t i, std::string* why) {
  const AbstractionView& abs = catalog.abstractions[i];
  const std::string where = "abstraction " + std::to_string(i);
  if (abs.context == nullptr) return fail(why, where + ": context is null");
  if (abs.num_blocks == 0) return fail(why, where + ": num_blocks is 0");
  if (abs.block_reward == nullptr || abs.reward == nullptr || abs.policy == nullptr ||
      abs.value == nullptr)
    return fail(why, where + ": a required array is null");
  if (catalog.is_continuous()) {
    if (!validate_cells(catalog, abs, where, why)) return false;
  } else {
    if (abs.num_blocks > catalog.num_states) return fail(why, where + ": more blocks than states");
    if (abs.block_of == nullptr) return fail(why, where + ": a required array is null");
    if (!validate_blocks(abs, catalog.num_states, where, why)) return false;
    if (abs.grid.dimension != 0 || abs.cell_block != nullptr || abs.bsp.num_nodes != 0)
      return fail(why, where + ": a grid in a discrete catalog");
  }
  if (!validate_numbers(abs, catalog.num_actions, where, why)) return false;
  if (!csr_is_empty(abs.quotient) &&
      !validate_csr(abs.quotient, abs.num_blocks, catalog.num_actions, abs.num_blocks,
                    where + " quotient", why))
    return false;
  if (!validate_policy(abs, catalog.num_actions, where, why)) return false;
  if (catalog.has_robust_section())
    return validate_csr(abs.state_transitions, catalog.num_states, catalog.num_actions,
                        catalog.num_states, where + " state_transitions", why);
  if (!csr_is_empty(abs.state_transitions))
    return fail(why, where + ": state_transitions given without an observation model");
  return true;
}

}  // namespace detail

/// Checks every invariant stated in this header.
///
/// Requires: every non-null pointer in `catalog` points to an array of at least the length
/// that the counts in `catalog` give for it (for a CSR: choice_begin R*A+1, target and
/// probability num_edges). A loader guarantees this by sizing its buffers from the counts it
/// read; validate() then guarantees the rest.
/// Guarantees: returns true iff all invariants hold (sizes at least 1, pointers non-null where
/// required, every index in range, every block non-empty, every probability finite in [0, 1],
/// every distribution summing to 1, every reward and value finite, every policy entry an
/// action (an enabled one when the quotient's transitions are present: they are optional,
/// an analysis product), robust section complete or absent). On false, and if `why` is not
/// null, stores a one-line reason naming the first violated invariant. Never reads past the
/// stated lengths. Allocates only the message and a num_blocks-byte map per abstraction, so
/// call it at load time, not in a control loop. O(size of the catalog).
inline bool validate(const CatalogView& catalog, std::string* why = nullptr) {
  if (!detail::validate_names(catalog, why) || !detail::validate_switching(catalog, why) ||
      !detail::validate_observation(catalog, why) || !detail::validate_position_noise(catalog, why))
    return false;
  if (catalog.abstractions == nullptr) return detail::fail(why, "abstractions is null");
  for (std::uint32_t i = 0; i < catalog.num_abstractions; ++i)
    if (!detail::validate_abstraction(catalog, i, why)) return false;
  if (!detail::validate_properties(catalog, why)) return false;
  if (why != nullptr) why->clear();
  return true;
}

}  // namespace oasis::rt
