#pragma once
// The signals that end a program when a person or the system asks it to: Ctrl-C (SIGINT), a
// service manager or `kill` (SIGTERM), and a closed terminal or ssh session (SIGHUP). Every
// program of oasis treats the three alike, each with its own policy: oasisc, oasisc-mpi and
// oasis-sim remove their unfinished output and die of the signal; oasis-go1 stops the robot,
// then stands; oasis-ros publishes the zero Twist. This header is the one list they all use, so
// that a signal cannot again be handled by one program and forgotten by another.
//
// SIGKILL and SIGSTOP cannot be caught; what each program guarantees then is in
// docs/RELIABILITY.md.

#include <array>
#include <csignal>

namespace oasis::process {

inline constexpr std::array<int, 3> kEndingSignals = {SIGINT, SIGTERM, SIGHUP};

// The signal's name for messages ("SIGHUP"), or "a signal" for any other number.
inline const char* ending_signal_name(int signal_number) {
  switch (signal_number) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP";
    default:
      return "a signal";
  }
}

// Installs `handler` for every ending signal, each blocked while the handler runs, with
// `flags` (SA_RESTART, say). A signal the program was started to ignore (under nohup, SIGHUP is
// ignored) stays ignored when `keep_ignored` is true: the person who started it asked for that.
// With `handler` SIG_DFL the default dispositions come back (a second Ctrl-C kills a stuck
// program).
inline void install_ending_signal_handler(void (*handler)(int), int flags, bool keep_ignored) {
  struct sigaction action {};
  action.sa_handler = handler;
  action.sa_flags = flags;
  sigemptyset(&action.sa_mask);
  for (const int signal_number : kEndingSignals)
    sigaddset(&action.sa_mask, signal_number);
  for (const int signal_number : kEndingSignals) {
    if (keep_ignored) {
      struct sigaction previous {};
      ::sigaction(signal_number, nullptr, &previous);
      if (previous.sa_handler == SIG_IGN) continue;
    }
    ::sigaction(signal_number, &action, nullptr);
  }
}

}  // namespace oasis::process
