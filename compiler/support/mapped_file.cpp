#include "support/mapped_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <string>
#include <utility>

#include <fcntl.h>
#include <poll.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace oasis {
namespace {

// Closes a descriptor on every path out of open().
class FileDescriptor {
 public:
  explicit FileDescriptor(int fd) : fd_(fd) {}
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  ~FileDescriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  int get() const { return fd_; }

 private:
  int fd_;
};

// strerror() capitalises; our diagnostics are lower-case fragments.
std::string system_error_text(int code) {
  std::string text = std::strerror(code);
  if (!text.empty() && text[0] >= 'A' && text[0] <= 'Z')
    text[0] = static_cast<char>(text[0] - 'A' + 'a');
  return text;
}

std::string too_large_message(std::size_t max_bytes) {
  return "file is larger than the limit of " + std::to_string(max_bytes) + " bytes";
}

// How long a FIFO (a named pipe, or `<(command)`) may stay silent before it counts as one that
// nobody writes to: a writer that is there delivers at once; none would block open() forever.
constexpr int kPipeWaitMs = 5000;

// A pipe is usable once its writer has written or closed; false (with `error`) if neither
// happened within kPipeWaitMs.
bool wait_for_writer(int fd, std::string& error) {
  pollfd waiting{fd, POLLIN, 0};
  for (;;) {
    const int ready = ::poll(&waiting, 1, kPipeWaitMs);
    if (ready > 0) return true;
    if (ready < 0 && errno == EINTR) continue;
    error = ready == 0 ? "is a pipe that nobody writes to (nothing arrived in " +
                             std::to_string(kPipeWaitMs / 1000) + " s)"
                       : system_error_text(errno);
    return false;
  }
}

}  // namespace

MappedFile::MappedFile(MappedFile&& other) noexcept {
  *this = std::move(other);
}

MappedFile& MappedFile::operator=(MappedFile&& other) noexcept {
  if (this != &other) {
    release();
    mapped_ = std::exchange(other.mapped_, false);
    size_ = std::exchange(other.size_, 0);
    owned_ = std::move(other.owned_);
    data_ = mapped_ ? std::exchange(other.data_, "") : owned_.data();
    other.data_ = "";
  }
  return *this;
}

MappedFile::~MappedFile() {
  release();
}

void MappedFile::release() {
  if (mapped_) ::munmap(const_cast<char*>(data_), size_);
  mapped_ = false;
  data_ = "";
  size_ = 0;
  owned_.clear();
}

void MappedFile::release_pages_before(std::size_t bytes) const {
  if (!mapped_) return;
  const auto page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
  const std::size_t whole_pages = std::min(bytes, size_) / page * page;
  // A hint: when it fails the pages simply stay resident.
  if (whole_pages > 0) ::madvise(const_cast<char*>(data_), whole_pages, MADV_DONTNEED);
}

bool MappedFile::open(const std::string& path, std::size_t max_bytes, std::string& error) {
  release();
  // Non-blocking, so that opening a FIFO nobody writes to does not wait forever.
  FileDescriptor fd(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
  if (fd.get() < 0) {
    error = system_error_text(errno);
    return false;
  }
  struct stat info {};
  if (::fstat(fd.get(), &info) != 0) {
    error = system_error_text(errno);
    return false;
  }
  if (S_ISDIR(info.st_mode)) {
    error = "is a directory";
    return false;
  }
  if (S_ISFIFO(info.st_mode) && !wait_for_writer(fd.get(), error)) return false;
  // Reading blocks again from here: a pipe with a writer delivers what it writes.
  ::fcntl(fd.get(), F_SETFL, ::fcntl(fd.get(), F_GETFL) & ~O_NONBLOCK);
  if (S_ISREG(info.st_mode) && info.st_size > 0) {
    const auto size = static_cast<std::size_t>(info.st_size);
    if (size > max_bytes) {
      error = too_large_message(max_bytes);
      return false;
    }
    void* address = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd.get(), 0);
    if (address != MAP_FAILED) {
      ::madvise(address, size, MADV_SEQUENTIAL);
      data_ = static_cast<const char*>(address);
      size_ = size;
      mapped_ = true;
      return true;
    }
  }
  // Pipes, character devices and empty files: read what there is, up to the limit.
  char buffer[1 << 16];
  for (;;) {
    const ssize_t count = ::read(fd.get(), buffer, sizeof buffer);
    if (count < 0) {
      if (errno == EINTR) continue;
      error = system_error_text(errno);
      owned_.clear();
      return false;
    }
    if (count == 0) break;
    if (owned_.size() + static_cast<std::size_t>(count) > max_bytes) {
      error = too_large_message(max_bytes);
      owned_.clear();
      return false;
    }
    owned_.append(buffer, static_cast<std::size_t>(count));
  }
  data_ = owned_.data();
  size_ = owned_.size();
  return true;
}

}  // namespace oasis
