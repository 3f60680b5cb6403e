// bisimulate (stormpy's perform_bisimulation) and verify_partition (oasisc verify on a
// partition): the partition comes from the compiler's pipeline, as `oasisc quotient` computes
// it (pipeline::abstract_contexts), and the check from the independent verifier (verify/).

#include <algorithm>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "bisim/quotient.hpp"
#include "errors.hpp"
#include "interruptible.hpp"
#include "model_object.hpp"
#include "pipeline/discrete_catalog.hpp"
#include "verify/verifier.hpp"
#include "verify/violation.hpp"

namespace oasis::python {
namespace py = pybind11;

namespace {

struct Bisimulation {
  ModelPointer quotient;  // null under choices="unlabelled" (its choices have no names)
  std::vector<model::BlockIndex> block_of;
  model::BlockIndex nr_blocks = 0;
  std::string context;
};

struct PartitionCheck {
  bool bisimulation = false;
  bool coarsest = false;
  std::string message;  // the first violation, by state and action names; "" when both hold
};

// True/"all", False/"none", or a list of label names: the selection oasisc's
// --respect-labels takes.
model::LabelSelection label_selection(const py::handle& respect) {
  if (py::isinstance<py::bool_>(respect)) {
    return {respect.cast<bool>() ? model::LabelSelection::Kind::kAll
                                 : model::LabelSelection::Kind::kNone,
            {}};
  }
  std::string text;
  if (py::isinstance<py::str>(respect)) {
    text = respect.cast<std::string>();
  } else {
    for (const py::handle name : respect)
      text += (text.empty() ? "" : ",") + name.cast<std::string>();
  }
  const auto selection = model::LabelSelection::parse(text);
  if (!selection)
    throw py::value_error("respect_labels: expected True, False, 'all', 'none' or label names");
  return *selection;
}

std::vector<std::uint32_t> label_classes(const model::ExplicitModel& model,
                                         const model::LabelSelection& selection) {
  try {
    return model::label_classes(model.labels, model.num_states(), selection);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(std::string("respect_labels: ") + e.what());
  }
}

bool unlabelled(const std::string& choices) {
  if (choices != "labelled" && choices != "unlabelled")
    throw py::value_error("choices must be 'labelled' or 'unlabelled', not '" + choices + "'");
  return choices == "unlabelled";
}

// The quotient as a model of its own: the source's type, and the respected labels, which every
// member of a block holds alike (its smallest member speaks for it, as for its rows).
ModelPointer quotient_model(const model::ExplicitModel& model, std::size_t context,
                            const model::Partition& partition,
                            const model::LabelSelection& selection) {
  auto object = std::make_shared<ModelObject>();
  object->model = bisim::build_quotient(model, context, partition);
  object->model.type = model.type;
  if (model.labels.empty() || selection.kind == model::LabelSelection::Kind::kNone) return object;
  std::vector<std::string> names;
  for (const std::string& name : model.labels.names) {
    const bool respected =
        selection.kind == model::LabelSelection::Kind::kAll ||
        std::find(selection.names.begin(), selection.names.end(), name) != selection.names.end();
    if (respected) names.push_back(name);
  }
  model::StateLabelsBuilder labels(names);
  std::vector<bool> seen(partition.num_blocks, false);
  for (model::StateIndex s = 0; s < partition.num_states(); ++s) {
    const model::BlockIndex z = partition.block_of[s];
    if (seen[z]) continue;
    seen[z] = true;
    for (const std::uint32_t label : model.labels.of(s)) {
      const auto at = std::find(names.begin(), names.end(), model.labels.names[label]);
      if (at != names.end()) labels.add(z, static_cast<std::uint32_t>(at - names.begin()));
    }
  }
  object->model.labels = labels.finish(partition.num_blocks);
  return object;
}

Bisimulation bisimulate(const ModelPointer& object, const py::handle& respect_labels,
                        const std::string& choices, const py::handle& context,
                        std::optional<double> epsilon, unsigned jobs) {
  const model::ExplicitModel& model = object->model;
  const std::size_t c = context_index(model, context);
  const model::LabelSelection selection = label_selection(respect_labels);
  pipeline::DiscreteOptions options;
  options.unlabelled_choices = unlabelled(choices);
  options.rounding_step = epsilon;
  if (epsilon && !(*epsilon >= 1e-15 && *epsilon <= 0.5))
    throw py::value_error("epsilon must be in [1e-15, 0.5], as oasisc quotient --epsilon");
  if (epsilon && options.unlabelled_choices)
    throw py::value_error("choices='unlabelled' compares probabilities exactly: no epsilon");
  options.label_class = label_classes(model, selection);
  options.solve = false;
  options.jobs = jobs;
  return run_interruptible([&](const Cancellation& cancellation) {
    options.progress = [&](std::size_t, const bisim::RefinementProgress&) { cancellation.check(); };
    std::string error;
    auto results = pipeline::abstract_contexts(model, {c}, options, error);
    if (!results) throw Failure(ErrorKind::kError, error);
    Bisimulation result;
    model::Partition& partition = results->front().partition;
    if (!options.unlabelled_choices)
      result.quotient = quotient_model(model, c, partition, selection);
    result.nr_blocks = partition.num_blocks;
    result.block_of = std::move(partition.block_of);
    result.context = model.contexts[c].name;
    return result;
  });
}

PartitionCheck verify_partition(const ModelPointer& object,
                                const py::array_t<std::int64_t, py::array::forcecast>& blocks,
                                const py::handle& respect_labels, const std::string& choices,
                                const py::handle& context) {
  const model::ExplicitModel& model = object->model;
  const std::size_t c = context_index(model, context);
  const bool storm = unlabelled(choices);
  const std::vector<std::uint32_t> classes = label_classes(model, label_selection(respect_labels));
  model::Partition partition;
  const auto read = blocks.unchecked<1>();
  for (py::ssize_t s = 0; s < read.shape(0); ++s) {
    if (read(s) < 0 || read(s) > UINT32_MAX - 1)
      throw py::value_error("block numbers must be in [0, 2^32 - 1)");
    partition.block_of.push_back(static_cast<model::BlockIndex>(read(s)));
    partition.num_blocks = std::max(partition.num_blocks, partition.block_of.back() + 1);
  }
  return run_interruptible([&](const Cancellation&) {
    // The checks `oasisc verify` runs, in its order; the failing one's kind says how far the
    // partition got (shape, then Definition 1, then coarsest).
    const verify::VerificationResult checked =
        verify::verify_partition(model, c, partition, classes, storm);
    PartitionCheck result;
    result.coarsest = checked.ok();
    result.bisimulation =
        checked.ok() || (checked.violation->kind != verify::ViolationKind::PartitionShape &&
                         !verify::breaks_bisimulation(checked.violation->kind));
    if (!checked.ok()) result.message = checked.violation->message;
    return result;
  });
}

}  // namespace

void bind_bisimulation(py::module_& module) {
  py::class_<Bisimulation>(module, "Bisimulation", "The coarsest bisimulation of one context.")
      .def_property_readonly(
          "quotient",
          [](const Bisimulation& b) -> py::object {
            return b.quotient ? py::cast(b.quotient) : py::none();
          },
          "The quotient model: one state per block (z0, z1, ...), the source's type and its "
          "respected labels; None under choices='unlabelled'.")
      .def_property_readonly(
          "block_of",
          [](const py::object& self) {
            const auto& b = self.cast<const Bisimulation&>();
            return view(b.block_of.data(), b.block_of.size(), self);
          },
          "block_of[s]: the block of state s (read-only uint32, blocks numbered in order of "
          "their smallest state).")
      .def_readonly("nr_blocks", &Bisimulation::nr_blocks)
      .def_readonly("context", &Bisimulation::context)
      .def("__repr__", [](const Bisimulation& b) {
        return "<oasis.Bisimulation " + std::to_string(b.nr_blocks) + " blocks of " +
               std::to_string(b.block_of.size()) + " states>";
      });
  py::class_<PartitionCheck>(module, "PartitionCheck", "What verify_partition found.")
      .def_readonly("bisimulation", &PartitionCheck::bisimulation,
                    "Whether the partition is a bisimulation.")
      .def_readonly("coarsest", &PartitionCheck::coarsest,
                    "Whether it is the coarsest one (no two blocks could merge).")
      .def_readonly("message", &PartitionCheck::message,
                    "The first violation found, naming states and actions; '' when both hold.")
      .def("__bool__", [](const PartitionCheck& p) { return p.bisimulation && p.coarsest; })
      .def("__repr__", [](const PartitionCheck& p) {
        return std::string("<oasis.PartitionCheck bisimulation=") +
               (p.bisimulation ? "True" : "False") +
               " coarsest=" + (p.coarsest ? "True" : "False") + ">";
      });

  module.def("bisimulate", &bisimulate, py::arg("model"), py::arg("respect_labels") = true,
             py::arg("choices") = "labelled", py::arg("context") = py::none(),
             py::arg("epsilon") = py::none(), py::arg("jobs") = 0,
             "The coarsest bisimulation of one context, exact (as oasisc quotient). "
             "respect_labels: True (all labels, Storm's default), False, or label names. "
             "choices: 'labelled' (Definition 1: actions matched by name) or 'unlabelled' "
             "(Storm's MDP bisimulation). epsilon: compare probabilities rounded to multiples of "
             "it (approximate). Releases the GIL; Ctrl-C stops it.");
  module.def("verify_partition", &verify_partition, py::arg("model"), py::arg("blocks"),
             py::arg("respect_labels") = true, py::arg("choices") = "labelled",
             py::arg("context") = py::none(),
             "Checks with the independent verifier (oasisc verify) whether blocks[s] (one block "
             "number per state) is a bisimulation, and the coarsest.");
}

}  // namespace oasis::python
