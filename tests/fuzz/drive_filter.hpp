#pragma once
// Driving a catalog a fuzz target accepted: the attention filter must construct, stay ok()
// and pick abstractions and actions in range for a few steps whose states, rewards and
// actions come from the input's bytes (now and then one past the end of the valid range).
// Shared by the targets whose inputs become catalogs (catalog_loader, continuous_json).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "fuzz_target.hpp"
#include "oasis/rt/attention_filter.hpp"
#include "oasis/rt/catalog_view.hpp"

namespace oasis::fuzz {

// A source of small numbers for the steps: the input's bytes from the start, cycled.
class FuzzSteps {
 public:
  FuzzSteps(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint32_t next() { return size_ == 0 ? 0 : data_[at_++ % size_]; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t at_ = 0;
};

inline void drive_filter(const rt::CatalogView& catalog, rt::FilterMode mode, FuzzSteps steps) {
  rt::FilterOptions options;
  options.mode = mode;
  std::vector<double> workspace(rt::AttentionFilter::workspace_size(catalog, options));
  rt::AttentionFilter filter(catalog, options, workspace.data(), workspace.size());
  FUZZ_REQUIRE(filter.ok());
  std::vector<double> state(catalog.state_dimension + 1);
  const auto fill_state = [&] {
    for (double& x : state)
      x = static_cast<double>(steps.next()) / 16.0 - 4.0;
  };
  if (catalog.is_continuous()) {
    fill_state();
    filter.start(state.data(), state.size());
  } else {
    filter.start(steps.next() % (catalog.num_states + 1));
  }
  for (int t = 0; t < 8; ++t) {
    const double reward = static_cast<double>(steps.next()) / 4.0 - 8.0;
    const std::uint32_t action = steps.next() % (catalog.num_actions + 1);
    if (catalog.is_continuous()) {
      fill_state();
      filter.step(state.data(), state.size(), reward, action);
    } else {
      filter.step(steps.next() % (catalog.num_states + 1), reward, action);
    }
    FUZZ_REQUIRE(filter.ok());
    FUZZ_REQUIRE(filter.ml_abstraction() < catalog.num_abstractions);
    const std::uint32_t chosen = filter.action();
    FUZZ_REQUIRE(chosen < catalog.num_actions || chosen == rt::kNoAction);
  }
}

}  // namespace oasis::fuzz
