#pragma once
// An output file that appears whole or not at all. Bytes go to a temporary file in the
// destination's directory (same file system, so the final rename is atomic); commit() flushes,
// fsyncs and renames it over the destination. Destroying an uncommitted AtomicFile, or any
// write error, removes the temporary file: a failed run never leaves half a model behind.
//
// The temporary file is anonymous where the kernel allows it (O_TMPFILE): it gets a name only
// at commit, when it is complete (the destination's own name if that is free, else a hidden
// sibling renamed over it at once), so a writer killed by SIGKILL leaves nothing behind but,
// at worst, in that instant, one complete sibling. Elsewhere the temporary file is a hidden
// sibling `.NAME.tmp.XXXXXXXXXX` from the start. Both hold an flock while they live; open()
// deletes siblings of the same destination whose flock is free (left by killed writers).
//
// Writes are buffered in one large block and numbers are formatted with std::to_chars
// straight into it, so writers of 10^7-line files pay no stream or allocation per number.
//
// Destinations that are not plain files are handled as a plain open() would, never replaced:
//   - a symbolic link: the file it finally names is replaced, in that file's own directory, and
//     the link stays a link (a dangling link's missing file is created);
//   - a device, FIFO or socket (/dev/null, /dev/full, a named pipe) is written directly:
//     renaming over it would replace the device itself (as root, /dev/null for the machine);
//   - "-", /dev/stdout, /dev/stderr, /dev/fd/N and /proc/self/fd/N write to that already open
//     descriptor (a duplicate of it), after whatever std::cout and stdio hold for it.
// A replaced file keeps its permission bits.
//
// Errors are reported as lower-case reason strings; the only exception that can escape is
// std::bad_alloc from open() (the buffer) or from building an error message.

#include <charconv>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>

#include "support/interrupt_cleanup.hpp"

namespace oasis {

// The prefix of the hidden files an AtomicFile (or an AtomicFileSet) makes beside
// `destination`. The next open() of that destination deletes those whose flock is free: they
// were left by a writer that was killed.
[[nodiscard]] std::string temporary_sibling_prefix(const std::string& destination);

class AtomicFile {
 public:
  AtomicFile() = default;
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  AtomicFile(AtomicFile&& other) noexcept;
  AtomicFile& operator=(AtomicFile&& other) noexcept;
  ~AtomicFile();

  // Creates the temporary file for `path`. On failure returns false and sets `error`.
  [[nodiscard]] bool open(const std::string& path, std::string& error);

  void append(std::string_view text) {
    if (text.size() <= capacity_ - used_) {
      std::char_traits<char>::copy(buffer_.get() + used_, text.data(), text.size());
      used_ += text.size();
    } else {
      append_slow(text);
    }
  }
  void append(char c) {
    if (used_ == capacity_) flush_buffer();
    if (used_ < capacity_) buffer_[used_++] = c;
  }
  // Any integer, in decimal.
  template <typename Integer>
  requires std::is_integral_v<Integer>
  void append_number(Integer value) {
    if (capacity_ - used_ < kMaxNumberLength) flush_buffer();
    if (capacity_ - used_ < kMaxNumberLength) return;  // not open, or failed
    char* begin = buffer_.get() + used_;
    used_ +=
        static_cast<std::size_t>(std::to_chars(begin, begin + kMaxNumberLength, value).ptr - begin);
  }

  // Flushes, fsyncs and renames the temporary file over the destination. On failure (or
  // after an earlier write error) removes the temporary file, returns false, sets `error`.
  [[nodiscard]] bool commit(std::string& error);
  // commit() in two steps, for a set of files that must change together (AtomicFileSet).
  // prepare() flushes and fsyncs, and names the temporary file as a hidden sibling (never the
  // destination itself, which stays as it was); install() then renames it over the
  // destination. Either removes the temporary file on failure.
  [[nodiscard]] bool prepare(std::string& error);
  [[nodiscard]] bool install(std::string& error);
  // Removes the temporary file now; the destination is left as it was.
  void discard();

  [[nodiscard]] bool is_open() const { return fd_ >= 0; }
  // False once a write has failed; the reason is in error().
  [[nodiscard]] bool good() const { return error_.empty(); }
  [[nodiscard]] const std::string& error() const { return error_; }
  // The path given to open().
  [[nodiscard]] const std::string& path() const { return path_; }
  // The file that is replaced or written: path() with symbolic links followed.
  [[nodiscard]] const std::string& destination() const { return destination_; }
  // The temporary file's name; empty while it is anonymous and when writing directly.
  [[nodiscard]] const std::string& temporary_path() const { return temporary_path_; }
  // True when the bytes go straight to a device, FIFO, socket or open descriptor.
  [[nodiscard]] bool writes_directly() const { return direct_; }

 private:
  static constexpr std::size_t kBufferSize = std::size_t{1} << 20;
  static constexpr std::size_t kMaxNumberLength = 24;  // 20 digits of UINT64_MAX, a sign

  void append_slow(std::string_view text);
  // install()'s rename and release, in a commit section; install() then syncs the folder.
  [[nodiscard]] bool move_into_place(std::string& error);
  void flush_buffer();
  void write_all(const char* data, std::size_t size);
  void fail(std::string reason);
  void close_descriptor();
  void start_buffer();
  bool open_direct(const std::string& path, std::string& error);
  bool open_duplicate(int descriptor, std::string& error);
  bool open_temporary(std::string& error);
  bool finish_writing(bool may_take_destination);
  bool name_temporary(bool may_take_destination, std::string& error);
  void set_temporary_path(std::string path);
  std::string target() const;

  std::string path_;
  std::string destination_;
  std::string temporary_path_;
  interrupt::CleanupPath cleanup_;  // the named temporary file, removed if we are interrupted
  bool direct_ = false;             // writing straight to a device, FIFO, socket or descriptor
  bool anonymous_ = false;          // the temporary file has no name yet (O_TMPFILE)
  bool flush_stdio_ = false;        // the descriptor is stdout or stderr: flush theirs first
  int fd_ = -1;
  std::unique_ptr<char[]> buffer_;
  std::size_t capacity_ = 0;  // 0 until open(), so appends before open() write nothing
  std::size_t used_ = 0;
  std::string error_;
};

// Writes `path` as one unit: an AtomicFile opened, filled by write(file, error) (which returns
// false, with `error` set, to give up), and committed. On any failure `error` says why and the
// destination is as it was. What every writer of one whole file runs.
template <typename Write>
[[nodiscard]] bool write_atomically(const std::string& path, std::string& error, Write write) {
  AtomicFile file;
  if (!file.open(path, error)) return false;
  if (!write(file, error)) return false;  // `file` removes its temporary
  return file.commit(error);              // a write error reports here
}

// The same for a text or bytes already in memory.
[[nodiscard]] inline bool write_atomically(const std::string& path, std::string_view bytes,
                                           std::string& error) {
  return write_atomically(path, error, [bytes](AtomicFile& file, std::string&) {
    file.append(bytes);
    return true;
  });
}

}  // namespace oasis
