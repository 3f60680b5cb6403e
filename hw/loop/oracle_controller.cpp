#include "loop/oracle_controller.hpp"

#include <utility>

namespace oasis::hw::loop {

OracleController::OracleController(const rt::CatalogView& catalog,
                                   const ControllerSettings& settings, TruthProvider truth)
    : catalog_(catalog), truth_(std::move(truth)) {
  for (std::uint32_t i = 0; i < catalog.num_abstractions; ++i) {
    auto view = std::make_unique<rt::CatalogView>(catalog);
    view->num_abstractions = 1;
    view->abstractions = &catalog.abstractions[i];
    view->switching = &certain_;
    view->prior = &certain_;
    controllers_.push_back(std::make_unique<AttentionController>(*view, settings));
    views_.push_back(std::move(view));
  }
}

log::StepRecord OracleController::decide(const PerceptionResult& seen, double time_s,
                                         const go1::Pose& robot) {
  if (const std::optional<std::uint32_t> truth = truth_ ? truth_() : std::nullopt;
      truth && *truth < controllers_.size())
    context_ = *truth;
  log::StepRecord chosen;
  for (std::uint32_t i = 0; i < controllers_.size(); ++i) {
    log::StepRecord record = controllers_[i]->decide(seen, time_s, robot);
    if (i == context_) chosen = std::move(record);
  }
  chosen.belief.assign(catalog_.num_abstractions, 0.0);
  chosen.belief[context_] = 1.0;
  chosen.abstraction = context_;
  chosen.abstraction_name = catalog_.abstractions[context_].context;
  return chosen;
}

}  // namespace oasis::hw::loop
