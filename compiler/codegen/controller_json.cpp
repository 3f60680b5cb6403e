#include "codegen/controller_json.hpp"

#include <algorithm>

namespace oasis::codegen {
namespace {

template <typename T>
void array(JsonWriter& out, const std::vector<T>& values) {
  out.begin_array();
  for (const T& value : values)
    out.value(value);
  out.end_array();
}

void write_grid(JsonWriter& out, const model::ModelIR& ir, const guarantee::UniformGrid& grid) {
  out.key("variables");
  out.begin_array();
  for (const model::ContinuousVariable& variable : ir.continuous)
    out.value(variable.name);
  out.end_array();
  out.key("grid");
  out.begin_array();
  for (std::size_t i = 0; i < grid.dimension(); ++i) {
    out.begin_object();
    out.key("cells");
    out.value(static_cast<std::uint64_t>(grid.intervals(i)));
    out.key("breaks");
    array(out, grid.breaks[i]);
    out.end_object();
  }
  out.end_array();
}

void write_actions(JsonWriter& out, const model::ModelIR& ir,
                   const std::vector<guarantee::ActionChoice>& actions) {
  out.key("inputs");
  out.begin_array();
  for (const model::InputVariable& input : ir.inputs) {
    out.begin_object();
    out.key("name");
    out.value(input.name);
    out.key("values");
    out.begin_array();
    for (const Rational& value : input.values)
      out.value(to_double(value));
    out.end_array();
    out.end_object();
  }
  out.end_array();
  out.key("actions");
  out.begin_array();
  for (const guarantee::ActionChoice& choice : actions) {
    out.begin_object();
    out.key("action");
    out.value(ir.actions[choice.action]);
    out.key("inputs");
    out.begin_array();
    for (const Rational& value : choice.inputs)
      out.value(to_double(value));
    out.end_array();
    out.end_object();
  }
  out.end_array();
}

void write_objective(JsonWriter& out, const model::GuaranteeObjective& objective) {
  out.key("objective");
  out.begin_object();
  out.key("kind");
  out.value(objective.kind == model::GuaranteeObjective::Kind::Safety ? "safety" : "reach-avoid");
  out.key("steps");
  if (objective.steps) {
    out.value(*objective.steps);
  } else {
    out.null();
  }
  out.key("exactly_at_step");
  out.value(objective.exactly_at_step);
  out.end_object();
}

void write_summary(JsonWriter& out, const pipeline::GuaranteeResult& result) {
  const guarantee::Synthesis& s = result.synthesis;
  out.key("summary");
  out.begin_object();
  out.key("cells");
  out.value(static_cast<std::uint64_t>(result.grid.cells));
  out.key("actions");
  out.value(static_cast<std::uint64_t>(result.actions.size()));
  out.key("interval_entries");
  out.value(result.entries);
  out.key("distinct_rows");
  out.value(result.distinct_rows);
  out.key("sweeps");
  out.value(s.sweeps);
  out.key("evaluation_sweeps");
  out.value(s.evaluation_sweeps);
  out.key("stop_reason");
  out.value(s.stop_reason);
  if (!s.lower_method.empty()) {  // unbounded objectives
    out.key("lower_method");
    out.value(s.lower_method);
    out.key("upper_method");
    out.value(s.upper_method);
    out.key("upper_sweeps");
    out.value(s.upper_sweeps);
    out.key("policy_rounds");
    out.value(s.policy_rounds);
  }
  out.key("largest_gap");
  out.value(s.largest_gap);
  out.key("lower_mean");
  out.value(s.lower_mean());
  out.key("upper_mean");
  out.value(s.upper_mean());
  out.key("lower_max");
  out.value(s.lower.empty() ? 0.0 : *std::max_element(s.lower.begin(), s.lower.end()));
  out.end_object();
}

}  // namespace

void write_controller_json(JsonWriter& out, const model::ModelIR& ir,
                           const pipeline::GuaranteeResult& result) {
  out.begin_object();
  out.key("format");
  out.value("oasis-controller");
  out.key("version");
  out.value(std::uint64_t{1});
  out.key("model");
  out.value(ir.name);
  write_grid(out, ir, result.grid);
  write_actions(out, ir, result.actions);
  write_objective(out, *ir.guarantee);
  out.key("lower");
  array(out, result.synthesis.lower);
  out.key("upper");
  array(out, result.synthesis.upper);
  out.key("controller");
  if (ir.guarantee->steps) {
    out.begin_array();
    for (const auto& step : result.synthesis.controller)
      array(out, step);
    out.end_array();
  } else {
    array(out, result.synthesis.controller.front());
  }
  write_summary(out, result);
  out.end_object();
  out.finish();
}

}  // namespace oasis::codegen
