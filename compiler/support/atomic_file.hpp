#pragma once
// An output file that appears whole or not at all. Bytes go to a fresh temporary file in the
// destination's directory (same file system, so the final rename is atomic); commit() flushes,
// fsyncs and renames it over the destination. Destroying an uncommitted AtomicFile, or any
// write error, removes the temporary file: a failed run never leaves half a model behind.
//
// Writes are buffered in one large block and numbers are formatted with std::to_chars
// straight into it, so writers of 10^7-line files pay no stream or allocation per number.
//
// A destination that is a device, FIFO or socket (/dev/null, /dev/stdout, a pipe) is written
// directly: there is nothing to replace atomically, and renaming over it would replace the
// device itself with a regular file (as root, /dev/null for the whole machine).
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

namespace oasis {

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
  // Removes the temporary file now; the destination is left as it was.
  void discard();

  [[nodiscard]] bool is_open() const { return fd_ >= 0; }
  // False once a write has failed; the reason is in error().
  [[nodiscard]] bool good() const { return error_.empty(); }
  [[nodiscard]] const std::string& error() const { return error_; }
  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] const std::string& temporary_path() const { return temporary_path_; }

 private:
  static constexpr std::size_t kBufferSize = std::size_t{1} << 20;
  static constexpr std::size_t kMaxNumberLength = 24;  // 20 digits of UINT64_MAX, a sign

  void append_slow(std::string_view text);
  void flush_buffer();
  void write_all(const char* data, std::size_t size);
  void fail(std::string reason);
  void close_descriptor();
  bool open_direct(const std::string& path, std::string& error);
  const std::string& target() const { return direct_ ? path_ : temporary_path_; }

  std::string path_;
  std::string temporary_path_;
  bool direct_ = false;  // writing straight to a device, FIFO or socket (no temporary)
  int fd_ = -1;
  std::unique_ptr<char[]> buffer_;
  std::size_t capacity_ = 0;  // 0 until open(), so appends before open() write nothing
  std::size_t used_ = 0;
  std::string error_;
};

}  // namespace oasis
