#pragma once
// The contexts of a catalog dealt out to the ranks of an MPI job: context c to rank c mod P.
// Every rank holds the whole model (a catalog's contexts share its state space), abstracts
// its own contexts as `oasisc compile` does (pipeline::abstract_contexts), and sends rank 0
// each partition and policy. Rank 0 rebuilds each quotient from its partition
// (bisim::build_quotient, what the rank that made it did) and so holds what a one-process
// compile holds: the catalog it then writes is the same, byte for byte.

#include <string>
#include <vector>

#include "distributed/communicator.hpp"
#include "model/explicit_model.hpp"
#include "pipeline/discrete_catalog.hpp"

namespace oasis::distributed {

// Collective. Returns on every rank whether every rank succeeded; rank 0 then has every
// context's abstraction in `all`, in context order. When a rank fails (a policy that does not
// converge), rank 0's `error` is the failure of the lowest rank that failed.
bool abstract_contexts_spread(const model::ExplicitModel& model,
                              const pipeline::DiscreteOptions& options,
                              const Communicator& communicator,
                              std::vector<pipeline::DiscreteAbstraction>& all, std::string& error);

}  // namespace oasis::distributed
