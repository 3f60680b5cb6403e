#pragma once
// The one rule for opening a file a user names as an input, in every program (oasisc's readers
// through MappedFile, oasis-sim, oasis-go1's settings, recordings, step logs and specs,
// oasis-ros's bags):
//   - a regular file is read;
//   - a FIFO (a named pipe, or `<(command)`) is read once its writer has written or closed; if
//     nothing arrives within kPipeWaitMs it is "a pipe that nobody writes to" (a blocking open()
//     used to wait forever);
//   - a directory, a device or a socket is refused with what it is.
// Reasons are lower-case fragments to put after the path: "PATH: is a directory".
// (The runtime's catalog loader keeps its own check: the runtime depends on nothing of ours.)

#include <cerrno>
#include <cstddef>
#include <cstring>
#include <optional>
#include <string>

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

namespace oasis::files {

// How long a FIFO may stay silent before it counts as one nobody writes to: a writer that is
// there delivers at once.
inline constexpr int kPipeWaitMs = 5000;

// strerror() capitalises; our messages are lower-case fragments ("no such file or directory").
inline std::string reason_of_errno(int code) {
  std::string text = std::strerror(code);
  if (!text.empty() && text[0] >= 'A' && text[0] <= 'Z') text[0] = static_cast<char>(text[0] + 32);
  return text;
}

// What a file that is not a regular file or a FIFO is, or nothing when it may be read.
inline std::optional<std::string> refused_kind(const struct stat& info) {
  if (S_ISDIR(info.st_mode)) return "is a directory";
  if (S_ISCHR(info.st_mode) || S_ISBLK(info.st_mode)) return "is a device, not a file";
  if (S_ISSOCK(info.st_mode)) return "is a socket, not a file";
  if (!S_ISREG(info.st_mode) && !S_ISFIFO(info.st_mode)) return "is not a file";
  return std::nullopt;
}

// A pipe is usable once its writer has written or closed.
inline bool wait_for_writer(int fd, std::string& reason) {
  pollfd waiting{fd, POLLIN, 0};
  for (;;) {
    const int ready = ::poll(&waiting, 1, kPipeWaitMs);
    if (ready > 0) return true;
    if (ready < 0 && errno == EINTR) continue;
    reason = ready == 0 ? "is a pipe that nobody writes to (nothing arrived in " +
                              std::to_string(kPipeWaitMs / 1000) + " s)"
                        : reason_of_errno(errno);
    return false;
  }
}

// Opens `path` for reading by the rule above: a blocking descriptor (close it), with `info`
// filled, or -1 and `reason`.
inline int open_input(const std::string& path, struct stat& info, std::string& reason) {
  // Non-blocking, so that opening a FIFO nobody writes to does not wait forever.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    reason = errno == ENXIO ? "is a socket, not a file" : reason_of_errno(errno);
    return -1;
  }
  if (::fstat(fd, &info) != 0) {
    reason = reason_of_errno(errno);
    ::close(fd);
    return -1;
  }
  const std::optional<std::string> refused = refused_kind(info);
  if (refused || (S_ISFIFO(info.st_mode) && !wait_for_writer(fd, reason))) {
    if (refused) reason = *refused;
    ::close(fd);
    return -1;
  }
  // Reading blocks again from here: a pipe with a writer delivers what it writes.
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  return fd;
}

// Reads what `fd` delivers until its end into `text`, at most `max_bytes`; kTooLarge past them,
// kError (with `reason`) on a read error. Both readers of streams use it: read_input() below,
// and MappedFile for the pipes it cannot map.
enum class ReadResult { kWhole, kTooLarge, kError };

inline ReadResult read_to_end(int fd, std::size_t max_bytes, std::string& text,
                              std::string& reason) {
  char buffer[1 << 16];
  for (;;) {
    const ssize_t got = ::read(fd, buffer, sizeof buffer);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) {
      reason = reason_of_errno(errno);
      return ReadResult::kError;
    }
    if (got == 0) return ReadResult::kWhole;
    if (text.size() + static_cast<std::size_t>(got) > max_bytes) return ReadResult::kTooLarge;
    text.append(buffer, static_cast<std::size_t>(got));
  }
}

// The whole input at `path` (at most `max_bytes`), or nothing and `reason`.
inline std::optional<std::string> read_input(const std::string& path, std::size_t max_bytes,
                                             std::string& reason) {
  struct stat info {};
  const int fd = open_input(path, info, reason);
  if (fd < 0) return std::nullopt;
  std::string text;
  if (S_ISREG(info.st_mode) && static_cast<std::size_t>(info.st_size) <= max_bytes)
    text.reserve(static_cast<std::size_t>(info.st_size));
  const ReadResult result = read_to_end(fd, max_bytes, text, reason);
  ::close(fd);
  if (result == ReadResult::kTooLarge)
    reason = "is larger than the limit of " + std::to_string(max_bytes) + " bytes";
  if (result != ReadResult::kWhole) return std::nullopt;
  return text;
}

}  // namespace oasis::files
