#include "go1/fake_go1.hpp"

#include <algorithm>
#include <cmath>

#include "go1/high_state.hpp"

namespace oasis::hw::go1 {

namespace {

// How long the thread waits for a packet when none is due: bounds how late a delayed packet or
// the destructor is noticed.
constexpr std::chrono::milliseconds kMaxWait{1};

bool moves(const HighCommand& command) {
  return command.mode == Mode::kVelocityWalk;
}

}  // namespace

FakeGo1::FakeGo1(FakeGo1Options options)
    : options_(std::move(options)),
      socket_(options_.listen),
      loss_(options_.loss_probability, options_.seed),
      thread_([this] { run(); }) {}

FakeGo1::~FakeGo1() {
  {
    const std::lock_guard lock(mutex_);
    quitting_ = true;
  }
  thread_.join();
}

Pose FakeGo1::pose() const {
  const std::lock_guard lock(mutex_);
  return pose_;
}

FakeGo1Counts FakeGo1::counts() const {
  const std::lock_guard lock(mutex_);
  return counts_;
}

std::string FakeGo1::last_refusal() const {
  const std::lock_guard lock(mutex_);
  return last_refusal_;
}

std::vector<AppliedCommand> FakeGo1::applied_commands() const {
  const std::lock_guard lock(mutex_);
  return applied_;
}

void FakeGo1::run() {
  for (;;) {
    {
      const std::lock_guard lock(mutex_);
      if (quitting_) return;
    }
    if (std::optional<Datagram> datagram = socket_.receive(kMaxWait))
      accept(*datagram, Clock::now());
    apply_due(Clock::now());
  }
}

void FakeGo1::accept(const Datagram& datagram, Clock::time_point now) {
  const DecodeResult<HighCommand> decoded =
      decode_high_cmd(datagram.bytes, options_.expected_level_flag);
  const std::lock_guard lock(mutex_);
  ++counts_.received;
  if (!decoded.ok()) {
    ++counts_.refused;
    last_refusal_ =
        std::string(refusal_name(decoded.refused().reason)) + ": " + decoded.refused().detail;
    return;
  }
  if (loss_.drop_next()) {
    ++counts_.dropped;
    return;
  }
  // Every draw is made for every packet, so one fault's rate does not shift another's stream.
  const bool duplicate = loss_.next_uniform() < options_.duplicate_probability;
  const bool spike = loss_.next_uniform() < options_.spike_probability;
  Clock::time_point due = now + options_.delay;
  if (spike) {
    due += options_.spike;
    ++counts_.spiked;
  }
  schedule(Pending{due, decoded.packet(), datagram.from});
  if (duplicate) {
    schedule(Pending{due + std::chrono::milliseconds(1), decoded.packet(), datagram.from});
    ++counts_.duplicated;
  }
}

// Keeps pending_ sorted by due time; equal times keep their arrival order.
void FakeGo1::schedule(Pending pending) {
  const auto at =
      std::upper_bound(pending_.begin(), pending_.end(), pending.due,
                       [](Clock::time_point due, const Pending& other) { return due < other.due; });
  pending_.insert(at, std::move(pending));
}

void FakeGo1::apply_due(Clock::time_point now) {
  while (!pending_.empty() && pending_.front().due <= now) {
    apply(pending_.front());
    reply(pending_.front().reply_to);
    pending_.pop_front();
  }
}

void FakeGo1::apply(const Pending& pending) {
  const std::lock_guard lock(mutex_);
  integrate_until(pending.due);
  in_effect_ = AppliedCommand{pending.due, pending.command};
  applied_.push_back(*in_effect_);
  ++counts_.applied;
}

// Moves the pose under the command in effect since it was applied (mutex held).
void FakeGo1::integrate_until(Clock::time_point at) {
  if (!in_effect_ || !moves(in_effect_->command)) return;
  const double seconds = std::chrono::duration<double>(at - in_effect_->at).count();
  const HighCommand& command = in_effect_->command;
  pose_ = advanced(pose_, {command.velocity[0], command.velocity[1], command.yaw_speed}, seconds);
}

void FakeGo1::reply(const Endpoint& to) {
  HighState state;
  {
    const std::lock_guard lock(mutex_);
    state.mode = in_effect_->command.mode;
    state.gait_type = in_effect_->command.gait_type;
    state.position = {static_cast<float>(pose_.x), static_cast<float>(pose_.y), 0.0f};
    state.imu_rpy = {0.0f, 0.0f, static_cast<float>(pose_.yaw)};
    state.imu_quaternion = {static_cast<float>(std::cos(pose_.yaw / 2)), 0.0f, 0.0f,
                            static_cast<float>(std::sin(pose_.yaw / 2))};
    if (moves(in_effect_->command)) {
      state.velocity = {in_effect_->command.velocity[0], in_effect_->command.velocity[1],
                        in_effect_->command.yaw_speed};
      state.yaw_speed = in_effect_->command.yaw_speed;
    }
    state.body_height = 0.28f;  // comm.h's default
    state.battery_percent = 100;
  }
  const HighStateBytes packet = encode_high_state(state, options_.state_level_flag);
  (void)socket_.send_to(packet, to_sockaddr(to));  // a test robot need not report its errors
}

}  // namespace oasis::hw::go1
