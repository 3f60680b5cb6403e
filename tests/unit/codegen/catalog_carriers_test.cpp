// Every carrier of a catalog carries every field. Two specs (tests/data/catalog_carriers/: a
// discrete one and a continuous one, between them every optional part of a catalog) are
// compiled here into the catalog in memory (model::CatalogData, what every emitter reads),
// and each carrier is read back and compared with it field by field
// (tests/support/catalog_fields.hpp):
//   the binary file     codegen::binary_catalog  -> rt::LoadedCatalog (the runtime's loader)
//   the C++ tables      oasisc --format cpp, compiled into this test by tests/CMakeLists.txt
//   the JSON            codegen's JSON           -> verify's reader (continuous) or the reader
//                                                   below (discrete: verify reads none)
// A field a carrier forgets (or a field added to the view and to no carrier) fails here.

#include <algorithm>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../../support/catalog_fields.hpp"
#include "carriers_continuous_catalog.hpp"
#include "carriers_discrete_catalog.hpp"
#include "codegen/binary_catalog.hpp"
#include "codegen/continuous_json.hpp"
#include "codegen/json_catalog.hpp"
#include "input/model_loader.hpp"
#include "oasis/rt/catalog_file.hpp"
#include "pipeline/continuous_catalog.hpp"
#include "pipeline/continuous_catalog_data.hpp"
#include "pipeline/continuous_options.hpp"
#include "pipeline/discrete_catalog.hpp"
#include "property/catalog_guarantees.hpp"
#include "verify/continuous_json_reader.hpp"

namespace oasis {
namespace {

struct Compiled {
  model::CatalogData data;                                // what every carrier must carry
  std::optional<pipeline::ContinuousCatalog> continuous;  // the continuous JSON's input
};

std::string spec_path(const std::string& name) {
  return std::string(OASIS_SOURCE_DIR) + "/tests/data/catalog_carriers/" + name + ".oasis";
}

// As `oasisc compile SPEC --with-transitions` builds it (the options the spec states).
Compiled compile(const std::string& name) {
  SourceManager sources;
  std::ostringstream messages;
  DiagnosticEngine diagnostics(sources, messages);
  const auto loaded = input::load_model(spec_path(name), sources, diagnostics, {});
  EXPECT_TRUE(loaded && !diagnostics.has_errors()) << messages.str();
  if (!loaded) return {};
  Compiled out;
  std::string error;
  if (loaded->model) {
    auto data = pipeline::build_catalog(*loaded->model, loaded->source_hash, {}, error);
    EXPECT_TRUE(data) << error;
    if (!data) return out;
    EXPECT_TRUE(property::state_guarantees(*loaded->model, loaded->names, loaded->properties, *data,
                                           diagnostics))
        << messages.str();
    out.data = std::move(*data);
    return out;
  }
  pipeline::ContinuousCatalogOptions options;
  options.abstraction.target = pipeline::continuous_target(*loaded->ir, {});
  out.continuous =
      pipeline::build_continuous_catalog(*loaded->ir, loaded->source_hash, options, error);
  EXPECT_TRUE(out.continuous) << error;
  if (out.continuous) out.data = pipeline::continuous_catalog_data(*out.continuous, true);
  return out;
}

Compiled& discrete() {
  static Compiled compiled = compile("carriers_discrete");
  return compiled;
}

Compiled& continuous() {
  static Compiled compiled = compile("carriers_continuous");
  return compiled;
}

std::string listed(const std::vector<std::string>& differences) {
  std::string text;
  for (const std::string& difference : differences)
    text += "  " + difference + "\n";
  return text;
}

// ---- The discrete JSON read back (codegen/json_catalog.hpp's keys) ----

std::uint32_t index_in(const std::vector<std::string>& names, const std::string& name) {
  const auto found = std::find(names.begin(), names.end(), name);
  EXPECT_NE(found, names.end()) << name;
  return static_cast<std::uint32_t>(found - names.begin());
}

void read_observation(const nlohmann::json& observation, model::CatalogData& catalog) {
  if (observation.is_null()) return;
  if (observation.at("kind") == "symmetric") {
    catalog.observation = rt::ObservationKind::kSymmetric;
    catalog.p_correct = observation.at("p_correct").get<double>();
  } else {
    catalog.observation = rt::ObservationKind::kMatrix;
    for (const nlohmann::json& row : observation.at("confusion"))
      for (const nlohmann::json& p : row)
        catalog.confusion.push_back(p.get<double>());
  }
  if (observation.at("reward_follows") == "observed")
    catalog.reward_source = rt::RewardSource::kObservedState;
}

void read_blocks(const nlohmann::json& blocks, const model::CatalogData& catalog,
                 model::AbstractionData& data) {
  data.num_blocks = static_cast<std::uint32_t>(blocks.size());
  data.block_of.assign(catalog.num_states, 0);
  for (const nlohmann::json& block : blocks) {
    const auto z = block.at("block").get<std::uint32_t>();
    for (const nlohmann::json& member : block.at("members"))
      data.block_of[index_in(catalog.state_names, member.get<std::string>())] = z;
    data.block_reward.push_back(block.at("reward").get<double>());
    const nlohmann::json& action = block.at("action");
    data.policy.push_back(action.is_null()
                              ? rt::kNoAction
                              : index_in(catalog.action_names, action.get<std::string>()));
    data.value.push_back(block.at("value").get<double>());
  }
}

// The listed rows (block, action) with their successors; the rows left out are empty, with
// reward 0 (as the emitters write a disabled action's).
void read_transitions(const nlohmann::json& transitions, const model::CatalogData& catalog,
                      model::AbstractionData& data) {
  const std::size_t rows = std::size_t{data.num_blocks} * catalog.num_actions;
  std::vector<std::vector<std::pair<std::uint32_t, double>>> successors(rows);
  data.reward.assign(rows, 0.0);
  for (const nlohmann::json& transition : transitions) {
    const std::size_t row =
        transition.at("block").get<std::size_t>() * catalog.num_actions +
        index_in(catalog.action_names, transition.at("action").get<std::string>());
    data.reward[row] = transition.at("reward").get<double>();
    for (const nlohmann::json& edge : transition.at("successors"))
      successors[row].emplace_back(edge.at(0).get<std::uint32_t>(), edge.at(1).get<double>());
  }
  data.quotient.choice_begin.push_back(0);
  for (const auto& row : successors) {
    for (const auto& [target, probability] : row) {
      data.quotient.target.push_back(target);
      data.quotient.probability.push_back(probability);
    }
    data.quotient.choice_begin.push_back(static_cast<std::uint32_t>(data.quotient.target.size()));
  }
}

// A bound: a number, or "infinity".
double bound_of(const nlohmann::json& bound) {
  if (bound.is_string()) return bound == "infinity" ? HUGE_VAL : -HUGE_VAL;
  return bound.get<double>();
}

// Each property's policy and optimum intervals; an exact value, where stated, must lie in its
// interval.
void read_guarantees(const nlohmann::json& guarantees, model::AbstractionData& data) {
  for (const nlohmann::json& guarantee : guarantees) {
    for (const char* which : {"policy", "optimum"}) {
      const nlohmann::json& value = guarantee.at(which);
      data.guarantee.push_back(bound_of(value.at("lower")));
      data.guarantee.push_back(bound_of(value.at("upper")));
      if (!value.contains("exact") || value.at("exact") == "infinity") continue;
      const Rational exact(value.at("exact").get<std::string>());
      EXPECT_LE(Rational(data.guarantee[data.guarantee.size() - 2]), exact);
      EXPECT_GE(Rational(data.guarantee.back()), exact);
    }
  }
}

model::CatalogData read_discrete_json(const std::string& text) {
  const nlohmann::json document = nlohmann::json::parse(text);
  model::CatalogData catalog;
  EXPECT_EQ(document.at("format").get<std::uint32_t>(), rt::kCatalogFormat);
  catalog.name = document.at("name").get<std::string>();
  catalog.spec_hash = std::stoull(document.at("spec_hash").get<std::string>(), nullptr, 16);
  catalog.compiler_version = document.at("compiler_version").get<std::string>();
  catalog.state_names = document.at("states").get<std::vector<std::string>>();
  catalog.num_states = static_cast<std::uint32_t>(catalog.state_names.size());
  catalog.action_names = document.at("actions").get<std::vector<std::string>>();
  catalog.num_actions = static_cast<std::uint32_t>(catalog.action_names.size());
  for (const nlohmann::json& row : document.at("switching"))
    for (const nlohmann::json& p : row)
      catalog.switching.push_back(p.get<double>());
  catalog.prior = document.at("prior").get<std::vector<double>>();
  read_observation(document.at("observation"), catalog);
  if (document.contains("properties")) {
    for (const nlohmann::json& property : document.at("properties"))
      catalog.properties.push_back(
          {property.at("name").get<std::string>(), property.at("property").get<std::string>()});
  }
  for (const nlohmann::json& abstraction : document.at("abstractions")) {
    model::AbstractionData& data = catalog.abstractions.emplace_back();
    data.context = abstraction.at("context").get<std::string>();
    read_blocks(abstraction.at("blocks"), catalog, data);
    read_transitions(abstraction.at("transitions"), catalog, data);
    if (abstraction.contains("guarantees")) read_guarantees(abstraction.at("guarantees"), data);
  }
  return catalog;
}

// ---- The catalogs are worth comparing: every optional part is there ----

TEST(CatalogCarriers, TheDiscreteCatalogFillsEveryOptionalPart) {
  const rt::CatalogView view = discrete().data.view();
  ASSERT_EQ(view.num_abstractions, 2u);
  EXPECT_NE(view.state_names, nullptr);
  EXPECT_EQ(view.observation.kind, rt::ObservationKind::kMatrix);
  EXPECT_NE(view.observation.confusion, nullptr);
  EXPECT_EQ(view.observation.reward_source, rt::RewardSource::kObservedState);
  EXPECT_EQ(view.properties.count, 2u) << "stated properties";
  for (std::uint32_t i = 0; i < view.num_abstractions; ++i) {
    const rt::AbstractionView& abstraction = view.abstractions[i];
    EXPECT_LT(abstraction.num_blocks, view.num_states) << "blocks of several states";
    EXPECT_GT(abstraction.quotient.num_edges, 0u);
    EXPECT_GT(abstraction.state_transitions.num_edges, 0u);
    EXPECT_NE(abstraction.guarantee, nullptr);
  }
}

TEST(CatalogCarriers, TheContinuousCatalogFillsEveryOptionalPart) {
  const rt::CatalogView view = continuous().data.view();
  ASSERT_EQ(view.num_abstractions, 2u);
  EXPECT_NE(view.variable_names, nullptr);
  EXPECT_EQ(view.observation.reward_source, rt::RewardSource::kObservedState);
  const rt::PositionNoise& noise = view.observation.position;
  ASSERT_EQ(noise.num_objects, 1u);
  ASSERT_EQ(view.state_dimension, 2u);
  EXPECT_EQ(noise.object_of[0], 0u);
  EXPECT_EQ(noise.object_of[1], rt::kExactVariable);
  EXPECT_EQ(view.abstractions[0].bsp.num_nodes, 0u) << "the first context is gridded";
  EXPECT_GT(view.abstractions[1].bsp.num_nodes, 1u) << "the second has polytope cells";
  for (std::uint32_t i = 0; i < view.num_abstractions; ++i) {
    EXPECT_GT(view.abstractions[i].quotient.num_edges, 0u);
    EXPECT_GT(view.abstractions[i].epsilon, 0.0);
  }
}

// ---- Each carrier ----

TEST(CatalogCarriers, TheBinaryFileCarriesEveryField) {
  for (Compiled* compiled : {&discrete(), &continuous()}) {
    const std::string bytes = codegen::binary_catalog(compiled->data);
    const rt::LoadedCatalog loaded = rt::LoadedCatalog::from_bytes(bytes.data(), bytes.size());
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    const auto differences = test::compare_catalogs(compiled->data.view(), loaded.view());
    EXPECT_TRUE(differences.empty()) << compiled->data.name << ":\n" << listed(differences);
  }
}

// The continuous tables leave out the quotient's rows, even with --with-transitions
// (codegen/catalog_files.cpp: a robot does not read them, and they are large); the discrete
// tables carry them, so the C++ emitter's writing of them is compared all the same.
TEST(CatalogCarriers, TheGeneratedCppCarriesEveryField) {
  const auto discrete_differences =
      test::compare_catalogs(discrete().data.view(), carriers_discrete::catalog());
  EXPECT_TRUE(discrete_differences.empty()) << listed(discrete_differences);
  const auto continuous_differences = test::compare_catalogs(
      continuous().data.view(), carriers_continuous::catalog(), {"quotient"});
  EXPECT_TRUE(continuous_differences.empty()) << listed(continuous_differences);
}

// The discrete JSON leaves out the robust section's state rows (a person reading the JSON
// reads the quotient; the robot loads the binary file).
TEST(CatalogCarriers, TheDiscreteJsonCarriesEveryFieldButTheStateRows) {
  model::CatalogData read = read_discrete_json(codegen::catalog_json(discrete().data).dump(2));
  const auto differences =
      test::compare_catalogs(discrete().data.view(), read.view(), {"state_transitions"});
  EXPECT_TRUE(differences.empty()) << listed(differences);
}

TEST(CatalogCarriers, TheContinuousJsonCarriesEveryField) {
  ASSERT_TRUE(continuous().continuous);
  std::string error;
  auto read = verify::parse_continuous_catalog_json(
      codegen::continuous_catalog_json(*continuous().continuous, true), error);
  ASSERT_TRUE(read) << error;
  const auto differences = test::compare_catalogs(continuous().data.view(), read->view());
  EXPECT_TRUE(differences.empty()) << listed(differences);
}

}  // namespace
}  // namespace oasis
