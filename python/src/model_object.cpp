#include "model_object.hpp"

#include <algorithm>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "support/rational.hpp"

namespace oasis::python {
namespace py = pybind11;

namespace {

const model::TransitionMatrix& matrix_of(const ModelObject& object, const py::handle& context) {
  return *object.model.contexts[context_index(object.model, context)].transitions;
}

void check_state(const model::ExplicitModel& model, std::uint32_t state) {
  if (state >= model.num_states()) {
    throw py::index_error("state " + std::to_string(state) +
                          " is not a state of the model (it has " +
                          std::to_string(model.num_states()) + ")");
  }
}

model::ActionIndex action_index(const model::ExplicitModel& model, const py::handle& action) {
  if (py::isinstance<py::str>(action)) {
    const auto name = action.cast<std::string>();
    for (model::ActionIndex a = 0; a < model.num_actions(); ++a)
      if (model.actions[a] == name) return a;
    throw py::value_error("the model has no action '" + name + "'");
  }
  const auto a = action.cast<std::uint32_t>();
  if (a >= model.num_actions()) throw py::index_error("no action " + std::to_string(a));
  return a;
}

// The CSR arrays of one context for scipy.sparse: rows are choices (state * nr_actions +
// action), so a Markov chain's matrix is square. Index arrays are views; the doubles are new.
py::tuple csr(const ModelPointer& object, const py::handle& context) {
  const model::TransitionMatrix& matrix = matrix_of(*object, context);
  const py::object owner = py::cast(object);
  std::vector<double> data(matrix.num_edges());
  for (std::size_t e = 0; e < data.size(); ++e)
    data[e] = to_double(object->model.values[matrix.edge_probability[e]]);
  const std::size_t rows = std::size_t{matrix.num_states} * matrix.num_actions;
  return py::make_tuple(view(matrix.choice_begin.data(), matrix.choice_begin.size(), owner),
                        view(matrix.edge_target.data(), matrix.edge_target.size(), owner),
                        owned(std::move(data)), py::make_tuple(rows, matrix.num_states));
}

// Every entry's exact probability, in the order of the CSR arrays. Each distinct value is
// made into a Fraction once.
py::list exact_probabilities(const ModelObject& object, const py::handle& context) {
  const model::TransitionMatrix& matrix = matrix_of(object, context);
  std::vector<py::object> made(object.model.values.size());
  py::list entries;
  for (const ValueId id : matrix.edge_probability) {
    if (!made[id]) made[id] = fraction(object.model.values[id]);
    entries.append(made[id]);
  }
  return entries;
}

py::object probability(const ModelObject& object, std::uint32_t state, const py::handle& action,
                       std::uint32_t target, const py::handle& context) {
  const model::ExplicitModel& model = object.model;
  check_state(model, state);
  check_state(model, target);
  const model::ActionIndex a = action_index(model, action);
  const model::TransitionMatrix& matrix = matrix_of(object, context);
  for (model::EdgeIndex e = matrix.edges_begin(state, a); e < matrix.edges_end(state, a); ++e)
    if (matrix.edge_target[e] == target) return fraction(model.values[matrix.edge_probability[e]]);
  return fraction(Rational(0));
}

py::array_t<double> doubles(const ModelObject& object, const std::vector<ValueId>& ids) {
  std::vector<double> values(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i)
    values[i] = to_double(object.model.values[ids[i]]);
  return owned(std::move(values));
}

py::list states_with_label(const ModelObject& object, const std::string& name) {
  const model::StateLabels& labels = object.model.labels;
  const auto label = labels.find(name);
  if (!label) throw py::key_error("the model has no label '" + name + "'");
  py::list states;
  for (std::uint32_t s = 0; s < object.model.num_states(); ++s) {
    const auto held = labels.of(s);
    if (std::find(held.begin(), held.end(), *label) != held.end()) states.append(s);
  }
  return states;
}

py::list labels_of_state(const ModelObject& object, std::uint32_t state) {
  check_state(object.model, state);
  py::list names;
  for (const std::uint32_t label : object.model.labels.of(state))
    names.append(object.model.labels.names[label]);
  return names;
}

py::object valuations(const ModelPointer& object) {
  const model::StateSpace& states = object->model.states;
  if (states.variables.empty()) return py::none();
  return view(states.valuations.data(), states.size, states.variables.size(), py::cast(object));
}

std::vector<std::string> context_names(const ModelObject& object) {
  std::vector<std::string> names;
  for (const model::Context& context : object.model.contexts)
    names.push_back(context.name);
  return names;
}

std::string describe(const ModelObject& object) {
  const model::ExplicitModel& model = object.model;
  return "<oasis.Model '" + model.name + "' " +
         (model.type == model::ModelType::kDtmc ? "dtmc" : "mdp") + ", " +
         std::to_string(model.num_states()) + " states, " +
         std::to_string(model.contexts.front().transitions->num_edges()) + " transitions>";
}

}  // namespace

std::size_t context_index(const model::ExplicitModel& model, const py::handle& context) {
  if (context.is_none()) return 0;
  if (py::isinstance<py::str>(context)) {
    const auto name = context.cast<std::string>();
    for (std::size_t c = 0; c < model.contexts.size(); ++c)
      if (model.contexts[c].name == name) return c;
    throw py::value_error("the model has no context (reward structure) '" + name + "'");
  }
  const auto c = context.cast<std::size_t>();
  if (c >= model.contexts.size()) {
    throw py::index_error("context " + std::to_string(c) + " out of range (the model has " +
                          std::to_string(model.contexts.size()) + ")");
  }
  return c;
}

py::object fraction(const Rational& value) {
  // Looked up once and kept for the life of the process (never released: no destructor runs
  // after the interpreter is gone).
  static const py::handle type =
      py::object(py::module_::import("fractions").attr("Fraction")).release();
  return type(py::int_(py::str(value.get_num().get_str())),
              py::int_(py::str(value.get_den().get_str())));
}

void bind_model(py::module_& module) {
  const py::none none;
  py::class_<ModelObject, ModelPointer>(module, "Model",
                                        "An explicit model: states, actions, contexts (reward "
                                        "structures), labels and exact transition probabilities.")
      .def_property_readonly(
          "name", [](const ModelObject& o) { return o.model.name; }, "The model's name.")
      .def_property_readonly(
          "model_type",
          [](const ModelObject& o) {
            return o.model.type == model::ModelType::kDtmc ? "dtmc" : "mdp";
          },
          "'dtmc' or 'mdp'.")
      .def_property_readonly(
          "nr_states", [](const ModelObject& o) { return o.model.num_states(); },
          "The number of states.")
      .def_property_readonly(
          "nr_actions", [](const ModelObject& o) { return o.model.num_actions(); },
          "The number of actions (a Markov chain has one).")
      .def_property_readonly(
          "actions", [](const ModelObject& o) { return o.model.actions; }, "The action names.")
      .def_property_readonly(
          "nr_choices",
          [](const ModelObject& o) {
            return o.model.contexts.front().transitions->num_enabled_choices();
          },
          "The enabled (state, action) pairs of the first context.")
      .def_property_readonly(
          "nr_transitions",
          [](const ModelObject& o) { return o.model.contexts.front().transitions->num_edges(); },
          "The nonzero entries of the first context's transition matrix.")
      .def_property_readonly(
          "initial_states", [](const ModelObject& o) { return o.model.states.initial; },
          "The initial states, ascending.")
      .def_property_readonly("contexts", &context_names,
                             "The contexts' names: a PRISM program's reward structures chosen "
                             "with build_model(rewards=...), or a spec's contexts.")
      .def_property_readonly(
          "labels", [](const ModelObject& o) { return o.model.labels.names; },
          "The atomic propositions (labels) of the model.")
      .def("states_with_label", &states_with_label, py::arg("label"),
           "The states where `label` holds, ascending.")
      .def("labels_of_state", &labels_of_state, py::arg("state"),
           "The labels that hold in `state`.")
      .def(
          "state_name",
          [](const ModelObject& o, std::uint32_t s) {
            check_state(o.model, s);
            return o.model.states.name(s);
          },
          py::arg("state"), "The state's name: '(x=1,y=0)' for a factored model.")
      .def_property_readonly(
          "variables", [](const ModelObject& o) { return o.model.states.variables; },
          "The state variables of a factored model (a PRISM program, a spec); [] otherwise.")
      .def_property_readonly("state_valuations", &valuations,
                             "A read-only int64 array (nr_states x len(variables)) of every "
                             "state's variable values, a view of the model's own; None when the "
                             "model has no variables.")
      .def("_csr", &csr, py::arg("context") = none,
           "(indptr, indices, data, shape) of a context's transition matrix.")
      .def("exact_probabilities", &exact_probabilities, py::arg("context") = none,
           "Every nonzero entry of the transition matrix as a fractions.Fraction, in the order "
           "of transition_matrix(context).data.")
      .def("probability", &probability, py::arg("state"), py::arg("action"), py::arg("target"),
           py::arg("context") = none,
           "P(target | state, action) in a context, exactly, as a fractions.Fraction.")
      .def(
          "state_rewards",
          [](const ModelObject& o, const py::handle& context) {
            return doubles(o, o.model.contexts[context_index(o.model, context)].rewards.state);
          },
          py::arg("context") = none, "R(s), the state rewards of a context, as float64.")
      .def(
          "state_action_rewards",
          [](const ModelObject& o, const py::handle& context) -> py::object {
            const auto& choice = o.model.contexts[context_index(o.model, context)].rewards.choice;
            if (choice.empty()) return py::none();
            return doubles(o, choice);
          },
          py::arg("context") = none,
          "The choice rewards of a context (index state * nr_actions + action), or None when it "
          "has state rewards only.")
      .def(
          "reward",
          [](const ModelObject& o, std::uint32_t s, const py::handle& action,
             const py::handle& context) {
            check_state(o.model, s);
            return fraction(
                o.model.reward(context_index(o.model, context), s, action_index(o.model, action)));
          },
          py::arg("state"), py::arg("action"), py::arg("context") = none,
          "R(s, a) = state reward + choice reward, exactly.")
      .def("__repr__", &describe);
}

}  // namespace oasis::python
