#pragma once
// Test helper: two catalogs compared field by field through the runtime's view
// (oasis/rt/catalog_view.hpp), every field of every struct in it, naming each field that
// differs. A carrier (the binary file, the JSON, the generated C++) that forgets a field
// shows up as that field's name. The sizes of the view's structs are pinned below, so that a
// field added to the view fails to compile here until it is compared too.

#include <cstdint>
#include <cstring>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "oasis/rt/catalog_view.hpp"

namespace oasis::test {

// A field added to one of these structs must be added to compare_catalogs() below; then
// update the size.
static_assert(sizeof(void*) != 8 || sizeof(rt::TransitionsCsr) == 32, "compare the new field");
static_assert(sizeof(void*) != 8 || sizeof(rt::GridView) == 32, "compare the new field");
static_assert(sizeof(void*) != 8 || sizeof(rt::BspView) == 48, "compare the new field");
static_assert(sizeof(void*) != 8 || sizeof(rt::AbstractionView) == 232, "compare the new field");
static_assert(sizeof(void*) != 8 || sizeof(rt::PositionNoise) == 32, "compare the new field");
static_assert(sizeof(void*) != 8 || sizeof(rt::ObservationModel) == 64, "compare the new field");
static_assert(sizeof(void*) != 8 || sizeof(rt::CatalogView) == 192, "compare the new field");

// Collects the fields that differ. A field is named "abstraction 'CONTEXT': FIELD" or
// "FIELD"; those whose FIELD (or its part before the first '.') is in `not_carried` are not
// compared: what a carrier leaves out by design, said once at the call.
class FieldComparison {
 public:
  explicit FieldComparison(std::set<std::string> not_carried)
      : not_carried_(std::move(not_carried)) {}

  void enter(const std::string& where) { where_ = where; }

  template <typename T>
  void value(const std::string& field, const T& expected, const T& actual) {
    if (skipped(field) || expected == actual) return;
    std::ostringstream out;
    out << expected << " != " << actual;
    differ(field, out.str());
  }

  // `count` elements (both arrays must hold that many when present).
  template <typename T>
  void array(const std::string& field, const T* expected, const T* actual, std::uint64_t count) {
    if (skipped(field) || count == 0) return;
    if ((expected == nullptr) != (actual == nullptr))
      return differ(field, expected == nullptr ? "present, expected absent" : "absent");
    if (expected == nullptr) return;
    for (std::uint64_t k = 0; k < count; ++k) {
      if (expected[k] == actual[k]) continue;
      std::ostringstream out;
      out << "[" << k << "] " << expected[k] << " != " << actual[k];
      return differ(field, out.str());
    }
  }

  void text(const std::string& field, const char* expected, const char* actual) {
    if (skipped(field)) return;
    if ((expected == nullptr) != (actual == nullptr))
      return differ(field, expected == nullptr ? "present, expected absent" : "absent");
    if (expected != nullptr && std::strcmp(expected, actual) != 0)
      differ(field, std::string("'") + expected + "' != '" + actual + "'");
  }

  void texts(const std::string& field, const char* const* expected, const char* const* actual,
             std::uint64_t count) {
    if (skipped(field) || count == 0) return;
    if ((expected == nullptr) != (actual == nullptr))
      return differ(field, expected == nullptr ? "present, expected absent" : "absent");
    for (std::uint64_t k = 0; expected != nullptr && k < count; ++k)
      text(field + "[" + std::to_string(k) + "]", expected[k], actual[k]);
  }

  const std::vector<std::string>& differences() const { return differences_; }

 private:
  bool skipped(const std::string& field) const {
    return not_carried_.count(field) != 0 || not_carried_.count(field.substr(0, field.find('.')));
  }

  void differ(const std::string& field, const std::string& how) {
    differences_.push_back((where_.empty() ? "" : where_ + ": ") + field + ": " + how);
  }

  std::set<std::string> not_carried_;
  std::string where_;
  std::vector<std::string> differences_;
};

namespace detail {

inline void compare_csr(FieldComparison& out, const std::string& field,
                        const rt::TransitionsCsr& expected, const rt::TransitionsCsr& actual,
                        std::uint64_t rows) {
  out.value(field + ".num_edges", expected.num_edges, actual.num_edges);
  if (expected.num_edges != actual.num_edges) return;
  out.array(field + ".choice_begin", expected.choice_begin, actual.choice_begin,
            expected.choice_begin == nullptr ? 0 : rows + 1);
  out.array(field + ".target", expected.target, actual.target, expected.num_edges);
  out.array(field + ".probability", expected.probability, actual.probability, expected.num_edges);
}

inline void compare_grid(FieldComparison& out, const rt::AbstractionView& expected,
                         const rt::AbstractionView& actual) {
  const rt::GridView& e = expected.grid;
  const rt::GridView& a = actual.grid;
  out.value("grid.dimension", e.dimension, a.dimension);
  if (e.dimension != a.dimension || e.dimension == 0) return;
  out.array("grid.axes", e.axes, a.axes, e.dimension);
  out.array("grid.break_begin", e.break_begin, a.break_begin, e.dimension + 1);
  if (a.break_begin == nullptr || e.break_begin[e.dimension] != a.break_begin[e.dimension]) return;
  out.array("grid.breaks", e.breaks, a.breaks, e.break_begin[e.dimension]);
}

inline void compare_bsp(FieldComparison& out, const rt::AbstractionView& expected,
                        const rt::AbstractionView& actual) {
  const rt::BspView& e = expected.bsp;
  const rt::BspView& a = actual.bsp;
  out.value("bsp.num_nodes", e.num_nodes, a.num_nodes);
  out.value("bsp.num_cells", e.num_cells, a.num_cells);
  if (e.num_nodes != a.num_nodes || expected.grid.dimension != actual.grid.dimension) return;
  out.array("bsp.normal", e.normal, a.normal, std::uint64_t{e.num_nodes} * expected.grid.dimension);
  out.array("bsp.bound", e.bound, a.bound, e.num_nodes);
  out.array("bsp.below", e.below, a.below, e.num_nodes);
  out.array("bsp.above", e.above, a.above, e.num_nodes);
  out.array("bsp.cell", e.cell, a.cell, e.num_nodes);
}

inline void compare_abstraction(FieldComparison& out, const rt::CatalogView& catalog,
                                const rt::AbstractionView& expected,
                                const rt::AbstractionView& actual) {
  out.text("context", expected.context, actual.context);
  out.value("num_blocks", expected.num_blocks, actual.num_blocks);
  if (expected.num_blocks != actual.num_blocks) return;
  const std::uint64_t blocks = expected.num_blocks;
  const std::uint64_t actions = catalog.num_actions;
  out.array("block_of", expected.block_of, actual.block_of, catalog.num_states);
  out.array("block_reward", expected.block_reward, actual.block_reward, blocks);
  compare_csr(out, "quotient", expected.quotient, actual.quotient, blocks * actions);
  out.array("reward", expected.reward, actual.reward, blocks * actions);
  out.array("policy", expected.policy, actual.policy, blocks);
  out.array("value", expected.value, actual.value, blocks);
  compare_csr(out, "state_transitions", expected.state_transitions, actual.state_transitions,
              std::uint64_t{catalog.num_states} * actions);
  compare_grid(out, expected, actual);
  compare_bsp(out, expected, actual);
  out.array("cell_block", expected.cell_block, actual.cell_block,
            expected.grid.dimension == 0 ? 0 : rt::partition_cells(expected));
  out.value("outside_block", expected.outside_block, actual.outside_block);
  out.value("epsilon", expected.epsilon, actual.epsilon);
  out.array("guarantee", expected.guarantee, actual.guarantee,
            std::uint64_t{catalog.properties.count} * rt::kGuaranteeFields);
}

inline void compare_observation(FieldComparison& out, const rt::CatalogView& catalog,
                                const rt::ObservationModel& expected,
                                const rt::ObservationModel& actual) {
  out.value("observation.kind", static_cast<std::uint32_t>(expected.kind),
            static_cast<std::uint32_t>(actual.kind));
  out.value("observation.p_correct", expected.p_correct, actual.p_correct);
  out.array("observation.confusion", expected.confusion, actual.confusion,
            std::uint64_t{catalog.num_states} * catalog.num_states);
  out.value("observation.reward_source", static_cast<std::uint32_t>(expected.reward_source),
            static_cast<std::uint32_t>(actual.reward_source));
  const rt::PositionNoise& e = expected.position;
  const rt::PositionNoise& a = actual.position;
  out.value("position.num_objects", e.num_objects, a.num_objects);
  if (e.num_objects != a.num_objects) return;
  out.array("position.object_of", e.object_of, a.object_of, catalog.state_dimension);
  out.array("position.sigma", e.sigma, a.sigma, std::uint64_t{e.num_objects} * 3);
  out.array("position.detection", e.detection, a.detection, e.num_objects);
}

}  // namespace detail

// Every field of `actual` against `expected`, but those in `not_carried`; the differences,
// one line each (empty: the same catalog).
inline std::vector<std::string> compare_catalogs(const rt::CatalogView& expected,
                                                 const rt::CatalogView& actual,
                                                 std::set<std::string> not_carried = {}) {
  FieldComparison out(std::move(not_carried));
  out.value("format", expected.format, actual.format);
  out.text("name", expected.name, actual.name);
  out.value("spec_hash", expected.spec_hash, actual.spec_hash);
  out.text("compiler_version", expected.compiler_version, actual.compiler_version);
  out.value("num_states", expected.num_states, actual.num_states);
  out.value("num_actions", expected.num_actions, actual.num_actions);
  out.value("num_abstractions", expected.num_abstractions, actual.num_abstractions);
  out.value("state_dimension", expected.state_dimension, actual.state_dimension);
  if (!out.differences().empty()) return out.differences();  // the sizes of all that follows
  out.texts("action_names", expected.action_names, actual.action_names, expected.num_actions);
  out.texts("state_names", expected.state_names, actual.state_names, expected.num_states);
  out.texts("variable_names", expected.variable_names, actual.variable_names,
            expected.state_dimension);
  out.value("properties.count", expected.properties.count, actual.properties.count);
  if (!out.differences().empty()) return out.differences();  // the guarantees' size
  out.texts("properties.names", expected.properties.names, actual.properties.names,
            expected.properties.count);
  out.texts("properties.texts", expected.properties.texts, actual.properties.texts,
            expected.properties.count);
  const std::uint64_t n = expected.num_abstractions;
  out.array("switching", expected.switching, actual.switching, n * n);
  out.array("prior", expected.prior, actual.prior, n);
  detail::compare_observation(out, expected, expected.observation, actual.observation);
  for (std::uint64_t i = 0; i < n; ++i) {
    out.enter("abstraction " + std::to_string(i));
    detail::compare_abstraction(out, expected, expected.abstractions[i], actual.abstractions[i]);
  }
  return out.differences();
}

}  // namespace oasis::test
