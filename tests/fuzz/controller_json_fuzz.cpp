// oasisc verify's reader of a controller file (verify/controller_reader.hpp, the document
// codegen/controller_json.hpp writes): any text is refused with a reason or read; a file that
// reads is then checked against a small model with an objective (verify/controller_check.hpp),
// structure and a short Monte-Carlo run, which must answer every check with a verdict, never
// crash, whatever the file's sizes, indices and numbers say.

#include <optional>
#include <sstream>
#include <string>

#include "frontend/load_spec.hpp"
#include "fuzz_target.hpp"
#include "verify/controller_check.hpp"
#include "verify/controller_reader.hpp"

namespace {

// The model every file is checked against: 2-D, one input, a bounded reach-avoid objective.
const oasis::model::ModelIR& fuzz_model() {
  static const oasis::model::ModelIR ir = [] {
    oasis::SourceManager sources;
    std::ostringstream messages;
    oasis::DiagnosticEngine diagnostics(sources, messages);
    auto checked = oasis::frontend::check_spec_text(
        sources.add("fuzz.oasis",
                    "mdp swing {\n"
                    "  continuous x : [-2 .. 2];\n"
                    "  continuous v : [-2 .. 2];\n"
                    "  input u in {-1, 0, 1};\n"
                    "  actions push;\n"
                    "  disturbance x ~ gaussian(0, 0.2);\n"
                    "  disturbance v in [-0.1 .. 0.1];\n"
                    "  dynamics [push] { x' = x + 0.1 * v; v' = v + 0.1 * sin(x) + 0.2 * u; }\n"
                    "  region home = x >= -0.5 & x <= 0.5;\n"
                    "  objective reach home while v <= 1.5 steps 3;\n"
                    "  grid x : 2, v : 2;\n"
                    "}\n"),
        diagnostics);
    return std::move(*checked);
  }();
  return ir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace oasis;
  std::string error;
  const std::optional<verify::ControllerFile> file =
      verify::parse_controller_file(fuzz::text_of(data, size), error);
  if (!file) {
    FUZZ_REQUIRE(!error.empty());
    return 0;
  }
  verify::MonteCarloSettings settings;
  settings.samples = 20;
  settings.cells = 4;
  settings.max_steps = 20;
  for (const verify::CatalogCheck& check : verify::check_controller(fuzz_model(), *file, settings))
    FUZZ_REQUIRE(!check.verdict.empty());
  return 0;
}
