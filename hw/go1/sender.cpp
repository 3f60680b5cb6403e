#include "go1/sender.hpp"

#include <stdexcept>

#include "go1/stop_signal.hpp"

namespace oasis::hw::go1 {

namespace {

SenderOptions checked(SenderOptions options) {
  if (!(options.rate_hz >= 1.0 && options.rate_hz <= 1000.0))
    throw std::invalid_argument("rate_hz must be in 1..1000 (the SDK's comment allows 100..1000)");
  if (options.watchdog_timeout.count() <= 0)
    throw std::invalid_argument("watchdog_timeout must be positive");
  if (options.stop_hold.count() < 0 || options.shutdown_stand_hold.count() < 0)
    throw std::invalid_argument("stop_hold and shutdown_stand_hold must not be negative");
  if (const std::string problem = check_limits(options.limits); !problem.empty())
    throw std::invalid_argument(problem);
  return options;
}

HighCommand stand_command() {
  return HighCommand{};
}  // idle mode, idle gait, all zero

}  // namespace

Sender::Sender(SenderOptions options)
    : options_(checked(std::move(options))),
      robot_address_(to_sockaddr(options_.robot)),
      robot_endpoint_(from_sockaddr(robot_address_)),
      tick_(std::chrono::duration_cast<Clock::duration>(
          std::chrono::duration<double>(1.0 / options_.rate_hz))),
      socket_(options_.local),
      watchdog_(options_.watchdog_timeout, options_.stop_hold),
      thread_([this] { run(); }) {}

Sender::~Sender() {
  stop();
}

void Sender::set_command(const VelocityCommand& wanted) {
  const std::lock_guard lock(mutex_);
  if (shutdown_started_) return;
  target_ = clamp_to_limits(wanted, options_.limits);
  watchdog_.feed(Clock::now());
}

void Sender::stop() {
  {
    const std::lock_guard lock(mutex_);
    stop_requested_ = true;
  }
  if (thread_.joinable()) thread_.join();
}

bool Sender::wait_until_finished(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  return finished_changed_.wait_for(lock, timeout,
                                    [this] { return status_.phase == SenderPhase::kFinished; });
}

SenderStatus Sender::status() const {
  const std::lock_guard lock(mutex_);
  return status_;
}

void Sender::run() {
  Clock::time_point next_tick = Clock::now();
  for (;;) {
    const Clock::time_point now = Clock::now();
    if (shutdown_due(now)) break;
    send(next_command(now));
    read_states();
    next_tick += tick_;
    if (next_tick < now) next_tick = now + tick_;  // late: skip ticks rather than burst
    std::this_thread::sleep_until(next_tick);
  }
  const std::lock_guard lock(mutex_);
  status_.phase = SenderPhase::kFinished;
  finished_changed_.notify_all();
}

// Starts the shutdown sequence when asked to, and says whether it has run its course.
bool Sender::shutdown_due(Clock::time_point now) {
  const std::lock_guard lock(mutex_);
  const bool asked = stop_requested_ || (options_.obey_stop_signal && stop_signal_received());
  if (asked && !shutdown_started_) {
    shutdown_started_ = now;
    shutdown_skips_stop_ = status_.phase == SenderPhase::kStanding;
  }
  if (!shutdown_started_) return false;
  const Clock::duration stop_part =
      shutdown_skips_stop_ ? Clock::duration::zero() : Clock::duration(options_.stop_hold);
  return now >= *shutdown_started_ + stop_part + options_.shutdown_stand_hold;
}

HighCommand Sender::next_command(Clock::time_point now) {
  const std::lock_guard lock(mutex_);
  SafetyAction action = watchdog_.decide(now);
  if (shutdown_started_) {
    const bool stopping = !shutdown_skips_stop_ && now < *shutdown_started_ + options_.stop_hold;
    action = stopping ? SafetyAction::kStop : SafetyAction::kStand;
  }
  const float tick_seconds = std::chrono::duration<float>(tick_).count();
  switch (action) {
    case SafetyAction::kPass:
      status_.phase = SenderPhase::kDriving;
      status_.commanded = ramp_toward(status_.commanded, target_, options_.limits, tick_seconds);
      return walk(status_.commanded);
    case SafetyAction::kStop:
      status_.phase = shutdown_started_ ? SenderPhase::kShuttingDown : SenderPhase::kStopping;
      status_.commanded = VelocityCommand{};
      return walk(status_.commanded);
    case SafetyAction::kStand:
      status_.phase = shutdown_started_ ? SenderPhase::kShuttingDown : SenderPhase::kStanding;
      status_.commanded = VelocityCommand{};
      return stand_command();
  }
  return stand_command();
}

HighCommand Sender::walk(const VelocityCommand& velocity) const {
  HighCommand command;
  command.mode = Mode::kVelocityWalk;
  command.gait_type = options_.gait;
  command.velocity = {velocity.forward, velocity.lateral};
  command.yaw_speed = velocity.yaw_rate;
  return command;
}

void Sender::send(const HighCommand& command) {
  const HighCmdBytes packet = encode_high_cmd(command, options_.level_flag);
  std::optional<std::string> error = socket_.send_to(packet, robot_address_);
  const std::lock_guard lock(mutex_);
  if (!error) {
    ++status_.packets_sent;
    return;
  }
  ++status_.send_failures;
  status_.last_send_error = std::move(*error);
}

std::string ignored_datagrams_text(std::uint64_t count, std::string_view last_from) {
  if (count == 0) return "";
  std::string text = "ignored " + std::to_string(count) + (count == 1 ? " datagram" : " datagrams");
  if (!last_from.empty())
    text += (count == 1 ? " from " : ", the last from ") + std::string(last_from);
  return text + " (not the robot)";
}

std::string ignored_datagrams_text(const SenderStatus& status) {
  return ignored_datagrams_text(status.datagrams_ignored, status.last_ignored_from
                                                              ? to_string(*status.last_ignored_from)
                                                              : std::string());
}

void Sender::read_states() {
  while (std::optional<Datagram> datagram = socket_.receive(std::chrono::milliseconds(0))) {
    if (datagram->from != robot_endpoint_) {
      const std::lock_guard lock(mutex_);
      ++status_.datagrams_ignored;
      status_.last_ignored_from = datagram->from;
      continue;
    }
    const DecodeResult<HighState> decoded =
        decode_high_state(datagram->bytes, options_.state_level_flag, options_.check_state_crc);
    const std::lock_guard lock(mutex_);
    if (decoded.ok()) {
      ++status_.states_received;
      status_.latest_state = decoded.packet();
    } else {
      ++status_.states_refused;
      status_.last_refusal = std::string(refusal_name(decoded.refused().reason)) + ": " +
                             decoded.refused().detail + " (from " + to_string(datagram->from) + ")";
    }
  }
}

}  // namespace oasis::hw::go1
