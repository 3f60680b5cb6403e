#pragma once
// An output directory that changes as one unit: the whole new set of files or the whole old
// one, never a mix, whenever the writer is killed.
//
// open(target) makes a hidden staging directory beside the target, in the same parent (so
// that the final step is a rename on one file system), and holds an exclusive flock on it
// while the writer fills it. commit() syncs it and swaps it with the target in one atomic
// renameat2(RENAME_EXCHANGE) (or renames it into place when the target does not exist), then
// deletes the old content. Where the file system refuses RENAME_EXCHANGE the swap falls back
// to two renames; only then can a crash between them leave the target missing, with the old
// set kept in a hidden sibling that the next open() puts back.
//
// The target is owned by the tool: it must be absent, empty, or hold the marker file
// kMarkerName that a previous commit wrote (a directory with other files is refused, so that
// no user file is ever deleted). open() also removes stale staging directories that killed
// writers left beside the same target: those whose flock can be taken.
//
// SIGINT, SIGTERM and SIGHUP remove the staging directory (interrupt_cleanup.hpp) in programs
// that install the clean-up handlers; the swap itself runs with those signals held back.
//
// Errors are lower-case reason strings, like AtomicFile's.

#include <string>

#include "support/interrupt_cleanup.hpp"

namespace oasis {

class StagedDirectory {
 public:
  // The file that marks a directory as written by a StagedDirectory commit.
  static constexpr const char* kMarkerName = ".oasisc-output";

  StagedDirectory() = default;
  StagedDirectory(const StagedDirectory&) = delete;
  StagedDirectory& operator=(const StagedDirectory&) = delete;
  ~StagedDirectory();

  // Checks the target, removes stale staging siblings and creates the staging directory.
  [[nodiscard]] bool open(const std::string& target, std::string& error);
  // Where to write the new set.
  [[nodiscard]] const std::string& staging_path() const { return staging_; }
  // The target as resolved (symbolic links followed).
  [[nodiscard]] const std::string& target_path() const { return target_; }

  // Writes the marker (with `marker_text`, which should list the set), syncs, and swaps the
  // staging directory in. On failure the target is as it was and the staging directory gone.
  [[nodiscard]] bool commit(const std::string& marker_text, std::string& error);
  // Removes the staging directory; the target is left as it was.
  void discard();

 private:
  std::string target_;
  std::string staging_;
  interrupt::CleanupPath cleanup_;  // the staging directory, removed if we are interrupted
  int lock_fd_ = -1;
};

}  // namespace oasis
