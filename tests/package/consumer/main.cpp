// Runs Online Attention Switching on a catalog linked through oasis_add_catalog(): the
// linked tables validate, and the filter follows the context the rewards point at.
#include <cstdio>
#include <string>

#include "discrete_tracking_catalog.hpp"
#include "oasis/rt/attention_filter.hpp"
#include "oasis/rt/catalog_validation.hpp"
#include "oasis/rt/catalog_view.hpp"

int main() {
  const oasis::rt::CatalogView& catalog = discrete_tracking::catalog();
  std::string why;
  if (!oasis::rt::validate(catalog, &why)) {
    std::printf("invalid catalog: %s\n", why.c_str());
    return 1;
  }
  oasis::rt::FixedWorkspace<2> workspace;
  oasis::rt::AttentionFilter filter(catalog, {}, workspace);
  filter.start(2);  // s3
  for (int t = 0; t < 5; ++t)
    filter.step(2, 1.0, filter.action());  // rewarded at s3
  std::printf("consumer: %u abstractions, ML %s\n", catalog.num_abstractions,
              catalog.abstractions[filter.ml_abstraction()].context);
  return 0;
}
