#pragma once
// Which of the catalog's contexts says "human N holds the treat" (the Go1 spec's names), for
// the ground truth of the simulators.
#include <cstdint>
#include <optional>

#include "oasis/rt/catalog_view.hpp"
#include "perception/treat_holder.hpp"

namespace oasis::hw::loop {

// The index of the context, if the catalog has it.
std::optional<std::uint32_t> context_index(const rt::CatalogView& catalog, TreatHolder holder);

}  // namespace oasis::hw::loop
