#include "support/interrupt_cleanup.hpp"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <ctime>

#include <dirent.h>
#include <fcntl.h>
#include <unistd.h>

#include "process/ending_signals.hpp"

namespace oasis::interrupt {
namespace {

constexpr int kSlots = 64;
constexpr std::size_t kMaxPath = 4096;
constexpr int kMaxDepth = 8;        // staging directories are flat; this only bounds the recursion
constexpr int kRemovalRounds = 16;  // see remove_tree_at

enum SlotState : int { kFree = 0, kFilling = 1, kReady = 2 };

struct Slot {
  std::atomic<int> state{kFree};
  bool directory = false;
  char path[kMaxPath] = {};
};

Slot slots[kSlots];
// The number of running commit sections, or -1 once the handler has begun to clean up: the
// program is then about to die, and nothing may start a commit or reuse a slot.
std::atomic<int> gate{0};
std::atomic<int> pending_signal{0};
std::atomic<int> wait_before_dying_ms{0};

[[noreturn]] void wait_for_death() {
  for (;;)
    ::pause();
}

bool remove_tree_at(int parent, const char* name, int depth);

// Empties the open directory `fd`. Entries are removed while reading, so the listing restarts
// from the beginning until a pass removes nothing.
void empty_directory(int fd, int depth) {
  alignas(dirent64) char buffer[2048];
  bool removed = true;
  while (removed) {
    removed = false;
    ::lseek(fd, 0, SEEK_SET);
    for (;;) {
      const ssize_t size = ::getdents64(fd, buffer, sizeof buffer);
      if (size <= 0) break;
      for (ssize_t offset = 0; offset < size;) {
        const auto* entry = reinterpret_cast<const dirent64*>(buffer + offset);
        offset += entry->d_reclen;
        const char* entry_name = entry->d_name;
        if (std::strcmp(entry_name, ".") == 0 || std::strcmp(entry_name, "..") == 0) continue;
        removed = remove_tree_at(fd, entry_name, depth + 1) || removed;
      }
    }
  }
}

// Removes the name `name` in `parent` when it is not a directory, keeping the file open. The
// last unlink of a file whose pages the kernel is still writing out (a catalog file just
// written and synced) waits for that writeback, which on a slow disk takes seconds: longer
// than mpirun's second between SIGTERM and SIGKILL, which then left the folder behind. With
// the file still open, unlink only removes the name; the wait moves to the program's exit,
// when every name is gone. The descriptor is never closed: the program is about to die.
bool unlink_keeping_open(int parent, const char* name) {
  const int keep = ::openat(parent, name, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  static_cast<void>(keep);  // a file that cannot be opened is still unlinked, waiting or not
  return ::unlinkat(parent, name, 0) == 0;
}

bool remove_tree_at(int parent, const char* name, int depth) {
  if (unlink_keeping_open(parent, name)) return true;
  if (errno != EISDIR || depth > kMaxDepth) return false;
  const int fd = ::openat(parent, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return false;
  // The signal may run this on a thread that does not write while another still does (an
  // MPI library's thread, a worker): a file it creates once the folder is empty makes the
  // removal fail, so the folder is emptied again. The writer stops at its next registration
  // (CleanupPath waits for death once the gate is closed), so a few rounds suffice.
  bool gone = false;
  for (int round = 0; round < kRemovalRounds && !gone; ++round) {
    empty_directory(fd, depth);
    gone = ::unlinkat(parent, name, AT_REMOVEDIR) == 0;
    if (!gone && errno != ENOTEMPTY && errno != EEXIST) break;
  }
  ::close(fd);
  return gone;
}

void write_error(const char* text) {
  const ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
  static_cast<void>(ignored);
}

// Called with the gate closed (-1): no slot changes meanwhile.
bool remove_registered_paths() {
  bool removed = false;
  for (Slot& slot : slots) {
    if (slot.state.load(std::memory_order_acquire) != kReady) continue;
    removed = (slot.directory ? remove_tree_at(AT_FDCWD, slot.path, 0)
                              : unlink_keeping_open(AT_FDCWD, slot.path)) ||
              removed;
  }
  return removed;
}

[[noreturn]] void clean_up_and_die(int signal_number) {
  const bool removed = remove_registered_paths();
  if (removed) {
    write_error(program_invocation_short_name);
    write_error(": interrupted: removed the unfinished output\n");
  }
  if (const int wait_ms = wait_before_dying_ms.load(); wait_ms > 0) {
    timespec wait{wait_ms / 1000, static_cast<long>(wait_ms % 1000) * 1000000L};
    while (::nanosleep(&wait, &wait) != 0 && errno == EINTR) {
    }
  }
  ::signal(signal_number, SIG_DFL);
  ::raise(signal_number);  // delivered when the handler returns (or at once outside one)
  sigset_t just_this;
  sigemptyset(&just_this);
  sigaddset(&just_this, signal_number);
  ::sigprocmask(SIG_UNBLOCK, &just_this, nullptr);
  wait_for_death();
}

void on_signal(int signal_number) {
  const int saved_errno = errno;
  int state = gate.load();
  for (;;) {
    if (state > 0) {  // a commit is moving files into place: it raises the signal when done
      pending_signal.store(signal_number);
      errno = saved_errno;
      return;
    }
    if (state < 0) {  // another thread is cleaning up; the program is about to die
      errno = saved_errno;
      return;
    }
    if (gate.compare_exchange_weak(state, -1)) break;
  }
  clean_up_and_die(signal_number);
}

}  // namespace

void install_cleanup_handlers() {
  // Started under nohup, SIGHUP stays ignored: the person who started the run asked for that.
  process::install_ending_signal_handler(on_signal, 0, /*keep_ignored=*/true);
}

void set_wait_before_dying(int milliseconds) {
  wait_before_dying_ms.store(milliseconds > 0 ? milliseconds : 0);
}

CleanupPath::CleanupPath(const std::string& path, Kind kind) {
  if (path.empty() || path.size() >= kMaxPath) return;
  if (gate.load() < 0) wait_for_death();
  for (int i = 0; i < kSlots; ++i) {
    int expected = kFree;
    if (!slots[i].state.compare_exchange_strong(expected, kFilling)) continue;
    std::memcpy(slots[i].path, path.c_str(), path.size() + 1);
    slots[i].directory = kind == Kind::kDirectory;
    slots[i].state.store(kReady, std::memory_order_release);
    slot_ = i;
    return;
  }
}

CleanupPath::CleanupPath(CleanupPath&& other) noexcept : slot_(other.slot_) {
  other.slot_ = -1;
}

CleanupPath& CleanupPath::operator=(CleanupPath&& other) noexcept {
  if (this != &other) {
    release();
    slot_ = other.slot_;
    other.slot_ = -1;
  }
  return *this;
}

CleanupPath::~CleanupPath() {
  release();
}

void CleanupPath::release() {
  if (slot_ < 0) return;
  if (gate.load() < 0) wait_for_death();  // the handler may be reading this slot
  slots[slot_].state.store(kFree, std::memory_order_release);
  slot_ = -1;
}

CommitSection::CommitSection() {
  int state = gate.load();
  for (;;) {
    if (state < 0) wait_for_death();
    if (gate.compare_exchange_weak(state, state + 1)) return;
  }
}

CommitSection::~CommitSection() {
  if (gate.fetch_sub(1) != 1) return;
  const int signal_number = pending_signal.exchange(0);
  if (signal_number != 0) on_signal(signal_number);
}

bool remove_unfinished_output_now() {
  int state = 0;
  if (!gate.compare_exchange_strong(state, -1)) return false;  // committing, or already dying
  return remove_registered_paths();
}

std::size_t registered_paths() {
  std::size_t count = 0;
  for (const Slot& slot : slots)
    count += slot.state.load() == kReady ? 1 : 0;
  return count;
}

}  // namespace oasis::interrupt
