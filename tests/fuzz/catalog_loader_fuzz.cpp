// The binary catalog loader (rt::LoadedCatalog), discrete and continuous: whatever the bytes,
// from_bytes() reads only inside them and either refuses them with a reason or gives a view
// that passes rt::validate(). A view it accepts then drives the attention filter, in paper
// mode and (when the catalog has the section) robust mode, for a few steps whose states,
// rewards and actions come from the input's first bytes: the filter must stay ok() and pick
// abstractions and actions in range. Under ASan, any read outside the catalog is a crash.

#include <cstring>
#include <vector>

#include "drive_filter.hpp"
#include "fuzz_target.hpp"
#include "oasis/rt/catalog_file.hpp"
#include "oasis/rt/catalog_validation.hpp"
#include "oasis/rt/spec_hash.hpp"

namespace {

using namespace oasis;
using fuzz::drive_filter;
using fuzz::FuzzSteps;

void load_and_drive(const std::uint8_t* data, std::size_t size) {
  const rt::LoadedCatalog loaded = rt::LoadedCatalog::from_bytes(data, size);
  if (!loaded.ok()) {
    FUZZ_REQUIRE(!loaded.error().empty());
    return;
  }
  std::string why;
  FUZZ_REQUIRE(rt::validate(loaded.view(), &why));
  drive_filter(loaded.view(), rt::FilterMode::kPaper, FuzzSteps(data, size));
  if (loaded.view()
          .has_noise_model())  // the filter of the catalog's own kind that models the noise
    drive_filter(loaded.view(), rt::noise_model_mode(loaded.view()), FuzzSteps(data, size));
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
