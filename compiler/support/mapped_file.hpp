#pragma once
// Read-only view of a whole file. Large model files are memory-mapped so that readers scan
// them in place; small or special files (pipes, /dev/stdin) are read into memory instead.

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

 private:
  void release();

  const char* data_ = "";
  std::size_t size_ = 0;
  bool mapped_ = false;
  std::string owned_;  // used when the file could not be mapped
};

}  // namespace oasis
