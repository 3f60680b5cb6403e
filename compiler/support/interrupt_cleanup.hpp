#pragma once
// One policy for the programs that stage output (oasisc, oasis-sim): when SIGINT, SIGTERM or
// SIGHUP ends the program, the unfinished output it was staging goes with it, and the program
// then dies of that signal as it would have without the handler (a shell sees status 128+N).
// What was already in place before the run stays as it was: StagedDirectory and AtomicFile only
// ever replace it whole, at their commit.
//
// Staged paths register themselves (CleanupPath) for as long as they are unfinished; a commit
// that moves them into place runs inside a CommitSection, during which a signal waits, so that
// the handler never deletes something half-way through being renamed. SIGKILL cannot be caught:
// what a killed writer leaves is removed by the next writer to the same place (both classes'
// open()).
//
// The handler uses only async-signal-safe calls: each path is copied into a fixed slot when it
// registers, and removal walks a directory with getdents64 and unlinkat.

#include <cstddef>
#include <string>

namespace oasis::interrupt {

// Installs the handlers for SIGINT, SIGTERM and SIGHUP. Call once, early in main(). Programs
// that handle these signals themselves (oasis-go1 stops the robot first) do not call it.
void install_cleanup_handlers();

// How long the handler waits, after removing what is registered, before the program dies of
// the signal. For the ranks of an MPI job that write nothing: mpirun signals every rank at
// once, and when one dies of a signal it kills the others with SIGKILL at the same moment, so
// a rank that died at once could take the writing rank with it before its handler had removed
// the unfinished output (issue 38). mpirun's own SIGKILL comes a second after its SIGTERM.
void set_wait_before_dying(int milliseconds);

// A file, or a directory with everything in it, that the handler removes while this lives.
// Registration fails silently when every slot is taken or the path is too long: the next writer
// still removes the leftover.
class CleanupPath {
 public:
  enum class Kind { kFile, kDirectory };
  CleanupPath() = default;
  CleanupPath(const std::string& path, Kind kind);
  CleanupPath(CleanupPath&& other) noexcept;
  CleanupPath& operator=(CleanupPath&& other) noexcept;
  CleanupPath(const CleanupPath&) = delete;
  CleanupPath& operator=(const CleanupPath&) = delete;
  ~CleanupPath();

  // The path is finished (or removed by its owner): the handler leaves it alone from now on.
  void release();
  [[nodiscard]] bool registered() const { return slot_ >= 0; }

 private:
  int slot_ = -1;
};

// While any CommitSection lives, a signal is held back; it takes effect when the last one ends.
class CommitSection {
 public:
  CommitSection();
  ~CommitSection();
  CommitSection(const CommitSection&) = delete;
  CommitSection& operator=(const CommitSection&) = delete;
};

// For a handler of a fatal signal that ends the program with _exit (mapped_file.cpp's SIGBUS
// handler): removes every registered path now, async-signal-safely, and returns whether any
// was. From then on no commit starts and no path registers, as after an ending signal. While
// another thread is committing, nothing is removed: its staged paths are left to the next
// writer, as after SIGKILL.
bool remove_unfinished_output_now();

// How many slots are in use (for tests).
[[nodiscard]] std::size_t registered_paths();

}  // namespace oasis::interrupt
