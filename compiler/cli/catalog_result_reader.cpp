#include "cli/catalog_result_reader.hpp"

#include "codegen/catalog_data.hpp"
#include "oasis/rt/catalog_file.hpp"

namespace oasis::cli {
std::optional<PartitionResult> read_catalog_partitions(const std::string& path,
                                                       const model::ExplicitModel& model,
                                                       std::uint64_t model_hash,
                                                       std::string& error) {
  const rt::LoadedCatalog catalog = rt::LoadedCatalog::from_file(path);
  if (!catalog.ok()) {
    error = catalog.error();
    if (error.rfind(path + ": ", 0) == 0)
      error.erase(0, path.size() + 2);  // the caller names the file
    return std::nullopt;
  }
  const rt::CatalogView& view = catalog.view();
  if (view.spec_hash != model_hash) {
    error = "the catalog was compiled from another spec (hash " +
            codegen::hash_text(view.spec_hash) + ", this one has " +
            codegen::hash_text(model_hash) + "); recompile it";
    return std::nullopt;
  }
  if (view.num_states != model.num_states() || view.num_actions != model.num_actions()) {
    error = "the catalog has " + std::to_string(view.num_states) + " states and " +
            std::to_string(view.num_actions) + " actions, the model " +
            std::to_string(model.num_states()) + " and " + std::to_string(model.num_actions());
    return std::nullopt;
  }
  PartitionResult result;
  for (std::uint32_t i = 0; i < view.num_abstractions; ++i) {
    const rt::AbstractionView& abstraction = view.abstractions[i];
    std::size_t c = 0;
    while (c < model.contexts.size() && model.contexts[c].name != abstraction.context)
      ++c;
    if (c == model.contexts.size()) {
      error = std::string("the catalog has a context '") + abstraction.context +
              "' that the model does not";
      return std::nullopt;
    }
    ContextPartition entry;
    entry.context = c;
    entry.partition.block_of.assign(abstraction.block_of, abstraction.block_of + view.num_states);
    entry.partition.num_blocks = abstraction.num_blocks;
    result.contexts.push_back(std::move(entry));
  }
  return result;
}

}  // namespace oasis::cli
