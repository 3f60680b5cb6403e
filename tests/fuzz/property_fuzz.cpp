// The property language: lexer, parser and evaluator, over a fixed small MDP with labels,
// variables, constants, formulas and two reward structures. Every input ends with one answer
// per property, or with at least one printed error: an answer is never missing without a
// reason. The exact and sound answers of each property agree (the exact value lies in the
// sound interval), which checks both engines on whatever the fuzzer writes.

#include <optional>
#include <sstream>

#include "fuzz_target.hpp"
#include "prism/load_program.hpp"
#include "property/evaluator.hpp"
#include "property/parser.hpp"

namespace {

// An MDP with an end component (stay), a choice between two risks, and both kinds of reward.
constexpr const char* kModel = R"(mdp
const int N = 4;
formula far = x >= N - 1;
module m
  x : [0..4] init 0;
  b : bool init false;
  [stay] x < 4 -> (x'=x);
  [go] x < 4 -> 1/3 : (x'=x+1) + 2/3 : (x'=0) & (b'=!b);
  [jump] x = 0 -> 1/2 : (x'=2) + 1/2 : (x'=4);
  [] x = 4 -> true;
endmodule
label "goal" = x = 4;
label "odd" = b;
rewards "time" true : 1; endrewards
rewards "cost" [go] true : 2; [jump] x = 0 : 5; endrewards
)";

struct Model {
  oasis::SourceManager sources;
  std::optional<oasis::model::ExplicitModel> model;
  oasis::property::Names names;
};

const Model& fixed_model() {
  static Model* loaded = [] {
    auto* m = new Model;
    std::ostringstream messages;
    oasis::DiagnosticEngine diagnostics(m->sources, messages);
    oasis::prism::LoadOptions options;
    options.rewards = oasis::model::LabelSelection{};
    options.names = &m->names;
    m->model = oasis::prism::load_program_text(m->sources.add("model.nm", kModel), "model",
                                               diagnostics, options);
    FUZZ_REQUIRE(m->model.has_value());
    return m;
  }();
  return *loaded;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace oasis;
  const Model& fixed = fixed_model();
  SourceManager sources;
  std::ostringstream messages;
  DiagnosticEngine diagnostics(sources, messages);
  const property::PropertiesFile file =
      property::parse_file(sources.add("fuzz.props", fuzz::text_of(data, size)), diagnostics);
  if (diagnostics.error_count() != 0) {
    FUZZ_REQUIRE(messages.str().find(": error: ") != std::string::npos);
    return 0;
  }
  modelcheck::Options exact;
  exact.mode = modelcheck::Mode::kExact;
  exact.max_number_bits = 4096;
  modelcheck::Options sound;
  property::Evaluator exact_evaluator(*fixed.model, fixed.names, file, diagnostics, exact);
  property::Evaluator sound_evaluator(*fixed.model, fixed.names, file, diagnostics, sound);
  for (const property::Property& p : file.properties) {
    if (diagnostics.should_stop()) break;  // past the error limit errors are no longer counted
    const std::size_t errors = diagnostics.error_count();
    const auto a = exact_evaluator.answer(p);
    FUZZ_REQUIRE(a.has_value() || diagnostics.error_count() > errors);
    if (!a) continue;
    const auto b = sound_evaluator.answer(p);
    if (!b || a->kind != property::Answer::Kind::kNumber) continue;
    FUZZ_REQUIRE(b->kind == property::Answer::Kind::kNumber);
    FUZZ_REQUIRE(a->value.infinite == b->value.infinite);
    if (!a->value.infinite) {
      const double truth = a->value.exact.get_d();
      FUZZ_REQUIRE(b->value.lower <= truth + 1e-12 && truth <= b->value.upper + 1e-12);
    }
  }
  return 0;
}
