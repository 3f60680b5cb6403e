#pragma once
// The intent record of an AtomicFileSet's commit, so that a set whose writer was killed in the
// middle of its renames (SIGKILL, the out-of-memory killer, a power cut) is finished by the next
// writer instead of staying a mix of two runs.
//
// A commit renames its files in only after every new file is complete, synced and named (a
// hidden sibling of its destination) and every old file is kept as a hidden hard link. Just
// before the first rename, the commit writes a journal beside the first destination
// (`.oasis-file-set.PID.N`, written under a `.tmp` name, synced, then renamed, so it is whole or
// absent) listing each destination with its new file and its old copy, and holds an flock on it
// until the last rename is done and the journal is deleted. From the moment a journal exists,
// every new file it lists is complete, so an interrupted commit can always be finished:
//
//   repair_interrupted_file_sets(directory) finds the journals in `directory` whose flock is free
//   (their writer is gone), renames in every new file still waiting, deletes what the set
//   removes, deletes the old copies and the journal. The set is then wholly the new one.
//
// AtomicFile::open() runs it for its destination's directory before anything else, so the next
// write to that folder (the same command run again, or any other oasisc output there) repairs the
// set before it touches the folder. A journal without its final name (killed while writing it)
// means no rename had begun: the old set is whole, and the leftovers are ordinary stale
// temporaries, which open() removes too.

#include <cstddef>
#include <string>
#include <vector>

namespace oasis {

// One file of a committing set: `temporary` is renamed over `destination` (empty for a file
// the set removes); `old_copy` is the hard link that keeps the replaced file until the end (empty
// when there was none).
struct FileSetEntry {
  std::string destination;
  std::string temporary;
  std::string old_copy;
};

class FileSetJournal {
 public:
  FileSetJournal() = default;
  FileSetJournal(const FileSetJournal&) = delete;
  FileSetJournal& operator=(const FileSetJournal&) = delete;
  ~FileSetJournal();

  // Writes and syncs the journal in `directory` and locks it. False and `error` on failure
  // (nothing has been renamed yet, so the commit can still give up cleanly).
  [[nodiscard]] bool write(const std::string& directory, const std::vector<FileSetEntry>& entries,
                           std::string& error);
  // The set is in place: deletes the journal and releases its lock.
  void finish();

 private:
  std::string path_;
  int fd_ = -1;
};

// Finishes every set in `directory` whose writer was killed in its commit (see above). Returns
// how many sets it finished; prints one note per set on standard error.
std::size_t repair_interrupted_file_sets(const std::string& directory);

// For tests: the commit stops the process (_exit) after this many renames, as a SIGKILL there
// would; negative (the default) never.
void set_file_set_crash_point_for_testing(int renames);
[[nodiscard]] int file_set_crash_point_for_testing();

}  // namespace oasis
