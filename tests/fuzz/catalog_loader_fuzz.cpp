// The binary catalog loader (rt::LoadedCatalog), discrete and continuous: whatever the bytes,
// from_bytes() reads only inside them and either refuses them with a reason or gives a view
// that passes rt::validate(). A view it accepts then drives the attention filter, in paper
// mode and (when the catalog has the section) robust mode, for a few steps whose states,
// rewards and actions come from the input's first bytes: the filter must stay ok() and pick
// abstractions and actions in range. Under ASan, any read outside the catalog is a crash.

#include <cstring>
#include <vector>

#include "fuzz_target.hpp"
#include "oasis/rt/attention_filter.hpp"
#include "oasis/rt/catalog_file.hpp"
#include "oasis/rt/spec_hash.hpp"

namespace {

using namespace oasis;

// A source of small numbers for the steps: the input's bytes from the start, cycled.
class Steps {
 public:
  Steps(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint32_t next() { return size_ == 0 ? 0 : data_[at_++ % size_]; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t at_ = 0;
};

void drive(const rt::CatalogView& catalog, rt::FilterMode mode, Steps steps) {
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
    filter.start(steps.next() % (catalog.num_states + 1));  // one past the end now and then
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

void load_and_drive(const std::uint8_t* data, std::size_t size) {
  const rt::LoadedCatalog loaded = rt::LoadedCatalog::from_bytes(data, size);
  if (!loaded.ok()) {
    FUZZ_REQUIRE(!loaded.error().empty());
    return;
  }
  std::string why;
  FUZZ_REQUIRE(rt::validate(loaded.view(), &why));
  drive(loaded.view(), rt::FilterMode::kPaper, Steps(data, size));
  if (loaded.view().has_robust_section())
    drive(loaded.view(), rt::FilterMode::kRobust, Steps(data, size));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  load_and_drive(data, size);
  // A mutated file almost always fails the checksum, which guards everything after the
  // header: loaded again with the checksum made right, it reaches the section parser, as a
  // crafted (not corrupted) file would.
  constexpr std::size_t kChecksumAt = 24;
  constexpr std::size_t kCheckedFrom = 32;
  if (size < kCheckedFrom) return 0;
  std::vector<std::uint8_t> sealed(data, data + size);
  const std::uint64_t checksum = rt::fnv1a64(sealed.data() + kCheckedFrom, size - kCheckedFrom);
  std::memcpy(sealed.data() + kChecksumAt, &checksum, sizeof checksum);
  load_and_drive(sealed.data(), sealed.size());
  return 0;
}
