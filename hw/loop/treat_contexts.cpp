#include "loop/treat_contexts.hpp"

#include <cstring>

namespace oasis::hw::loop {

std::optional<std::uint32_t> context_index(const rt::CatalogView& catalog, TreatHolder holder) {
  const char* name = holder == TreatHolder::kHuman1 ? "human1_holds_treat" : "human2_holds_treat";
  for (std::uint32_t i = 0; i < catalog.num_abstractions; ++i)
    if (std::strcmp(catalog.abstractions[i].context, name) == 0) return i;
  return std::nullopt;
}

}  // namespace oasis::hw::loop
