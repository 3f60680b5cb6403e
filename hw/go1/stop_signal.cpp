#include "go1/stop_signal.hpp"

#include <atomic>
#include <csignal>

#include "process/ending_signals.hpp"

namespace oasis::hw::go1 {

namespace {

std::atomic<int> received_signal{0};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs a lock-free atomic");

void on_stop_signal(int signal_number) {
  received_signal.store(signal_number);
}

// Every ending signal, SIGHUP too: a closed terminal or ssh session must stop the robot as
// Ctrl-C does. An ignored SIGHUP (nohup) is taken over all the same: the robot still stands
// before the program ends, whoever asked.
void set_disposition(void (*handler)(int)) {
  process::install_ending_signal_handler(handler, SA_RESTART, /*keep_ignored=*/false);
}

}  // namespace

void install_stop_signal_handlers() {
  set_disposition(on_stop_signal);
}
void restore_default_signal_handlers() {
  set_disposition(SIG_DFL);
}
bool stop_signal_received() {
  return received_signal.load() != 0;
}
int received_stop_signal() {
  return received_signal.load();
}
void clear_stop_signal() {
  received_signal.store(0);
}

}  // namespace oasis::hw::go1
