#include "loop/control_loop.hpp"

#include <chrono>
#include <stdexcept>
#include <thread>
#include <variant>

namespace oasis::hw::loop {
namespace {

using Clock = std::chrono::steady_clock;

Clock::duration seconds(double s) {
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
}

bool stop_requested(const LoopParts& parts) {
  return parts.stop_requested && parts.stop_requested();
}

// Waits until `until`, repeating `velocity` to the link every keep-alive. False when a stop
// was requested meanwhile.
bool hold_until(LoopParts& parts, const LoopOptions& options, Clock::time_point start,
                Clock::time_point until, const go1::VelocityCommand& velocity) {
  while (true) {
    if (stop_requested(parts)) return false;
    const Clock::time_point now = Clock::now();
    if (now >= until) return true;
    std::this_thread::sleep_until(std::min(until, now + seconds(options.keepalive_s)));
    if (Clock::now() < until) {
      const double time_s = std::chrono::duration<double>(Clock::now() - start).count();
      parts.link.command(velocity, time_s);
    }
  }
}

go1::VelocityCommand velocity_of(const log::StepRecord& record) {
  return {static_cast<float>(record.command.forward_m_s),
          static_cast<float>(record.command.lateral_m_s),
          static_cast<float>(record.command.yaw_rate_rad_s)};
}

}  // namespace

LoopResult run_loop(LoopParts& parts, const LoopOptions& options) {
  if (!(options.period_s > 0.0) || !(options.keepalive_s > 0.0))
    throw std::invalid_argument("loop period and keep-alive must be > 0 s");
  const Clock::time_point start = Clock::now();
  LoopResult result;
  while (!options.max_steps || result.steps < *options.max_steps) {
    if (stop_requested(parts)) {
      result.end = LoopEnd::kStopRequested;
      return result;
    }
    NextFrame next = parts.source.next();
    if (const SourceStop* stop = std::get_if<SourceStop>(&next)) {
      result.end =
          stop->kind == SourceStop::Kind::kEnd ? LoopEnd::kSourceEnded : LoopEnd::kSourceFailed;
      result.reason = stop->reason;
      return result;
    }
    const double time_s = options.realtime
                              ? std::chrono::duration<double>(Clock::now() - start).count()
                              : static_cast<double>(result.steps) * options.period_s;
    const go1::Pose robot = parts.link.pose();
    const PerceptionResult seen = parts.perception.step(std::get<Frame>(next));
    log::StepRecord record = parts.controller.decide(seen, time_s, robot);
    if (parts.truth) record.truth = parts.truth();
    record.link = parts.link.link_record();
    parts.link.command(velocity_of(record), time_s);
    if (parts.on_step) parts.on_step(record);
    ++result.steps;
    if (options.realtime &&
        !hold_until(parts, options, start,
                    start + seconds(static_cast<double>(result.steps) * options.period_s),
                    velocity_of(record))) {
      result.end = LoopEnd::kStopRequested;
      return result;
    }
  }
  result.end = LoopEnd::kStepLimit;
  return result;
}

}  // namespace oasis::hw::loop
