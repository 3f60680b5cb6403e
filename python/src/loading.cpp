// Models into Python: parse_prism_program and build_model (stormpy's two steps), load_model
// for any file oasisc reads. The work is the compiler's: prism::load_program_text and
// input::load_model, with the module's diagnostics and a progress callback that stops on
// Ctrl-C.

#include <filesystem>

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "command_line/memory_budget.hpp"
#include "errors.hpp"
#include "input/model_loader.hpp"
#include "interruptible.hpp"
#include "model_object.hpp"
#include "prism/checker.hpp"
#include "prism/lexer.hpp"
#include "prism/load_program.hpp"
#include "prism/parser.hpp"
#include "support/input_validation.hpp"
#include "support/limits.hpp"
#include "support/mapped_file.hpp"

namespace oasis::python {
namespace py = pybind11;

namespace {

// A checked PRISM program, kept as its text and constants; build_model explores it. What it
// declares is read once, when it is parsed.
struct PrismProgram {
  std::string path;
  std::string text;
  std::string constants;  // "N=4,p=0.1", as oasisc --const takes them
  std::string name;
  std::string model_type;
  std::vector<std::string> labels;
  std::vector<std::string> reward_models;
  std::vector<std::string> variables;
};

// A Python value as PRISM's command line writes it: true/false, an integer, a decimal.
std::string constant_text(const py::handle& value) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::int_>(value)) return py::str(value).cast<std::string>();
  if (py::isinstance<py::float_>(value)) return py::repr(value).cast<std::string>();
  const py::object fraction_type = py::module_::import("fractions").attr("Fraction");
  if (py::isinstance(value, fraction_type)) return py::str(value).cast<std::string>();
  throw py::type_error("a constant's value must be a bool, an int, a float or a Fraction, not " +
                       py::str(py::type::of(value)).cast<std::string>());
}

std::string constants_text(const std::optional<py::dict>& constants) {
  std::string text;
  if (!constants) return text;
  for (const auto& [name, value] : *constants) {
    if (!text.empty()) text += ',';
    text += py::str(name).cast<std::string>() + "=" + constant_text(value);
  }
  return text;
}

// "all", "none" or "a,b" for the loader's --rewards, from None, "all", "none" or a list.
std::string rewards_text(const py::handle& rewards) {
  if (rewards.is_none()) return "none";
  if (py::isinstance<py::str>(rewards)) return rewards.cast<std::string>();  // all, none, a name
  std::string text;
  for (const py::handle name : rewards) {
    if (!text.empty()) text += ',';
    text += name.cast<std::string>();
  }
  if (text.empty()) return "none";
  if (!model::LabelSelection::parse(text)) throw py::value_error("empty reward structure name");
  return text;
}

std::string read_text(const std::string& path, Diagnostics& diagnostics) {
  MappedFile contents;
  std::string reason;
  if (!contents.open(path, limits::kDefaultMaxSpecBytes, reason)) {
    diagnostics.engine().file_error(path, "cannot read PRISM program: " + reason);
    diagnostics.fail(ErrorKind::kSpec, reason);
  }
  return std::string(contents.text());
}

PrismProgram parse_prism_program(const std::string& path,
                                 const std::optional<py::dict>& constants) {
  PrismProgram program;
  program.path = path;
  program.constants = constants_text(constants);
  Diagnostics diagnostics;
  program.text = read_text(path, diagnostics);
  const FileId file = diagnostics.sources().add(path, program.text);
  if (!validate_input(file, diagnostics.engine())) diagnostics.fail(ErrorKind::kSpec, "bad input");
  const auto tokens = prism::lex(file, diagnostics.engine());
  const auto tree = prism::parse(tokens, diagnostics.engine());
  if (diagnostics.has_errors()) diagnostics.fail(ErrorKind::kSpec, "syntax errors");
  prism::CheckOptions options;
  options.constants = program.constants;
  options.rewards = model::LabelSelection{model::LabelSelection::Kind::kAll, {}};
  program.name = std::filesystem::path(path).stem().string();
  const auto checked = prism::check(tree, program.name, diagnostics.engine(), options);
  if (!checked) diagnostics.fail(ErrorKind::kSpec, "the program does not check");
  program.model_type = checked->type == prism::ModelType::Dtmc ? "dtmc" : "mdp";
  for (const prism::Label& label : checked->labels)
    program.labels.push_back(label.name);
  for (const prism::RewardStructure& rewards : checked->rewards)
    program.reward_models.push_back(rewards.name);
  for (const model::DiscreteVariable& variable : checked->variables)
    program.variables.push_back(variable.name);
  return program;
}

ModelPointer build_program(const PrismProgram& program, const std::string& rewards,
                           std::uint32_t max_states) {
  return run_interruptible([&](const Cancellation& cancellation) {
    auto object = std::make_shared<ModelObject>();
    object->path = program.path;
    Diagnostics diagnostics;
    const FileId file = diagnostics.sources().add(program.path, program.text);
    prism::LoadOptions options;
    options.constants = program.constants;
    options.rewards = model::LabelSelection::parse(rewards).value_or(model::LabelSelection{});
    options.names = &object->names;
    options.explore.max_states = max_states;
    options.explore.progress = [&](std::uint64_t, std::uint64_t) { cancellation.check(); };
    auto model = prism::load_program_text(file, program.name, diagnostics.engine(), options);
    if (!model) diagnostics.fail(ErrorKind::kSpec, "the program could not be built");
    object->model = std::move(*model);
    return object;
  });
}

// What oasisc's default --memory-budget ("auto") allows, 0 when the machine's memory is
// unknown: a model file whose header declares more than reading it could fit is refused at
// once (formats/model_size.hpp), before Python's process asks for it.
std::uint64_t default_memory_budget() {
  std::string ignored;
  return parse_memory_budget("auto", ignored).value_or(0);
}

ModelPointer load_file(const std::string& path, const std::optional<py::dict>& constants,
                       const py::handle& rewards, std::uint32_t max_states) {
  input::LoadOptions options;
  options.constants = constants_text(constants);
  options.rewards = rewards_text(rewards);
  options.hash_source = false;
  options.max_states = max_states;
  options.memory_budget = default_memory_budget();
  return run_interruptible([&](const Cancellation& cancellation) {
    options.on_progress = [&](std::uint64_t, std::uint64_t) { cancellation.check(); };
    Diagnostics diagnostics;
    auto loaded = input::load_model(path, diagnostics.sources(), diagnostics.engine(), options);
    if (!loaded || diagnostics.has_errors())
      diagnostics.fail(ErrorKind::kSpec, "cannot load " + path);
    if (!loaded->model) {
      throw Failure(ErrorKind::kError,
                    path + ": a continuous spec has no explicit model; compile() partitions it");
    }
    auto object = std::make_shared<ModelObject>();
    object->path = path;
    object->model = std::move(*loaded->model);
    object->names = std::move(loaded->names);
    return object;
  });
}

}  // namespace

void bind_loading(py::module_& module) {
  py::class_<PrismProgram>(module, "PrismProgram",
                           "A checked PRISM program (dtmc or mdp) with its constants' values; "
                           "build_model explores it.")
      .def_readonly("path", &PrismProgram::path)
      .def_readonly("name", &PrismProgram::name, "The file's stem, the model's name.")
      .def_readonly("model_type", &PrismProgram::model_type, "'dtmc' or 'mdp'.")
      .def_readonly("constants", &PrismProgram::constants,
                    "The constants given, as oasisc --const writes them.")
      .def_readonly("labels", &PrismProgram::labels)
      .def_readonly("reward_models", &PrismProgram::reward_models,
                    "The reward structures' names (an unnamed one is 'rewardsN').")
      .def_readonly("variables", &PrismProgram::variables)
      .def("__repr__", [](const PrismProgram& p) {
        return "<oasis.PrismProgram '" + p.name + "' " + p.model_type + ">";
      });

  module.def("parse_prism_program", &parse_prism_program, py::arg("path"),
             py::arg("constants") = py::none(),
             "Reads and checks a PRISM program (.pm, .nm, .prism). `constants` gives values to "
             "constants the program leaves undefined, e.g. {'N': 4, 'p': 0.1}. Raises SpecError "
             "with every problem located.");
  module.def(
      "build_model",
      [](const PrismProgram& program, const py::handle& rewards, std::uint32_t max_states) {
        return build_program(program, rewards_text(rewards), max_states);
      },
      py::arg("program"), py::arg("rewards") = py::none(),
      py::arg("max_states") = limits::kDefaultMaxStates,
      "Explores a PRISM program into an explicit Model. `rewards` names the reward structures "
      "that become the model's contexts ('all', or a list); none by default, as Storm builds "
      "a reward model only when asked. Releases the GIL; Ctrl-C stops it.");
  module.def("load_model", &load_file, py::arg("path"), py::arg("constants") = py::none(),
             py::arg("rewards") = py::none(), py::arg("max_states") = limits::kDefaultMaxStates,
             "Loads any model oasisc reads, as it reads it: a spec (.oasis), a PRISM program "
             "(.pm, .nm, .prism), or an explicit model (.aut, .tra with its .lab/.srew/.trew, "
             ".drn, .umb). Raises SpecError with every problem located, also when a model "
             "file's header declares more than 75% of the machine's memory could hold.");
}

}  // namespace oasis::python
