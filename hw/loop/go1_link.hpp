#pragma once
// The loop's link to a Go1 (or to the fake one): the sender thread of hw/go1 with its clamps,
// ramps and watchdog, plus the check that a robot answers before anything moves.
#include <chrono>
#include <memory>
#include <string>

#include "go1/sender.hpp"
#include "loop/robot_link.hpp"

namespace oasis::hw::loop {

class Go1Link final : public RobotLink {
 public:
  // Throws go1::LinkError (bad address, port in use) or std::invalid_argument (bad options).
  // The robot is told to stand until the first command().
  explicit Go1Link(go1::SenderOptions options);

  // Waits for the robot's first valid HighState from the robot's own address and port (a
  // packet from anyone else is ignored, go1/sender.hpp). False if none came within `timeout`:
  // the robot is off, on another network, answers from another address, or speaks another
  // level flag (hw/README.md, "First checks"); the caller must not start the loop then.
  bool wait_for_robot(std::chrono::milliseconds timeout) const;

  // Why wait_for_robot() failed, for the error message: what was sent and what came back.
  std::string silence_report() const;

  void command(const go1::VelocityCommand& velocity, double time_s) override;
  go1::Pose pose() const override;
  void shut_down() override { sender_->stop(); }
  std::string describe() const override;
  std::optional<log::LinkRecord> link_record() const override;

  const go1::Sender& sender() const { return *sender_; }

 private:
  go1::SenderOptions options_;
  std::unique_ptr<go1::Sender> sender_;
};

}  // namespace oasis::hw::loop
