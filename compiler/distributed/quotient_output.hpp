#pragma once
// The quotient MDP of a distributed model, assembled on rank 0 from the rows of each block's
// representative, so that `oasisc-mpi --format aut` writes what `oasisc quotient --format
// aut` writes, byte for byte.

#include <optional>

#include "distributed/communicator.hpp"
#include "distributed/owned_model.hpp"
#include "distributed/partition_output.hpp"
#include "model/explicit_model.hpp"

namespace oasis::distributed {

// Collective. Rank 0 gets the quotient MDP that bisim::build_quotient makes of the whole
// model (each block represented by its smallest state), from the representatives' rows
// only; the other ranks get nullopt. `gathered` is read on rank 0 only.
std::optional<model::ExplicitModel> gather_quotient(
    const OwnedModel& owned, const std::optional<GatheredPartition>& gathered,
    const Communicator& communicator);

}  // namespace oasis::distributed
