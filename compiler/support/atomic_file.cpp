#include "support/atomic_file.hpp"

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <utility>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace oasis {
namespace {

// strerror() capitalises; our messages are lower-case fragments.
std::string reason_of(int code) {
  std::string text = std::strerror(code);
  if (!text.empty() && text[0] >= 'A' && text[0] <= 'Z') {
    text[0] = static_cast<char>(text[0] - 'A' + 'a');
  }
  return text;
}

std::string directory_of(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

std::string base_name_of(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// A name no other writer uses: pid, a clock reading and a per-process counter, mixed so that
// retries after EEXIST differ in every character position that matters.
std::string unique_suffix(unsigned attempt) {
  static std::atomic<unsigned> counter{0};
  std::uint64_t mix = static_cast<std::uint64_t>(::getpid());
  mix = mix * 0x9e3779b97f4a7c15ULL +
        static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
  mix = mix * 0x9e3779b97f4a7c15ULL + ++counter + attempt;
  static constexpr char kAlphabet[] = "abcdefghijklmnopqrstuvwxyz0123456789";
  std::string suffix;
  for (int i = 0; i < 10; ++i) {
    suffix += kAlphabet[mix % 36];
    mix /= 36;
    if (mix == 0) mix = 0x2545f4914f6cdd1dULL + attempt;
  }
  return suffix;
}

// Makes the rename itself durable. Best effort: some file systems refuse fsync on a
// directory, and the data is already safe.
void sync_directory(const std::string& directory) {
  const int fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

AtomicFile::AtomicFile(AtomicFile&& other) noexcept {
  *this = std::move(other);
}

AtomicFile& AtomicFile::operator=(AtomicFile&& other) noexcept {
  if (this != &other) {
    discard();
    path_ = std::move(other.path_);
    temporary_path_ = std::move(other.temporary_path_);
    direct_ = std::exchange(other.direct_, false);
    fd_ = std::exchange(other.fd_, -1);
    buffer_ = std::move(other.buffer_);
    capacity_ = std::exchange(other.capacity_, 0);
    used_ = std::exchange(other.used_, 0);
    error_ = std::move(other.error_);
    other.temporary_path_.clear();
  }
  return *this;
}

AtomicFile::~AtomicFile() {
  discard();
}

bool AtomicFile::open(const std::string& path, std::string& error) {
  discard();
  error_.clear();
  path_ = path;
  direct_ = false;
  struct stat status {};
  if (::stat(path.c_str(), &status) == 0 &&
      (S_ISCHR(status.st_mode) || S_ISFIFO(status.st_mode) || S_ISSOCK(status.st_mode)))
    return open_direct(path, error);
  const std::string prefix = directory_of(path) + "/." + base_name_of(path) + ".tmp.";
  // O_EXCL with mode 0666 is mkstemp's guarantee plus the umask's permissions, so the
  // committed file gets the same permissions a plain open() would have given it.
  for (unsigned attempt = 0; attempt < 100; ++attempt) {
    std::string candidate = prefix + unique_suffix(attempt);
    const int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      fd_ = fd;
      temporary_path_ = std::move(candidate);
      if (!buffer_) buffer_ = std::make_unique<char[]>(kBufferSize);
      capacity_ = kBufferSize;
      used_ = 0;
      return true;
    }
    if (errno != EEXIST) {
      error = "cannot create a temporary file next to '" + path + "': " + reason_of(errno);
      return false;
    }
  }
  error = "cannot create a temporary file next to '" + path + "': too many name collisions";
  return false;
}

bool AtomicFile::open_direct(const std::string& path, std::string& error) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) {
    error = "cannot open '" + path + "': " + reason_of(errno);
    return false;
  }
  fd_ = fd;
  direct_ = true;
  if (!buffer_) buffer_ = std::make_unique<char[]>(kBufferSize);
  capacity_ = kBufferSize;
  used_ = 0;
  return true;
}

void AtomicFile::append_slow(std::string_view text) {
  flush_buffer();
  if (text.size() < capacity_) {
    std::char_traits<char>::copy(buffer_.get(), text.data(), text.size());
    used_ = text.size();
  } else if (fd_ >= 0 && good()) {
    write_all(text.data(), text.size());  // larger than the buffer: no point copying
  }
}

void AtomicFile::flush_buffer() {
  if (used_ > 0 && fd_ >= 0 && good()) write_all(buffer_.get(), used_);
  used_ = 0;
}

void AtomicFile::write_all(const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t written = ::write(fd_, data, size);
    if (written < 0) {
      if (errno == EINTR) continue;
      fail("cannot write '" + target() + "': " + reason_of(errno));
      return;
    }
    data += written;
    size -= static_cast<std::size_t>(written);
  }
}

void AtomicFile::fail(std::string reason) {
  if (error_.empty()) error_ = std::move(reason);
}

void AtomicFile::close_descriptor() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

bool AtomicFile::commit(std::string& error) {
  if (fd_ < 0 && good()) fail("file '" + path_ + "' was not opened");
  flush_buffer();
  if (good() && !direct_ && ::fsync(fd_) != 0)
    fail("cannot sync '" + temporary_path_ + "': " + reason_of(errno));
  if (good()) {
    const int result = ::close(fd_);
    fd_ = -1;
    if (result != 0) fail("cannot close '" + target() + "': " + reason_of(errno));
  }
  if (direct_) {
    if (!good()) {
      error = error_;
      discard();
      return false;
    }
    capacity_ = 0;
    return true;
  }
  if (good() && ::rename(temporary_path_.c_str(), path_.c_str()) != 0) {
    fail("cannot rename '" + temporary_path_ + "' to '" + path_ + "': " + reason_of(errno));
  }
  if (!good()) {
    error = error_;
    discard();
    return false;
  }
  temporary_path_.clear();
  capacity_ = 0;
  sync_directory(directory_of(path_));
  return true;
}

void AtomicFile::discard() {
  close_descriptor();
  if (!temporary_path_.empty()) ::unlink(temporary_path_.c_str());
  temporary_path_.clear();
  capacity_ = 0;
  used_ = 0;
}

}  // namespace oasis
