// compile (oasisc compile SPEC -o DIR): the catalog of a spec written as one unit into a
// directory, then loaded as the runtime loads it. The steps are those of the CLI's compile
// command, on the same library calls (input::load_model, pipeline::build_catalog or
// build_continuous_catalog, property::state_guarantees, codegen's writers, StagedDirectory), so
// the files are the same bytes; python/tests/test_cli_agreement.py compares them on every
// shipped spec. A model with an objective (a controller, docs/guarantees.md) is compiled by
// oasisc only.

#include <filesystem>

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "codegen/catalog_files.hpp"
#include "errors.hpp"
#include "input/model_loader.hpp"
#include "interruptible.hpp"
#include "pipeline/continuous_catalog.hpp"
#include "pipeline/continuous_options.hpp"
#include "pipeline/discrete_catalog.hpp"
#include "property/catalog_guarantees.hpp"
#include "support/staged_directory.hpp"

namespace oasis::python {
namespace py = pybind11;

namespace {

struct CompileRequest {
  codegen::CatalogFileOptions files;
  std::string output;
  std::optional<double> epsilon;
  std::optional<double> p_correct;
  unsigned jobs = 0;
};

struct Compiled {
  std::string catalog_path;  // "" when no binary catalog was asked for
  std::vector<std::string> warnings;
};

// The formats oasisc compile writes by default, and its refusals of the others.
void choose_formats(CompileRequest& request, bool continuous) {
  if (request.files.formats.empty())
    request.files.formats = codegen::default_catalog_formats(continuous);
  for (const std::string& format : request.files.formats) {
    if (format != "bin" && format != "json" && format != "dot" && format != "svg" &&
        format != "cpp")
      throw Failure(ErrorKind::kCompile,
                    "unknown format '" + format + "' (bin, json, dot, svg, cpp)");
  }
  if (codegen::unfitting_drawing(request.files, continuous) != nullptr) {
    throw Failure(ErrorKind::kCompile, continuous ? "dot draws explicit quotients; use svg"
                                                  : "svg draws continuous abstractions; use dot");
  }
}

bool write_discrete(const CompileRequest& request, const input::LoadedModel& loaded,
                    Diagnostics& diagnostics, const Cancellation& cancellation,
                    codegen::OutputSet& out, std::string& error) {
  pipeline::BuildOptions build;
  build.catalog.p_correct = request.p_correct;
  build.abstraction.jobs = request.jobs;
  build.abstraction.progress = [&](std::size_t, const bisim::RefinementProgress&) {
    cancellation.check();
  };
  auto catalog = pipeline::build_catalog(*loaded.model, loaded.source_hash, build, error);
  if (!catalog) throw Failure(ErrorKind::kCompile, request.files.spec + ": " + error);
  if (!property::state_guarantees(*loaded.model, loaded.names, loaded.properties, *catalog,
                                  diagnostics.engine()))
    diagnostics.fail(ErrorKind::kSpec, "a stated property could not be answered");
  return codegen::write_discrete_catalog(request.files, *catalog, out, error);
}

bool write_continuous(const CompileRequest& request, const input::LoadedModel& loaded,
                      const Cancellation& cancellation, codegen::OutputSet& out,
                      std::vector<std::string>& warnings, std::string& error) {
  pipeline::ContinuousCatalogOptions build;
  build.abstraction.target = pipeline::continuous_target(*loaded.ir, {request.epsilon, {}});
  build.abstraction.keep_rows = request.files.with_transitions;
  build.jobs = request.jobs;
  std::mutex lock;
  build.abstraction.warn = [&](const std::string& context, const std::string& warning) {
    const std::lock_guard guard(lock);
    warnings.push_back("context \"" + context + "\": " + warning);
  };
  build.abstraction.progress = [&](const std::string&, const std::string&, double) {
    cancellation.check();
  };
  const auto catalog =
      pipeline::build_continuous_catalog(*loaded.ir, loaded.source_hash, build, error);
  if (!catalog) throw Failure(ErrorKind::kCompile, request.files.spec + ": " + error);
  return codegen::write_continuous_catalog(request.files, *catalog, out, error);
}

Compiled compile_spec(CompileRequest& request, const Cancellation& cancellation) {
  Compiled compiled;
  Diagnostics diagnostics;
  input::LoadOptions load;
  load.on_progress = [&](std::uint64_t, std::uint64_t) { cancellation.check(); };
  const auto loaded =
      input::load_model(request.files.spec, diagnostics.sources(), diagnostics.engine(), load);
  if (!loaded || diagnostics.has_errors())
    diagnostics.fail(ErrorKind::kSpec, "cannot load the spec");
  const bool continuous = !loaded->model;
  if (continuous && loaded->ir->guarantee) {
    throw Failure(ErrorKind::kCompile, request.files.spec +
                                           ": a model with an objective compiles to a controller "
                                           "(docs/guarantees.md): use oasisc compile");
  }
  choose_formats(request, continuous);
  if (continuous && request.p_correct)
    throw Failure(ErrorKind::kCompile, "robust= needs explicit states (a discrete model)");
  if (!continuous && request.epsilon) {
    compiled.warnings.push_back(
        "epsilon is the error bound of continuous specs and is ignored here: a discrete "
        "catalog is an exact bisimulation");
  }
  if (request.output.empty())
    request.output = std::filesystem::path(request.files.spec).stem().string();
  StagedDirectory directory;
  std::string error;
  if (!directory.open(request.output, error))
    throw Failure(ErrorKind::kCompile, request.output + ": " + error);
  codegen::OutputSet out(directory.staging_path());
  const bool written =
      continuous ? write_continuous(request, *loaded, cancellation, out, compiled.warnings, error)
                 : write_discrete(request, *loaded, diagnostics, cancellation, out, error);
  cancellation.check();  // the last moment to stop with nothing written
  if (!written ||
      !directory.commit(codegen::marker_text(request.files, loaded->source_hash, out), error))
    throw Failure(ErrorKind::kCompile, request.output + ": " + error);
  for (const std::string& name : out.names()) {
    if (name.ends_with(".bin"))
      compiled.catalog_path = (std::filesystem::path(request.output) / name).string();
  }
  return compiled;
}

py::object compile(const std::string& spec, const std::optional<std::string>& out_dir,
                   std::optional<double> epsilon, unsigned jobs,
                   const std::optional<std::vector<std::string>>& formats,
                   std::optional<double> robust) {
  CompileRequest request;
  request.files.spec = spec;
  if (formats) request.files.formats = *formats;
  request.output = out_dir.value_or("");
  request.epsilon = epsilon;
  if (epsilon && !(*epsilon > 0 && std::isfinite(*epsilon)))
    throw py::value_error("epsilon must be a positive number");
  if (robust && !(*robust > 0 && *robust <= 1)) throw py::value_error("robust must be in (0, 1]");
  request.p_correct = robust;
  request.jobs = jobs;
  const Compiled compiled = run_interruptible(
      [&](const Cancellation& cancellation) { return compile_spec(request, cancellation); });
  for (const std::string& warning : compiled.warnings) {
    if (PyErr_WarnEx(PyExc_UserWarning, warning.c_str(), 1) != 0) throw py::error_already_set();
  }
  if (compiled.catalog_path.empty()) return py::none();
  return load_catalog(compiled.catalog_path, std::nullopt);
}

}  // namespace

void bind_compile(py::module_& module) {
  module.def("compile", &compile, py::arg("spec"), py::arg("out_dir") = py::none(),
             py::arg("epsilon") = py::none(), py::arg("jobs") = 0, py::arg("formats") = py::none(),
             py::arg("robust") = py::none(),
             "Compiles a spec's catalog into out_dir (default: the spec's stem) as oasisc "
             "compile does, byte for byte: the directory changes as one unit, and Ctrl-C leaves "
             "it as it was. formats: bin, json, dot (discrete), svg (continuous), cpp; epsilon: "
             "the error bound of a continuous spec; robust: the probability of a correct state "
             "reading (adds the robust filter's section); jobs: threads (0: one per core). "
             "Returns the Catalog loaded from the binary file (None without 'bin').");
}

}  // namespace oasis::python
