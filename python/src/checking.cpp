// check (stormpy's model_checking): one PRISM property answered on a model by the compiler's
// evaluator (property/evaluator.hpp), exactly (a Fraction) or with a sound interval, as
// `oasisc query` answers it, with the optimal scheduler when asked.

#include <cmath>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "errors.hpp"
#include "interruptible.hpp"
#include "model_object.hpp"
#include "modelcheck/number_limits.hpp"
#include "property/evaluator.hpp"
#include "property/parser.hpp"
#include "support/input_validation.hpp"

namespace oasis::python {
namespace py = pybind11;

namespace {

// exact=True, False or "auto" (oasisc query --mode auto: exact up to a size, else sound).
modelcheck::Mode mode_of(const py::handle& exact, const model::ExplicitModel& model,
                         bool& automatic) {
  automatic = false;
  if (py::isinstance<py::bool_>(exact))
    return exact.cast<bool>() ? modelcheck::Mode::kExact : modelcheck::Mode::kSound;
  if (py::isinstance<py::str>(exact) && exact.cast<std::string>() == "auto") {
    automatic = true;
    return model.num_states() <= modelcheck::kAutoExactStates ? modelcheck::Mode::kExact
                                                              : modelcheck::Mode::kSound;
  }
  throw py::value_error("exact must be True, False or 'auto'");
}

void require_shared_transitions(const ModelObject& object) {
  const model::ExplicitModel& model = object.model;
  for (const model::Context& context : model.contexts) {
    if (context.transitions != model.contexts.front().transitions) {
      throw Failure(ErrorKind::kError,
                    "context '" + context.name +
                        "' has transitions of its own: properties are answered on models whose "
                        "contexts share theirs (as oasisc query)");
    }
  }
}

// The answer in Python: a Fraction (exact), an Interval (sound), a bool (P>=b), math.inf.
py::object value_of(const property::Answer& answer) {
  if (answer.kind == property::Answer::Kind::kTruth) return py::bool_(answer.verdict);
  if (answer.value.infinite) return py::float_(INFINITY);
  if (answer.mode == modelcheck::Mode::kExact) return fraction(answer.value.exact);
  return py::module_::import("oasis.results")
      .attr("Interval")(answer.value.lower, answer.value.upper);
}

py::object scheduler_of(const property::Answer& answer, const model::ExplicitModel& model) {
  if (!answer.scheduler) return py::none();
  const auto to_array = [](const std::vector<model::ActionIndex>& actions) {
    std::vector<std::int64_t> values(actions.size());
    for (std::size_t s = 0; s < actions.size(); ++s)
      values[s] = actions[s] == modelcheck::Scheduler::kAnyAction ? -1 : std::int64_t{actions[s]};
    return owned(std::move(values));
  };
  py::object memoryless = py::none();
  if (!answer.scheduler->action.empty()) memoryless = to_array(answer.scheduler->action);
  py::list by_step;
  for (const auto& step : answer.scheduler->by_step)
    by_step.append(to_array(step));
  return py::module_::import("oasis.results").attr("Scheduler")(memoryless, by_step, model.actions);
}

py::object check(const ModelPointer& object, const std::string& text, const py::handle& exact,
                 double precision, bool scheduler, bool bisimulation,
                 std::uint32_t max_exact_states) {
  const model::ExplicitModel& model = object->model;
  require_shared_transitions(*object);
  bool automatic = false;
  modelcheck::Options options;
  options.mode = mode_of(exact, model, automatic);
  if (!(precision > 0 && precision < 1)) throw py::value_error("precision must be in (0, 1)");
  options.precision = precision;
  if (automatic)
    options.max_number_bits = std::min(options.max_number_bits, modelcheck::kAutoExactNumberBits);
  options.want_scheduler = scheduler;
  options.max_exact_states = max_exact_states;
  property::Answer answer = run_interruptible([&](const Cancellation& cancellation) {
    options.progress = [&](const std::string&) { cancellation.check(); };
    Diagnostics diagnostics;
    const FileId file = diagnostics.sources().add("property", text);
    if (!validate_input(file, diagnostics.engine()))
      diagnostics.fail(ErrorKind::kProperty, "bad property text");
    const property::PropertiesFile properties = property::parse_file(file, diagnostics.engine());
    if (diagnostics.has_errors()) diagnostics.fail(ErrorKind::kProperty, "bad property");
    if (properties.properties.size() != 1) {
      throw Failure(ErrorKind::kProperty, "check() answers one property; got " +
                                              std::to_string(properties.properties.size()));
    }
    property::Evaluator evaluator(model, object->names, properties, diagnostics.engine(), options);
    evaluator.allow_sound_fallback(automatic);
    evaluator.use_bisimulation(bisimulation);
    std::optional<property::Answer> result = evaluator.answer(properties.properties.front());
    if (!result) {
      // The evaluator reports a refused exact solve as an error located in the property, with
      // the engine's message, which always ends in the same suggestion.
      const std::string refused = modelcheck::suggest_sound_mode("");
      const bool limit = diagnostics.any_message(
          [&](const std::string& message) { return message.ends_with(refused); });
      diagnostics.fail(limit ? ErrorKind::kExactLimit : ErrorKind::kProperty,
                       "the property could not be answered");
    }
    return std::move(*result);
  });
  py::object value = value_of(answer);
  if (!scheduler) return value;
  return py::make_tuple(value, scheduler_of(answer, model));
}

}  // namespace

void bind_check(py::module_& module) {
  module.def("check", &check, py::arg("model"), py::arg("property"), py::arg("exact") = true,
             py::arg("precision") = 1e-6, py::arg("scheduler") = false,
             py::arg("bisimulation") = false, py::arg("max_exact_states") = 1'000'000,
             "Answers one PRISM property (P, R, their min/max forms, bounds, filters) in the "
             "model's initial state, as oasisc query. exact=True: a fractions.Fraction (or "
             "True/False for a bound, math.inf for an infinite reward); exact=False: an "
             "Interval(lower, upper) proven to contain the value, at most `precision` wide; "
             "'auto': exact up to 100,000 states, else sound. bisimulation=True solves on the "
             "coarsest quotient that respects the property. The exact solve gives up past "
             "max_exact_states states in one strongly connected part. scheduler=True returns "
             "(value, Scheduler). "
             "Raises PropertyError (located), ExactLimitError when the exact solve is refused. "
             "Releases the GIL; Ctrl-C stops it.");
}

}  // namespace oasis::python
