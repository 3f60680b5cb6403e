#include "codegen/json_catalog.hpp"

#include <cmath>

#include "oasis/rt/spec_hash.hpp"

namespace oasis::codegen {
namespace {

// A bound as JSON: a number, or "infinity" (an expected reward that is), which JSON's numbers
// cannot hold.
nlohmann::json bound_json(double bound) {
  if (std::isinf(bound)) return bound > 0 ? "infinity" : "-infinity";
  return bound;
}

// One value of a guarantee: its exact fraction when known, and the interval around it.
nlohmann::json guarantee_value_json(const model::AbstractionData& data, std::size_t property,
                                    std::size_t which) {
  const std::size_t at = property * rt::kGuaranteeFields + which * 2;
  nlohmann::json value = {{"lower", bound_json(data.guarantee[at])},
                          {"upper", bound_json(data.guarantee[at + 1])}};
  const std::string& exact = data.guarantee_exact[property * 2 + which];
  if (!exact.empty()) value["exact"] = exact;
  return value;
}

// What the abstraction's policy and the optimum give each stated property.
nlohmann::json guarantees_json(const model::CatalogData& catalog,
                               const model::AbstractionData& data) {
  nlohmann::json list = nlohmann::json::array();
  for (std::size_t k = 0; k < catalog.properties.size(); ++k) {
    list.push_back({{"property", catalog.properties[k].name},
                    {"policy", guarantee_value_json(data, k, 0)},
                    {"optimum", guarantee_value_json(data, k, 1)}});
  }
  return list;
}

nlohmann::json abstraction_json(const model::CatalogData& catalog,
                                const model::AbstractionData& data) {
  std::vector<nlohmann::json> blocks(data.num_blocks);
  for (std::uint32_t z = 0; z < data.num_blocks; ++z) {
    const std::uint32_t action = data.policy[z];
    blocks[z] = {{"block", z},
                 {"members", nlohmann::json::array()},
                 {"reward", data.block_reward[z]},
                 {"action", action == rt::kNoAction ? nlohmann::json()
                                                    : nlohmann::json(catalog.action_names[action])},
                 {"value", data.value[z]}};
  }
  for (std::uint32_t s = 0; s < catalog.num_states; ++s)
    blocks[data.block_of[s]]["members"].push_back(catalog.state_names[s]);
  nlohmann::json transitions = nlohmann::json::array();
  for (std::uint32_t z = 0; z < data.num_blocks; ++z) {
    for (std::uint32_t a = 0; a < catalog.num_actions; ++a) {
      const std::size_t row = std::size_t{z} * catalog.num_actions + a;
      const std::uint32_t begin = data.quotient.choice_begin[row];
      const std::uint32_t end = data.quotient.choice_begin[row + 1];
      if (begin == end) continue;
      nlohmann::json successors = nlohmann::json::array();
      for (std::uint32_t e = begin; e < end; ++e)
        successors.push_back({data.quotient.target[e], data.quotient.probability[e]});
      transitions.push_back({{"block", z},
                             {"action", catalog.action_names[a]},
                             {"reward", data.reward[row]},
                             {"successors", std::move(successors)}});
    }
  }
  nlohmann::json out = {
      {"context", data.context}, {"blocks", blocks}, {"transitions", std::move(transitions)}};
  if (!catalog.properties.empty()) out["guarantees"] = guarantees_json(catalog, data);
  return out;
}

// null without an observation model; else its kind, p_correct (symmetric) or the confusion
// matrix's rows (one per true state), and which state the reward follows.
nlohmann::json observation_json(const model::CatalogData& catalog) {
  if (catalog.observation == rt::ObservationKind::kNone) return nlohmann::json();
  nlohmann::json out;
  if (catalog.observation == rt::ObservationKind::kSymmetric) {
    out["kind"] = "symmetric";
    out["p_correct"] = catalog.p_correct;
  } else {
    out["kind"] = "matrix";
    out["confusion"] = matrix_rows_json(catalog.confusion, catalog.num_states);
  }
  out["reward_follows"] =
      catalog.reward_source == rt::RewardSource::kObservedState ? "observed" : "true";
  return out;
}

}  // namespace

nlohmann::json matrix_rows_json(const std::vector<double>& matrix, std::size_t n) {
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t i = 0; i < n; ++i) {
    rows.push_back(std::vector<double>(matrix.begin() + static_cast<std::ptrdiff_t>(i * n),
                                       matrix.begin() + static_cast<std::ptrdiff_t>((i + 1) * n)));
  }
  return rows;
}

nlohmann::json catalog_json(const model::CatalogData& catalog) {
  nlohmann::json out;
  out["format"] = rt::kCatalogFormat;
  out["name"] = catalog.name;
  out["spec_hash"] = rt::spec_hash_text(catalog.spec_hash);
  out["compiler_version"] = catalog.compiler_version;
  out["states"] = catalog.state_names;
  out["actions"] = catalog.action_names;
  out["switching"] = matrix_rows_json(catalog.switching, catalog.abstractions.size());
  out["prior"] = catalog.prior;
  out["observation"] = observation_json(catalog);
  if (!catalog.properties.empty()) {
    nlohmann::json properties = nlohmann::json::array();
    for (const model::StatedProperty& property : catalog.properties)
      properties.push_back({{"name", property.name}, {"property", property.text}});
    out["properties"] = std::move(properties);
  }
  nlohmann::json abstractions = nlohmann::json::array();
  for (const model::AbstractionData& data : catalog.abstractions)
    abstractions.push_back(abstraction_json(catalog, data));
  out["abstractions"] = std::move(abstractions);
  return out;
}

}  // namespace oasis::codegen
