#pragma once
// SIGINT, SIGTERM and SIGHUP (common/process/ending_signals.hpp) as a request to stop the robot.
// The handler only stores into a lock-free atomic (async-signal-safe); every Sender polls it once
// per tick and, when it is set, commands stop then stand and finishes, after which the program can
// exit. A self-pipe is not needed because the sender thread wakes every tick anyway.

namespace oasis::hw::go1 {

// Installs the handler for SIGINT, SIGTERM and SIGHUP (SA_RESTART). Safe to call more than once.
void install_stop_signal_handlers();

// Puts back the default dispositions (e.g. so a second Ctrl-C kills a stuck program).
void restore_default_signal_handlers();

bool stop_signal_received();

// The signal number received, 0 if none: a program may re-raise it after the robot stood.
int received_stop_signal();

// Forgets a received signal (tests; or a program that keeps running after a shutdown).
void clear_stop_signal();

}  // namespace oasis::hw::go1
