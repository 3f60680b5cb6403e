#pragma once
// A stand-in Go1 on loopback for tests: it receives HighCmd packets, refuses and counts bad ones,
// loses some on purpose (seeded), duplicates some, delays the rest (some by a spike, which
// reorders them: a spiked packet takes effect after later ones), then "executes" each: the
// commanded body velocity (walking mode only; every other mode stands still) is integrated into a
// planar pose between the times packets take effect, and a HighState carrying that pose is sent
// back to the packet's source, as the robot does (FACTS §1 "Addresses").

#include <chrono>
#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "go1/endpoint.hpp"
#include "go1/high_cmd.hpp"
#include "go1/loss_model.hpp"
#include "go1/planar_pose.hpp"
#include "go1/udp_socket.hpp"

namespace oasis::hw::go1 {

struct FakeGo1Options {
  Endpoint listen{"127.0.0.1", 0};  // port 0: any free port; see endpoint()
  std::optional<std::uint8_t> expected_level_flag = kLevelFlagHighLevel;  // nullopt: any
  std::uint8_t state_level_flag = kLevelFlagHighLevel;
  double loss_probability = 0.0;
  std::chrono::milliseconds delay{0};  // from receipt until the command takes effect
  double duplicate_probability = 0.0;  // a kept packet takes effect twice, 1 ms apart
  double spike_probability = 0.0;      // a kept packet is delayed by `spike` more
  std::chrono::milliseconds spike{0};
  std::uint64_t seed = 1;
};

struct FakeGo1Counts {
  std::uint64_t received = 0;  // datagrams of any kind
  std::uint64_t refused = 0;   // bad length, head, level flag or CRC
  std::uint64_t dropped = 0;   // lost on purpose
  std::uint64_t duplicated = 0;
  std::uint64_t spiked = 0;   // delayed by a spike (and so possibly reordered)
  std::uint64_t applied = 0;  // took effect
};

struct AppliedCommand {
  std::chrono::steady_clock::time_point at;
  HighCommand command;
};

class FakeGo1 {
 public:
  using Clock = std::chrono::steady_clock;

  explicit FakeGo1(FakeGo1Options options = {});  // throws LinkError if it cannot bind
  ~FakeGo1();
  FakeGo1(const FakeGo1&) = delete;
  FakeGo1& operator=(const FakeGo1&) = delete;

  Endpoint endpoint() const { return socket_.local_endpoint(); }
  Pose pose() const;  // as of the last applied command
  FakeGo1Counts counts() const;
  std::string last_refusal() const;
  std::vector<AppliedCommand> applied_commands() const;

 private:
  struct Pending {
    Clock::time_point due;
    HighCommand command;
    Endpoint reply_to;
  };

  void run();
  void accept(const Datagram& datagram, Clock::time_point now);
  void apply_due(Clock::time_point now);
  void schedule(Pending pending);
  void apply(const Pending& pending);
  void integrate_until(Clock::time_point at);
  void reply(const Endpoint& to);

  const FakeGo1Options options_;
  UdpSocket socket_;
  LossModel loss_;
  std::deque<Pending> pending_;  // thread-only; sorted by due time

  mutable std::mutex mutex_;
  bool quitting_ = false;
  Pose pose_;
  std::optional<AppliedCommand> in_effect_;
  FakeGo1Counts counts_;
  std::string last_refusal_;
  std::vector<AppliedCommand> applied_;

  std::thread thread_;
};

}  // namespace oasis::hw::go1
