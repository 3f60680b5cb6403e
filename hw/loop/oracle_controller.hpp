#pragma once
// The oracle baseline of Table II: told who truly holds the treat, it applies that context's
// policy, so it has no inference lag and no wrong context; what is left is how well the policy
// follows the person with the state perception gives it. The upper bound for the filter.
//
// It runs one AttentionController per context, each on a one-context view of the catalog (the
// same state handling: last seen places held, the domain's edge), all fed every step so that
// each holds the people where they were last seen; the true context's decision is the step's.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "loop/attention_controller.hpp"
#include "loop/loop_controller.hpp"

namespace oasis::hw::loop {

class OracleController final : public LoopController {
 public:
  // The index of the true context of the frame just taken (nothing: keep the last).
  using TruthProvider = std::function<std::optional<std::uint32_t>()>;

  OracleController(const rt::CatalogView& catalog, const ControllerSettings& settings,
                   TruthProvider truth);
  OracleController(const OracleController&) = delete;  // the views point into this object
  OracleController& operator=(const OracleController&) = delete;

  log::StepRecord decide(const PerceptionResult& seen, double time_s,
                         const go1::Pose& robot) override;

 private:
  const rt::CatalogView& catalog_;
  const double certain_ = 1.0;  // the switching matrix and prior of a one-context view
  std::vector<std::unique_ptr<rt::CatalogView>> views_;  // stable addresses: controllers keep them
  std::vector<std::unique_ptr<AttentionController>> controllers_;
  TruthProvider truth_;
  std::uint32_t context_ = 0;
};

}  // namespace oasis::hw::loop
