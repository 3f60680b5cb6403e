#include "distributed/context_spreading.hpp"

#include <type_traits>

#include "bisim/quotient.hpp"

namespace oasis::distributed {
namespace {

static_assert(std::is_trivially_copyable_v<bisim::RefinementStatistics>);

template <typename T>
void put_vector(ByteWriter& writer, const std::vector<T>& values) {
  writer.put(static_cast<std::uint64_t>(values.size()));
  for (const T& value : values)
    writer.put(value);
}

template <typename T>
std::vector<T> get_vector(ByteReader& reader) {
  std::vector<T> values(reader.get<std::uint64_t>());
  for (T& value : values)
    value = reader.get<T>();
  return values;
}

void put_policy(ByteWriter& writer, const policy::Policy& policy) {
  put_vector(writer, policy.action);
  put_vector(writer, policy.value);
  writer.put(policy.iterations);
  writer.put(policy.converged);
  writer.put(policy.residual);
  writer.put(policy.objective.discount);
  writer.put(policy.objective.horizon.has_value());
  writer.put(policy.objective.horizon.value_or(0));
  writer.put(policy.objective.default_discount);
}

policy::Policy get_policy(ByteReader& reader) {
  policy::Policy policy;
  policy.action = get_vector<model::ActionIndex>(reader);
  policy.value = get_vector<double>(reader);
  policy.iterations = reader.get<std::uint32_t>();
  policy.converged = reader.get<bool>();
  policy.residual = reader.get<double>();
  policy.objective.discount = reader.get<double>();
  const bool has_horizon = reader.get<bool>();
  const auto horizon = reader.get<std::uint32_t>();
  if (has_horizon) policy.objective.horizon = horizon;
  policy.objective.default_discount = reader.get<bool>();
  return policy;
}

// This rank's report to rank 0: whether it succeeded (with its error if not), then each of
// its abstractions without the quotient, which rank 0 rebuilds.
Bytes report(const std::optional<std::vector<pipeline::DiscreteAbstraction>>& abstractions,
             const std::string& error, bool solved) {
  Bytes bytes;
  ByteWriter writer(bytes);
  writer.put(abstractions.has_value());
  if (!abstractions) {
    writer.put_text(error);
    return bytes;
  }
  writer.put(static_cast<std::uint64_t>(abstractions->size()));
  for (const pipeline::DiscreteAbstraction& abstraction : *abstractions) {
    writer.put(static_cast<std::uint64_t>(abstraction.context));
    writer.put(abstraction.partition.num_blocks);
    put_vector(writer, abstraction.partition.block_of);
    writer.put(abstraction.statistics);
    writer.put(abstraction.refinement_seconds);
    if (solved) put_policy(writer, abstraction.policy);
  }
  return bytes;
}

pipeline::DiscreteAbstraction rebuild(const model::ExplicitModel& model, ByteReader& reader,
                                      bool solved) {
  pipeline::DiscreteAbstraction abstraction;
  abstraction.context = reader.get<std::uint64_t>();
  abstraction.partition.num_blocks = reader.get<model::BlockIndex>();
  abstraction.partition.block_of = get_vector<model::BlockIndex>(reader);
  abstraction.statistics = reader.get<bisim::RefinementStatistics>();
  abstraction.refinement_seconds = reader.get<double>();
  if (solved) {
    abstraction.policy = get_policy(reader);
    abstraction.quotient = bisim::build_quotient(model, abstraction.context, abstraction.partition);
  }
  return abstraction;
}

}  // namespace

bool abstract_contexts_spread(const model::ExplicitModel& model,
                              const pipeline::DiscreteOptions& options,
                              const Communicator& communicator,
                              std::vector<pipeline::DiscreteAbstraction>& all, std::string& error) {
  std::vector<std::size_t> mine;
  for (std::size_t c = communicator.rank(); c < model.contexts.size(); c += communicator.size())
    mine.push_back(c);
  std::string my_error;
  const auto abstractions = pipeline::abstract_contexts(model, mine, options, my_error);
  std::vector<Bytes> outgoing(communicator.size());
  outgoing[0] = report(abstractions, my_error, options.solve);
  const std::vector<Bytes> reports = communicator.exchange(outgoing);
  const bool failed = communicator.any(!abstractions.has_value());
  if (!communicator.is_root()) return !failed;  // the reports went to rank 0
  for (const Bytes& bytes : reports) {
    ByteReader reader(bytes);
    if (!reader.get<bool>()) {
      error = std::string(reader.get_text());
      return false;
    }
  }
  all.assign(model.contexts.size(), {});
  for (const Bytes& bytes : reports) {
    ByteReader reader(bytes);
    reader.get<bool>();
    const auto count = reader.get<std::uint64_t>();
    for (std::uint64_t i = 0; i < count; ++i) {
      pipeline::DiscreteAbstraction abstraction = rebuild(model, reader, options.solve);
      const std::size_t context = abstraction.context;
      all[context] = std::move(abstraction);
    }
  }
  return true;
}

}  // namespace oasis::distributed
