// Loads a binary catalog (argv[1]) with the installed runtime and runs a few filter steps.
#include <cstdio>
#include <vector>

#include "oasis/rt/attention_filter.hpp"
#include "oasis/rt/catalog_file.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: runtime_consumer CATALOG.bin\n");
    return 2;
  }
  const oasis::rt::LoadedCatalog catalog = oasis::rt::LoadedCatalog::from_file(argv[1]);
  if (!catalog.ok()) {
    std::fprintf(stderr, "%s\n", catalog.error().c_str());
    return 1;
  }
  std::vector<double> workspace(oasis::rt::AttentionFilter::workspace_size(catalog.view(), {}));
  oasis::rt::AttentionFilter filter(catalog.view(), {}, workspace.data(), workspace.size());
  filter.start(0);
  for (int t = 0; t < 5; ++t)
    filter.step(0, 0.0, filter.action());
  std::printf("runtime_consumer: %s, %u abstractions, ML %s\n", catalog.view().name,
              catalog.view().num_abstractions,
              catalog.view().abstractions[filter.ml_abstraction()].context);
  return 0;
}
