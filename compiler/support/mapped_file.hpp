#pragma once
// Read-only view of a whole file. Large model files are memory-mapped so that readers scan
// them in place; small or special files (pipes, /dev/stdin) are read into memory instead.
//
// A mapped file that shrinks while it is read (truncated by another program) makes the next
// read past its new end a SIGBUS, which would kill the program with a core dump. Every mapping
// is registered for as long as it lives, and the first one installs a SIGBUS handler that
// recognises a fault inside a registered mapping: it prints
//   PATH: error: the file changed size while being read
// removes the unfinished output (support/interrupt_cleanup.hpp) and ends the program with
// status 1. A fault anywhere else goes to the handler that was in place before (the default
// crash, or OpenMPI's), as if ours were not there. The handler uses async-signal-safe calls
// only: the message is composed when the file is mapped.

#include <cstddef>
#include <string>
#include <string_view>

namespace oasis {

class MappedFile {
 public:
  MappedFile() = default;
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;
  MappedFile(MappedFile&& other) noexcept;
  MappedFile& operator=(MappedFile&& other) noexcept;
  ~MappedFile();

  // Opens `path`. On failure returns false and sets `error` to a lower-case reason.
  // Files longer than `max_bytes` are refused rather than read.
  [[nodiscard]] bool open(const std::string& path, std::size_t max_bytes, std::string& error);

  [[nodiscard]] std::string_view text() const { return {data_, size_}; }

  // Tells the kernel that the first `bytes` of a mapped file are read: their pages leave this
  // process's resident memory (they stay in the page cache, which may keep or evict them).
  // text() is unchanged and still valid; a later read of those bytes faults them back in from
  // the file. A reader that scans a large file once calls this as it goes, so the file never
  // counts whole in the peak. Nothing happens for a file read into memory.
  void release_pages_before(std::size_t bytes) const;

  // For tests of the above only: when the environment sets OASIS_TEST_SHRINK_INPUT=BYTES and
  // this file is mapped and longer, cuts the file at `path` (this one's) to BYTES, so that a
  // reader meets the shrunk file at a known point. Readers call it once the file is theirs and
  // before they read (SourceManager::add); without the variable it does nothing.
  void shrink_if_testing(const std::string& path) const;

 private:
  void release();

  const char* data_ = "";
  std::size_t size_ = 0;
  bool mapped_ = false;
  int fault_slot_ = -1;  // the registration of a mapping (see the top of this file)
  std::string owned_;    // used when the file could not be mapped
};

// Appended to the message of a shrunk file, so that a process among several says which it is
// (oasisc-mpi's rank 3: " (rank 3)"). Call before any file is opened.
void set_changed_size_note(const std::string& note);

}  // namespace oasis
