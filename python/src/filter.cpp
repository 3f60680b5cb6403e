// Filter: the runtime's attention filter on a loaded catalog, stepped from Python. Modes:
// "paper" (Algorithm 1), "joint" (the robust filter over (abstraction, true state)),
// "noise_aware" (continuous catalogs) and "hedged" (Algorithm 1 and the robust filter weighed
// by their evidence, rt::HedgedFilter). The filter works in a workspace allocated once here, so
// a step allocates nothing in C++; it returns the decision and the belief as a read-only numpy
// view of the filter's own buffer, made once (the next step updates it in place).

#include <cmath>
#include <optional>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "catalog_object.hpp"
#include "errors.hpp"
#include "oasis/rt/attention_filter.hpp"
#include "oasis/rt/hedged_filter.hpp"

namespace oasis::python {
namespace py = pybind11;

namespace {

std::string construction_error(rt::FilterError error, const std::string& mode) {
  switch (error) {
    case rt::FilterError::kNone:
      return "";
    case rt::FilterError::kWorkspaceTooSmall:
      return "the workspace is too small (a bug of the module)";
    case rt::FilterError::kNoRobustSection:
      return "mode '" + mode +
             "' needs the catalog's observation model: compile it with robust=P (oasisc compile "
             "--robust P), or from a spec with an observation block";
    case rt::FilterError::kBadOptions:
      return "an option is out of range (detection_epsilon in [0, 1), tolerances >= 0)";
    case rt::FilterError::kEmptyCatalog:
      return "the catalog has no abstractions, states or actions";
    case rt::FilterError::kWrongCatalogKind:
      return "mode '" + mode +
             "' does not run on this kind of catalog (joint and hedged: "
             "discrete catalogs; noise_aware: continuous ones)";
  }
  return "unknown filter error";
}

class FilterObject {
 public:
  FilterObject(const py::object& catalog, const std::string& mode, bool guard,
               double detection_epsilon, double reward_tolerance, const std::string& tie,
               std::uint64_t seed)
      : catalog_ref_(catalog), catalog_(catalog.cast<CatalogPointer>()), mode_(mode) {
    rt::FilterOptions options;
    options.zero_likelihood_guard = guard;
    options.detection_epsilon = detection_epsilon;
    options.reward_tolerance = reward_tolerance;
    options.seed = seed;
    if (tie == "random") {
      options.tie_rule = rt::TieRule::kRandom;
    } else if (tie != "keep") {
      throw py::value_error("tie must be 'keep' or 'random'");
    }
    const rt::CatalogView& view = catalog_->view();
    if (mode == "hedged") {
      rt::HedgeOptions hedge;
      hedge.paper = options;
      hedge.robust = options;
      workspace_.resize(rt::HedgedFilter::workspace_size(view, hedge));
      hedged_.emplace(view, hedge, workspace_.data(), workspace_.size());
      error_ = hedged_->error();
    } else {
      if (mode == "paper") {
        options.mode = rt::FilterMode::kPaper;
      } else if (mode == "joint") {
        options.mode = rt::FilterMode::kJoint;
      } else if (mode == "noise_aware") {
        options.mode = rt::FilterMode::kNoiseAware;
      } else {
        throw py::value_error("mode must be 'paper', 'joint', 'noise_aware' or 'hedged', not '" +
                              mode + "'");
      }
      workspace_.resize(rt::AttentionFilter::workspace_size(view, options));
      single_.emplace(view, options, workspace_.data(), workspace_.size());
      error_ = single_->error();
    }
    if (error_ != rt::FilterError::kNone)
      throw Failure(ErrorKind::kFilter, construction_error(error_, mode));
  }

  // The belief's view, made on first use and kept: the filter's buffer never moves.
  py::object belief(const py::object& self) {
    if (!belief_) {
      const double* data = hedged_ ? hedged_->beliefs() : single_->beliefs();
      belief_ = view(data, catalog_->view().num_abstractions, self);
    }
    return belief_;
  }

  void start(const py::handle& observation) {
    rt::StepStatus status;
    if (catalog_->view().is_continuous()) {
      const auto state = py::array_t<double, py::array::forcecast>::ensure(observation);
      if (!state) throw py::type_error("a continuous catalog's observation is a vector of floats");
      status = hedged_ ? rt::StepStatus::kNotReady : single_->start(state.data(), state.size());
    } else {
      const auto s = observation.cast<std::uint32_t>();
      status = hedged_ ? hedged_->start(s) : single_->start(s);
    }
    report(status, observation);
    started_ = true;
  }

  py::tuple step(const py::object& self, const py::handle& observation, double reward,
                 const py::handle& action) {
    if (!started_) throw Failure(ErrorKind::kFilter, "call start(first observation) before step()");
    const std::uint32_t taken = action.is_none() ? current_action() : action.cast<std::uint32_t>();
    rt::StepStatus status;
    if (catalog_->view().is_continuous()) {
      const auto state = py::array_t<double, py::array::forcecast>::ensure(observation);
      if (!state) throw py::type_error("a continuous catalog's observation is a vector of floats");
      status = single_->step(state.data(), state.size(), reward, taken);
    } else {
      const auto s = observation.cast<std::uint32_t>();
      status = hedged_ ? hedged_->step(s, reward, taken) : single_->step(s, reward, taken);
    }
    report(status, observation);
    return py::make_tuple(decision(), belief(self));
  }

  [[nodiscard]] py::object decision() const {
    const std::uint32_t a = current_action();
    return a == rt::kNoAction ? py::object(py::none()) : py::object(py::int_(a));
  }
  [[nodiscard]] std::uint32_t ml_abstraction() const {
    return hedged_ ? hedged_->ml_abstraction() : single_->ml_abstraction();
  }
  [[nodiscard]] std::optional<double> robust_weight() const {
    if (!hedged_) return std::nullopt;
    return hedged_->robust_weight();
  }
  [[nodiscard]] const char* status() const { return rt::step_status_name(status_); }
  [[nodiscard]] const std::string& mode() const { return mode_; }

 private:
  [[nodiscard]] std::uint32_t current_action() const {
    return hedged_ ? hedged_->action() : single_->action();
  }

  // Rejected input leaves the filter unchanged and raises; the other statuses are kept.
  void report(rt::StepStatus status, const py::handle& observation) {
    if (status == rt::StepStatus::kBadState) {
      throw Failure(ErrorKind::kFilter, "observation " + py::repr(observation).cast<std::string>() +
                                            " is not a state of the catalog");
    }
    if (status == rt::StepStatus::kBadAction)
      throw Failure(ErrorKind::kFilter, "the action taken is not an action of the catalog");
    if (status == rt::StepStatus::kNotReady)
      throw Failure(ErrorKind::kFilter, "mode '" + mode_ + "' does not take this observation");
    status_ = status;
  }

  py::object catalog_ref_;  // keeps the catalog's bytes alive as long as the filter
  CatalogPointer catalog_;
  std::string mode_;
  std::vector<double> workspace_;
  std::optional<rt::AttentionFilter> single_;
  std::optional<rt::HedgedFilter> hedged_;
  rt::FilterError error_ = rt::FilterError::kNone;
  rt::StepStatus status_ = rt::StepStatus::kOk;
  py::object belief_;
  bool started_ = false;
};

}  // namespace

void bind_filter(py::module_& module) {
  py::class_<FilterObject>(module, "Filter",
                           "The runtime's attention filter (Algorithm 1 and its robust forms) "
                           "on a Catalog.")
      .def(py::init<const py::object&, const std::string&, bool, double, double, const std::string&,
                    std::uint64_t>(),
           py::arg("catalog"), py::arg("mode") = "paper", py::arg("guard") = false,
           py::arg("detection_epsilon") = 0.0, py::arg("reward_tolerance") = 1e-9,
           py::arg("tie") = "keep", py::arg("seed") = 0,
           "mode: 'paper' (Algorithm 1), 'joint' (robust, needs the catalog's observation "
           "model), 'noise_aware' (continuous catalogs with position noise) or 'hedged' (paper "
           "and joint weighed by their evidence). guard: keep the prediction when no "
           "abstraction explains a reward. Raises FilterError when the catalog cannot run it.")
      .def("start", &FilterObject::start, py::arg("observation"),
           "The first observed state (an int; a vector of floats on a continuous catalog).")
      .def(
          "step",
          [](const py::object& self, const py::handle& observation, double reward,
             const py::handle& action) {
            return self.cast<FilterObject&>().step(self, observation, reward, action);
          },
          py::arg("observation"), py::arg("reward"), py::arg("action") = py::none(),
          "One step after acting and observing: returns (decision, belief), the next action "
          "(None where no action is enabled) and the belief over abstractions, a read-only "
          "view the next step updates in place (copy it to keep it). `action` is the action "
          "taken, by default the filter's last decision. Raises FilterError on an observation "
          "or action out of range (the filter is then unchanged).")
      .def_property_readonly("decision", &FilterObject::decision, "The current decision.")
      .def_property_readonly(
          "belief", [](const py::object& self) { return self.cast<FilterObject&>().belief(self); },
          "The belief over abstractions (a read-only view, updated by each step).")
      .def_property_readonly("ml_abstraction", &FilterObject::ml_abstraction,
                             "The most likely abstraction.")
      .def_property_readonly("robust_weight", &FilterObject::robust_weight,
                             "Hedged mode: the robust filter's weight; None otherwise.")
      .def_property_readonly("status", &FilterObject::status,
                             "What the last step did: 'ok', 'zero_likelihood', "
                             "'missing_observation'.")
      .def_property_readonly("mode", &FilterObject::mode);
}

}  // namespace oasis::python
