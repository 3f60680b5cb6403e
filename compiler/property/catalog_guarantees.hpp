#pragma once
// The values a catalog states for its spec's properties (docs/properties.md, "Properties in
// catalogs"): every `property NAME = ...;` answered in every context twice, once with the
// context's compiled policy acting (the Markov chain it induces on the model's states, each
// state taking its block's action) and once at the optimum its operator names (Pmax, Rmin...).
// Values are exact where the model allows it (stored as the two doubles around each rational,
// the fraction itself in the JSON) and sound intervals past it, as `oasisc query --mode auto`
// answers.
//
// `compile` answers on bisimulation quotients (Evaluator::use_bisimulation); `verify`
// recomputes every value on the model itself, with the policy it reads from the catalog, and
// compares (check_guarantees).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "model/catalog_data.hpp"
#include "model/explicit_model.hpp"
#include "oasis/rt/catalog_view.hpp"
#include "property/evaluator.hpp"
#include "property/property.hpp"

namespace oasis::property {

// Parses a spec's stated properties (its `property` items), one file each, errors
// placed in the spec: one property per item, a number to answer (=?), no definitions.
// nullopt after reporting errors.
std::optional<std::vector<PropertiesFile>> parse_stated_properties(
    const std::vector<model::PropertySource>& sources, DiagnosticEngine& diagnostics);

// Answers `properties` (parse_stated_properties) in every context of `catalog` and stores
// them there: catalog.properties and every abstraction's guarantee and guarantee_exact. The
// policy of abstraction i is read from the catalog itself (block_of, policy). False after
// reporting errors located in the spec.
bool state_guarantees(const model::ExplicitModel& model, const Names& names,
                      const std::vector<PropertiesFile>& properties, model::CatalogData& catalog,
                      DiagnosticEngine& diagnostics);

// One verdict of check_guarantees: a property in a context, or the list of properties.
struct GuaranteeVerdict {
  std::string item;  // "property NAME in context C", or "properties"
  std::string verdict;
  bool ok = false;
};

// verify's check: the catalog states exactly the spec's properties (names and texts), and
// each stated interval holds the value recomputed here on the model itself (no quotient)
// under the catalog's own policy and at the optimum: it contains the exact value, or meets
// the recomputed sound interval, and is no wider than 10^-6 (a probability's or reward's
// stated interval may not be made wider to hide a wrong value).
std::vector<GuaranteeVerdict> check_guarantees(const model::ExplicitModel& model,
                                               const Names& names,
                                               const std::vector<PropertiesFile>& properties,
                                               const rt::CatalogView& catalog,
                                               DiagnosticEngine& diagnostics);

}  // namespace oasis::property
