#include "verify/continuous_json_reader.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <new>

#include <nlohmann/json.hpp>

#include "oasis/rt/bsp_locator.hpp"
#include "oasis/rt/catalog_view.hpp"
#include "support/mapped_file.hpp"

namespace oasis::verify {
namespace {

using nlohmann::json;

// The index of `name` in `names`; throws (as nlohmann does) with the key's meaning.
std::uint32_t index_of(const std::vector<std::string>& names, const std::string& name,
                       const char* what) {
  const auto found = std::find(names.begin(), names.end(), name);
  if (found == names.end())
    throw std::out_of_range(std::string("unknown ") + what + " '" + name + "'");
  return static_cast<std::uint32_t>(found - names.begin());
}

// A count or an index: a JSON integer in 0..2^32-1. nlohmann's get<std::uint32_t>() would
// take 1.5 as 1 and 5e9 modulo 2^32, and convert a double beyond the range with undefined
// behaviour (found by the continuous_json fuzz target).
std::uint32_t index_value(const json& value, const char* what) {
  if (!value.is_number_unsigned() ||
      value.get<std::uint64_t>() > std::numeric_limits<std::uint32_t>::max())
    throw std::out_of_range(std::string(what) + " must be an integer in 0..4294967295, not " +
                            value.dump());
  return static_cast<std::uint32_t>(value.get<std::uint64_t>());
}

std::vector<std::uint32_t> index_list(const json& values, const char* what) {
  if (!values.is_array()) throw std::out_of_range(std::string(what) + " must be an array");
  std::vector<std::uint32_t> list;
  for (const json& value : values)
    list.push_back(index_value(value, what));
  return list;
}

std::uint64_t parse_hash(const std::string& text) {
  if (text.size() != 16 || text.find_first_not_of("0123456789abcdef") != std::string::npos)
    throw std::out_of_range("spec_hash is not 16 hexadecimal digits");
  return std::stoull(text, nullptr, 16);
}

// A cell's polytope as it states it: "A" (one array of coefficients per row) and "b".
StatedCell stated_cell(const json& cell) {
  StatedCell stated;
  for (const json& row : cell.at("A"))
    stated.rows.push_back(row.get<std::vector<double>>());
  stated.bounds = cell.at("b").get<std::vector<double>>();
  return stated;
}

void read_grid(const json& abstraction, const model::CatalogData& catalog,
               model::AbstractionData& data) {
  for (const json& name : abstraction.at("relevant_variables"))
    data.grid_axes.push_back(index_of(catalog.variable_names, name.get<std::string>(), "variable"));
  data.grid_break_begin.push_back(0);
  for (const json& axis : abstraction.at("grid")) {
    for (const json& t : axis)
      data.grid_breaks.push_back(t.get<double>());
    data.grid_break_begin.push_back(static_cast<std::uint32_t>(data.grid_breaks.size()));
  }
  if (data.grid_break_begin.size() != data.grid_axes.size() + 1)
    throw std::out_of_range("the grid lists " + std::to_string(data.grid_break_begin.size() - 1) +
                            " axes for " + std::to_string(data.grid_axes.size()) +
                            " relevant variables");
  for (const json& cell : abstraction.at("cells"))
    data.cell_block.push_back(index_value(cell.at("block"), "a cell's block"));
}

// The cells a grid without a BSP has: the product of its axes' interval counts (0 when an axis
// has no interval, and more than any file holds when the product overflows).
std::uint64_t grid_cell_count(const model::AbstractionData& data) {
  std::uint64_t cells = 1;
  for (std::size_t i = 0; i + 1 < data.grid_break_begin.size(); ++i) {
    const std::uint32_t breaks = data.grid_break_begin[i + 1] - data.grid_break_begin[i];
    const std::uint64_t intervals = breaks < 2 ? 0 : breaks - 1;
    if (intervals != 0 && cells > std::numeric_limits<std::uint64_t>::max() / intervals)
      return std::numeric_limits<std::uint64_t>::max();
    cells *= intervals;
  }
  return cells;
}

void read_bsp(const json& bsp, model::AbstractionData& data) {
  for (const json& normal : bsp.at("normal")) {
    if (normal.empty()) {  // a leaf: zeros, as in the binary file
      data.bsp_normal.insert(data.bsp_normal.end(), data.grid_axes.size(), 0.0);
      continue;
    }
    if (normal.size() != data.grid_axes.size())
      throw std::out_of_range("a BSP normal has the wrong number of coefficients");
    for (const json& a : normal)
      data.bsp_normal.push_back(a.get<double>());
  }
  data.bsp_bound = bsp.at("bound").get<std::vector<double>>();
  data.bsp_below = index_list(bsp.at("below"), "a BSP node's below");
  data.bsp_above = index_list(bsp.at("above"), "a BSP node's above");
  for (const json& cell : bsp.at("cell"))
    data.bsp_cell.push_back(cell.is_null() ? rt::kInternalNode
                                           : index_value(cell, "a BSP leaf's cell"));
  const std::size_t nodes = data.bsp_cell.size();
  if (data.bsp_bound.size() != nodes || data.bsp_below.size() != nodes ||
      data.bsp_above.size() != nodes || data.bsp_normal.size() != nodes * data.grid_axes.size())
    throw std::out_of_range("the BSP's arrays differ in length");
  data.bsp_cells = static_cast<std::uint32_t>(data.cell_block.size());
}

// Blocks: rewards, policy and values; with transitions their `next` rows as CSR.
void read_blocks(const json& blocks, const model::CatalogData& catalog,
                 model::AbstractionData& data) {
  const std::size_t actions = catalog.action_names.size();
  bool rows = false;
  for (const json& block : blocks) {
    const double reward = block.at("reward").get<double>();
    data.block_reward.push_back(reward);
    data.reward.insert(data.reward.end(), actions, reward);  // state rewards
    const json& policy = block.at("policy");
    data.policy.push_back(
        policy.is_null() ? rt::kNoAction
                         : index_of(catalog.action_names, policy.get<std::string>(), "action"));
    data.value.push_back(block.at("value").get<double>());
    rows = rows || block.contains("next");
  }
  if (!rows) return;
  data.quotient.choice_begin.push_back(0);
  for (const json& block : blocks) {
    const json& next = block.at("next");
    for (const std::string& action : catalog.action_names) {
      for (const json& entry : next.at(action)) {
        data.quotient.target.push_back(index_value(entry.at(0), "a row's block"));
        data.quotient.probability.push_back(entry.at(1).get<double>());
      }
      data.quotient.choice_begin.push_back(static_cast<std::uint32_t>(data.quotient.target.size()));
    }
  }
}

// The "observation" object (absent or null: none), as continuous_json.cpp writes it.
void read_observation(const json& document, model::CatalogData& catalog) {
  if (!document.contains("observation") || document.at("observation").is_null()) return;
  const json& observation = document.at("observation");
  if (observation.at("reward_follows").get<std::string>() == "observed")
    catalog.reward_source = rt::RewardSource::kObservedState;
  model::PositionNoiseData& noise = catalog.position;
  const auto& objects = observation.at("objects");
  if (objects.empty()) return;
  noise.object_of.assign(catalog.variable_names.size(), rt::kExactVariable);
  for (const json& object : objects) {
    const auto k = static_cast<std::uint32_t>(noise.detection.size());
    noise.object_names.push_back(object.at("name").get<std::string>());
    for (const json& name : object.at("variables")) {
      const auto at = std::find(catalog.variable_names.begin(), catalog.variable_names.end(),
                                name.get<std::string>());
      if (at == catalog.variable_names.end())
        throw std::out_of_range("object '" + noise.object_names.back() +
                                "' measures an unknown variable " + name.dump());
      noise.object_of[static_cast<std::size_t>(at - catalog.variable_names.begin())] = k;
    }
    const auto sigma = object.at("sigma").get<std::vector<double>>();
    if (sigma.size() != 3)
      throw std::out_of_range("object '" + noise.object_names.back() + "': sigma needs 3 numbers");
    noise.sigma.insert(noise.sigma.end(), sigma.begin(), sigma.end());
    noise.detection.push_back(object.at("detection").get<double>());
  }
}

// `where` names the part being read, for the error message.
model::CatalogData catalog_of(const json& document, StatedCells* stated, std::string& where) {
  if (!document.is_object())
    throw std::out_of_range("the document is " + std::string(document.type_name()) +
                            ", not an object with the keys format, name, spec_hash, ...");
  model::CatalogData catalog;
  if (index_value(document.at("format"), "format") != rt::kCatalogFormat)
    throw std::out_of_range("catalog format " + document.at("format").dump() + ", expected " +
                            std::to_string(rt::kCatalogFormat));
  catalog.name = document.at("name").get<std::string>();
  catalog.spec_hash = parse_hash(document.at("spec_hash").get<std::string>());
  catalog.compiler_version = document.at("compiler_version").get<std::string>();
  catalog.variable_names = document.at("variables").get<std::vector<std::string>>();
  catalog.action_names = document.at("actions").get<std::vector<std::string>>();
  catalog.num_actions = static_cast<std::uint32_t>(catalog.action_names.size());
  for (const json& row : document.at("switching"))
    for (const json& p : row)
      catalog.switching.push_back(p.get<double>());
  catalog.prior = document.at("prior").get<std::vector<double>>();
  read_observation(document, catalog);
  for (const json& abstraction : document.at("abstractions")) {
    where = "abstraction " + std::to_string(catalog.abstractions.size());
    model::AbstractionData data;
    data.context = abstraction.at("context").get<std::string>();
    where += " ('" + data.context + "')";
    data.num_blocks = index_value(abstraction.at("num_blocks"), "num_blocks");
    data.outside_block = index_value(abstraction.at("outside_block"), "outside_block");
    data.epsilon = abstraction.at("epsilon").get<double>();
    read_grid(abstraction, catalog, data);
    if (abstraction.contains("bsp")) {
      read_bsp(abstraction.at("bsp"), data);
    } else if (!data.grid_axes.empty() && data.cell_block.size() != grid_cell_count(data)) {
      // The runtime reads one cell_block entry per grid cell: the counts must agree.
      throw std::out_of_range("abstraction '" + data.context + "' lists " +
                              std::to_string(data.cell_block.size()) + " cells for a grid of " +
                              std::to_string(grid_cell_count(data)));
    }
    read_blocks(abstraction.at("blocks"), catalog, data);
    if (stated != nullptr) {
      auto& cells = stated->emplace_back();
      for (const json& cell : abstraction.at("cells")) {
        where = "abstraction " + std::to_string(catalog.abstractions.size()) + " ('" +
                data.context + "'), cell " + std::to_string(cells.size());
        cells.push_back(stated_cell(cell));
      }
    }
    if (data.block_reward.size() != data.num_blocks)
      throw std::out_of_range("abstraction '" + data.context + "' lists " +
                              std::to_string(data.block_reward.size()) + " blocks, num_blocks " +
                              std::to_string(data.num_blocks));
    catalog.abstractions.push_back(std::move(data));
  }
  where.clear();
  // The runtime reads an n x n switching matrix and n priors for n abstractions.
  const std::size_t n = catalog.abstractions.size();
  if (catalog.switching.size() != n * n || catalog.prior.size() != n)
    throw std::out_of_range("switching and prior must be " + std::to_string(n) + " x " +
                            std::to_string(n) + " and " + std::to_string(n) + " numbers for the " +
                            std::to_string(n) + " abstractions");
  return catalog;
}

// nlohmann's messages start with their own code, "[json.exception.type_error.302] ": the
// user needs the sentence after it.
std::string without_code(const char* message) {
  std::string text = message;
  if (text.rfind("[json.exception.", 0) == 0) {
    const std::size_t end = text.find("] ");
    if (end != std::string::npos) text.erase(0, end + 2);
  }
  return text;
}

}  // namespace

std::optional<model::CatalogData> read_continuous_catalog_json(const std::string& path,
                                                               std::size_t max_bytes,
                                                               std::string& error,
                                                               StatedCells* stated) {
  MappedFile file;
  if (!file.open(path, max_bytes, error)) {
    error = "cannot read: " + error;
    return std::nullopt;
  }
  return parse_continuous_catalog_json(file.text(), error, stated);
}

std::optional<model::CatalogData> parse_continuous_catalog_json(std::string_view text,
                                                                std::string& error,
                                                                StatedCells* stated) {
  std::string where;
  try {
    if (stated != nullptr) stated->clear();
    return catalog_of(json::parse(text.begin(), text.end()), stated, where);
  } catch (const std::bad_alloc&) {
    throw;                             // the memory budget, reported by main
  } catch (const std::exception& e) {  // nlohmann's parse, key and type errors, and ours
    error = "not a continuous catalog's JSON: " + (where.empty() ? "" : where + ": ") +
            without_code(e.what());
    return std::nullopt;
  }
}

}  // namespace oasis::verify
