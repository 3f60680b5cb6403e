#include "loop/go1_link.hpp"

#include <sstream>
#include <thread>

namespace oasis::hw::loop {

Go1Link::Go1Link(go1::SenderOptions options)
    : options_(options), sender_(std::make_unique<go1::Sender>(std::move(options))) {}

bool Go1Link::wait_for_robot(std::chrono::milliseconds timeout) const {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    if (sender_->status().states_received > 0) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return sender_->status().states_received > 0;
}

std::string Go1Link::silence_report() const {
  const go1::SenderStatus status = sender_->status();
  std::ostringstream report;
  report << "sent " << status.packets_sent << " HighCmd packets to " << options_.robot.address
         << ':' << options_.robot.port << " from " << sender_->local_endpoint().address << ':'
         << sender_->local_endpoint().port << ", received no valid HighState";
  if (status.send_failures > 0) report << "; sending failed: " << status.last_send_error;
  if (status.states_refused > 0)
    report << "; refused " << status.states_refused << " answers: " << status.last_refusal;
  if (status.datagrams_ignored > 0) report << "; " << go1::ignored_datagrams_text(status);
  return report.str();
}

std::optional<log::LinkRecord> Go1Link::link_record() const {
  const go1::SenderStatus status = sender_->status();
  log::LinkRecord record;
  record.states_received = status.states_received;
  record.states_refused = status.states_refused;
  record.datagrams_ignored = status.datagrams_ignored;
  if (status.last_ignored_from)
    record.last_ignored_from = go1::to_string(*status.last_ignored_from);
  return record;
}

void Go1Link::command(const go1::VelocityCommand& velocity, double /*time_s*/) {
  sender_->set_command(velocity);
}

go1::Pose Go1Link::pose() const {
  const std::optional<go1::HighState> state = sender_->status().latest_state;
  if (!state) return {};
  return {state->position[0], state->position[1], state->imu_rpy[2]};
}

std::string Go1Link::describe() const {
  std::ostringstream text;
  text << "Go1 at " << options_.robot.address << ':' << options_.robot.port << " (HighCmd at "
       << options_.rate_hz << " Hz, watchdog " << options_.watchdog_timeout.count() << " ms)";
  return text.str();
}

}  // namespace oasis::hw::loop
