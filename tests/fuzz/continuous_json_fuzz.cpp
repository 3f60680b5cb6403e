// oasisc verify's reader of a continuous catalog's JSON (verify/continuous_json_reader.hpp,
// the document codegen/continuous_json.hpp writes for tools outside the project): any text is
// refused with a reason, or gives a catalog that rt::validate() either accepts or refuses
// with a reason (the reader checks only the shape; verify refuses what validate refuses). A
// catalog validate() accepts then drives the attention filter (drive_filter.hpp).

#include <string>

#include "drive_filter.hpp"
#include "fuzz_target.hpp"
#include "oasis/rt/catalog_validation.hpp"
#include "oasis/rt/catalog_view.hpp"
#include "verify/continuous_json_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace oasis;
  std::string error;
  auto catalog = verify::parse_continuous_catalog_json(fuzz::text_of(data, size), error);
  if (!catalog) {
    FUZZ_REQUIRE(!error.empty());
    return 0;
  }
  const rt::CatalogView view = catalog->view();
  std::string why;
  if (!rt::validate(view, &why)) {
    FUZZ_REQUIRE(!why.empty());
    return 0;
  }
  fuzz::drive_filter(view, rt::FilterMode::kPaper, fuzz::FuzzSteps(data, size));
  if (view.has_noise_model())  // the filter of the catalog's own kind that models the noise
    fuzz::drive_filter(view, rt::noise_model_mode(view), fuzz::FuzzSteps(data, size));
  return 0;
}
