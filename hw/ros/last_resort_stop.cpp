#include "ros/last_resort_stop.hpp"

#include <array>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <memory>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <geometry_msgs/Twist.h>
#include <poll.h>
#include <ros/names.h>
#include <ros/ros.h>
#include <signal.h>
#include <unistd.h>

#include "ros/command_gate.hpp"
#include "ros/ros_session_handles.hpp"

namespace oasis::hw::ros_node {
namespace {

using namespace std::chrono_literals;

constexpr std::array<int, 5> kFatalSignals = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};

// The gate of command_gate.hpp, without a lock that a dying thread could hold: a publisher
// counts itself in before it checks `halted`, the last resort sets `halted` before it reads
// the count. Sequentially consistent, so one of the two sees the other: the publisher drops
// its moving Twist, or the last resort waits for it to be published before its zero.
std::atomic<bool> halted{false};
std::atomic<int> publishing{0};
std::atomic<bool> fired{false};  // the last resort runs once
std::atomic<int> wake_fd{-1};    // the signal handler wakes the stopper thread here
std::atomic<int> done_fd{-1};    // and waits here for it to have published
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "the signal handler needs lock-free atomics");

bool is_zero(const geometry_msgs::Twist& t) {
  return t.linear.x == 0.0 && t.linear.y == 0.0 && t.linear.z == 0.0 && t.angular.x == 0.0 &&
         t.angular.y == 0.0 && t.angular.z == 0.0;
}

// Halts the commands; waits (a bounded time: the thread that died may be the one publishing)
// for a publish that passed the gate before to be done.
void halt() {
  halted.store(true);
  const auto deadline = std::chrono::steady_clock::now() + 200ms;
  while (publishing.load() > 0 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(1ms);
}

// Three zero Twists 20 ms apart, as CmdVelLink::shut_down sends them, then 100 ms for them to
// leave: roscpp writes to the sockets from the publishing thread when it can, from its own
// poll thread otherwise.
void publish_zeros(const ros::Publisher& publisher) {
  halt();
  for (int k = 0; k < 3; ++k) {
    publisher.publish(geometry_msgs::Twist());
    std::this_thread::sleep_for(20ms);
  }
  std::this_thread::sleep_for(100ms);
}

void write_text(const char* text, std::size_t size) {
  while (size > 0) {
    const ssize_t written = ::write(STDERR_FILENO, text, size);
    if (written <= 0) return;
    text += written;
    size -= static_cast<std::size_t>(written);
  }
}

// Async-signal-safe: atomics, write, poll, sigaction and raise only.
extern "C" void on_fatal_signal(int signal_number) {
  if (!fired.exchange(true)) {
    const char byte = 1;
    pollfd done{done_fd.load(), POLLIN, 0};
    const bool woken = ::write(wake_fd.load(), &byte, 1) == 1;
    if (woken && ::poll(&done, 1, 500) == 1) {
      static const char kSent[] =
          "oasis-ros: fatal signal: a zero Twist was published on cmd_vel (last resort)\n";
      write_text(kSent, sizeof kSent - 1);
    } else {
      static const char kNotSent[] =
          "oasis-ros: fatal signal: the zero Twist could not be published in time\n";
      write_text(kNotSent, sizeof kNotSent - 1);
    }
  }
  // Die of the signal, as without this handler: it is blocked until the handler returns.
  struct sigaction fallback {};
  fallback.sa_handler = SIG_DFL;
  sigemptyset(&fallback.sa_mask);
  ::sigaction(signal_number, &fallback, nullptr);
  ::raise(signal_number);
}

std::string thrown_text() {
  try {
    if (const std::exception_ptr thrown = std::current_exception()) std::rethrow_exception(thrown);
  } catch (const std::exception& e) {
    return std::string("an exception nobody caught: ") + e.what();
  } catch (...) {
    return "an exception nobody caught, of an unknown type";
  }
  return "std::terminate was called";
}

struct Armed {
  ros::Publisher publisher;
  int wake[2] = {-1, -1};
  int done[2] = {-1, -1};
  std::thread stopper;
  std::terminate_handler previous_terminate = nullptr;
  std::array<struct sigaction, kFatalSignals.size()> previous_actions{};
  std::vector<char> signal_stack;
  stack_t previous_stack{};
};

Armed* armed = nullptr;  // the one armed LastResortStop

[[noreturn]] void on_terminate() {
  // A hang in roscpp (a lock the thrower held) must not keep the process alive: SIGALRM's
  // default action ends it.
  ::alarm(2);
  const std::string what = thrown_text();
  if (armed && !fired.exchange(true)) {
    publish_zeros(armed->publisher);
    std::cerr << "oasis-ros: internal error: " << what
              << "; a zero Twist was published on cmd_vel (last resort)\n";
  } else {
    std::cerr << "oasis-ros: internal error: " << what << '\n';
  }
  std::abort();
}

// The stopper thread: waits for a fatal signal's handler to wake it; publishes the zero
// Twists from an ordinary context, where roscpp may be called. Ends when the write end closes.
void stop_when_woken(Armed& state) {
  char byte = 0;
  ssize_t got = 0;
  do {
    got = ::read(state.wake[0], &byte, 1);
  } while (got < 0 && errno == EINTR);
  if (got != 1) return;
  publish_zeros(state.publisher);
  const char done = 1;
  if (::write(state.done[1], &done, 1) != 1) return;
}

// The main thread's own stack for the handler, so that a stack overflow still reaches it.
void give_signal_stack(Armed& state) {
  state.signal_stack.resize(64 * 1024);
  stack_t stack{};
  stack.ss_sp = state.signal_stack.data();
  stack.ss_size = state.signal_stack.size();
  ::sigaltstack(&stack, &state.previous_stack);
}

void install_handlers(Armed& state) {
  state.previous_terminate = std::set_terminate(on_terminate);
  struct sigaction action {};
  action.sa_handler = on_fatal_signal;
  action.sa_flags = SA_ONSTACK;
  sigemptyset(&action.sa_mask);
  for (std::size_t k = 0; k < kFatalSignals.size(); ++k)
    ::sigaction(kFatalSignals[k], &action, &state.previous_actions[k]);
}

void remove_handlers(Armed& state) {
  for (std::size_t k = 0; k < kFatalSignals.size(); ++k)
    ::sigaction(kFatalSignals[k], &state.previous_actions[k], nullptr);
  std::set_terminate(state.previous_terminate);
  ::sigaltstack(&state.previous_stack, nullptr);
}

}  // namespace

void publish_command(const ros::Publisher& publisher, const geometry_msgs::Twist& twist) {
  publishing.fetch_add(1);
  if (!halted.load() || is_zero(twist)) publisher.publish(twist);
  publishing.fetch_sub(1);
}

LastResortStop::LastResortStop(RosSession& session, const std::string& topic) {
  if (armed) throw RosError("the last resort is already armed");
  std::string error;
  if (!ros::names::validate(topic, error))
    throw RosError("cmd_vel \"" + topic + "\" is not a valid ROS name: " + error);
  auto state = std::make_unique<Armed>();
  state->publisher = session.handles().node->advertise<geometry_msgs::Twist>(topic, 10);
  if (::pipe2(state->wake, O_CLOEXEC) != 0 || ::pipe2(state->done, O_CLOEXEC) != 0)
    throw RosError("cannot arm the last resort: no pipe");
  wake_fd.store(state->wake[1]);
  done_fd.store(state->done[0]);
  state->stopper = std::thread([s = state.get()] { stop_when_woken(*s); });
  give_signal_stack(*state);
  armed = state.release();
  install_handlers(*armed);
}

LastResortStop::~LastResortStop() {
  remove_handlers(*armed);
  wake_fd.store(-1);
  done_fd.store(-1);
  ::close(armed->wake[1]);  // the stopper reads the end of the pipe and returns
  armed->stopper.join();
  for (const int fd : {armed->wake[0], armed->done[0], armed->done[1]})
    ::close(fd);
  delete armed;
  armed = nullptr;
}

}  // namespace oasis::hw::ros_node
