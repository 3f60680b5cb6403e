#include "support/atomic_file.hpp"

#include <atomic>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <climits>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <optional>
#include <utility>
#include <vector>

#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "support/file_set_journal.hpp"
#include "support/path_text.hpp"

namespace oasis {
namespace {

// The kernel's own limit on symbolic links followed in one lookup (ELOOP past it).
constexpr int kMaxLinksFollowed = 40;

std::string base_name_of(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string temporary_prefix(const std::string& destination) {
  return temporary_sibling_prefix(destination);
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

// The descriptor that `path` names without being a file of its own: "-" is standard output,
// and /dev/stdout, /dev/fd/N or /proc/self/fd/N are the calling process's descriptors.
// Opening such a name again would start a second file offset (overwriting what was already
// written to a redirected stdout), and following it would rename over the shell's file.
std::optional<int> descriptor_named(const std::string& path) {
  if (path == "-" || path == "/dev/stdout") return STDOUT_FILENO;
  if (path == "/dev/stderr") return STDERR_FILENO;
  const std::string own_fd_folder = "/proc/" + std::to_string(::getpid()) + "/fd/";
  for (const std::string& folder : {std::string("/dev/fd/"), std::string("/proc/self/fd/"),
                                    std::string("/proc/thread-self/fd/"), own_fd_folder}) {
    if (path.size() <= folder.size() || path.compare(0, folder.size(), folder) != 0) continue;
    int descriptor = -1;
    const char* first = path.data() + folder.size();
    const char* last = path.data() + path.size();
    const auto [end, code] = std::from_chars(first, last, descriptor);
    if (code == std::errc() && end == last && descriptor >= 0) return descriptor;
  }
  return std::nullopt;
}

// Where writing to `path` really goes: a descriptor (above), or the file at the end of its
// chain of symbolic links. A dangling link ends at the missing file it names, which is
// created there, as a plain open() through the link would. Replacing the final file in its
// own directory keeps the link a link and updates what every other name of it sees.
struct Destination {
  std::string path;
  std::optional<int> descriptor;
};

bool resolve(std::string path, Destination& destination, std::string& error) {
  for (int followed = 0; followed <= kMaxLinksFollowed; ++followed) {
    if ((destination.descriptor = descriptor_named(path))) return true;
    struct stat status {};
    if (::lstat(path.c_str(), &status) != 0 || !S_ISLNK(status.st_mode)) {
      destination.path = std::move(path);
      return true;
    }
    // st_size is the link's length, except for links the kernel makes up (0 in /proc).
    std::vector<char> text(static_cast<std::size_t>(status.st_size > 0 ? status.st_size : 0) + 1);
    ssize_t length = 0;
    while ((length = ::readlink(path.c_str(), text.data(), text.size())) >= 0 &&
           static_cast<std::size_t>(length) == text.size() && text.size() < PATH_MAX) {
      text.resize(text.size() * 2);  // possibly truncated: the link grew, or st_size was 0
    }
    if (length < 0) {
      error = "cannot read the symbolic link '" + path + "': " + reason_of(errno);
      return false;
    }
    std::string target(text.data(), static_cast<std::size_t>(length));
    path = !target.empty() && target.front() == '/' ? target : directory_of(path) + "/" + target;
  }
  error = "cannot follow '" + path + "': " + reason_of(ELOOP);
  return false;
}

// Temporary files of killed writers beside `destination`: their flock is free, whereas a
// live writer holds it from creation to rename.
void remove_stale_temporaries(const std::string& destination) {
  const std::string directory = directory_of(destination);
  const std::string prefix = temporary_prefix(destination);
  DIR* listing = ::opendir(directory.c_str());
  if (listing == nullptr) return;
  std::vector<std::string> stale;
  while (const dirent* entry = ::readdir(listing)) {
    const std::string name = entry->d_name;
    if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string path = directory + "/" + name;
    const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) continue;
    struct stat status {};
    if (::fstat(fd, &status) == 0 && S_ISREG(status.st_mode) && ::flock(fd, LOCK_EX | LOCK_NB) == 0)
      stale.push_back(path);
    ::close(fd);
  }
  ::closedir(listing);
  for (const std::string& path : stale)
    ::unlink(path.c_str());
}

}  // namespace

std::string temporary_sibling_prefix(const std::string& destination) {
  return "." + base_name_of(destination) + ".tmp.";
}

AtomicFile::AtomicFile(AtomicFile&& other) noexcept {
  *this = std::move(other);
}

AtomicFile& AtomicFile::operator=(AtomicFile&& other) noexcept {
  if (this != &other) {
    discard();
    path_ = std::move(other.path_);
    destination_ = std::move(other.destination_);
    temporary_path_ = std::move(other.temporary_path_);
    cleanup_ = std::move(other.cleanup_);
    direct_ = std::exchange(other.direct_, false);
    anonymous_ = std::exchange(other.anonymous_, false);
    flush_stdio_ = std::exchange(other.flush_stdio_, false);
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
  destination_.clear();
  direct_ = false;
  anonymous_ = false;
  flush_stdio_ = false;
  Destination destination;
  if (!resolve(path, destination, error)) return false;
  if (destination.descriptor) return open_duplicate(*destination.descriptor, error);
  destination_ = std::move(destination.path);
  struct stat status {};
  const bool exists = ::stat(destination_.c_str(), &status) == 0;
  if (exists && (S_ISCHR(status.st_mode) || S_ISFIFO(status.st_mode) || S_ISSOCK(status.st_mode)))
    return open_direct(destination_, error);
  // First finish a set a killed writer left half replaced (its new files are stale-looking
  // temporaries that the clean-up below would otherwise delete), then clear the leftovers.
  repair_interrupted_file_sets(directory_of(destination_));
  remove_stale_temporaries(destination_);
  if (!open_temporary(error)) return false;
  // Held until the rename, so that no other writer's clean-up takes this file for stale.
  ::flock(fd_, LOCK_EX);
  // The replacement keeps the replaced file's permissions (an executable stays executable).
  // Best effort: only the owner may change them, and the default is still a usable file.
  if (exists && S_ISREG(status.st_mode)) ::fchmod(fd_, status.st_mode & 07777);
  start_buffer();
  return true;
}

bool AtomicFile::open_temporary(std::string& error) {
  const std::string directory = directory_of(destination_);
  // An anonymous file can only be given a name through /proc/self/fd (or with a capability
  // most users lack), so it is used only when /proc is there.
  if (::access("/proc/self/fd", X_OK) == 0) {
    const int fd = ::open(directory.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
    if (fd >= 0) {
      fd_ = fd;
      anonymous_ = true;
      return true;
    }
    // File systems without O_TMPFILE refuse it (EOPNOTSUPP, EISDIR): use a named file.
  }
  const std::string prefix = directory + "/" + temporary_prefix(destination_);
  const interrupt::CommitSection section;  // a signal waits until the new file is registered
  // O_EXCL with mode 0666 is mkstemp's guarantee plus the umask's permissions, so the
  // committed file gets the same permissions a plain open() would have given it.
  for (unsigned attempt = 0; attempt < 100; ++attempt) {
    std::string candidate = prefix + unique_suffix(attempt);
    const int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      fd_ = fd;
      set_temporary_path(std::move(candidate));
      return true;
    }
    if (errno != EEXIST) {
      error = "cannot create a temporary file next to '" + path_ + "': " + reason_of(errno);
      return false;
    }
  }
  error = "cannot create a temporary file next to '" + path_ + "': too many name collisions";
  return false;
}

bool AtomicFile::open_direct(const std::string& path, std::string& error) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) {
    error = "cannot open '" + path_ + "': " + reason_of(errno);
    return false;
  }
  fd_ = fd;
  direct_ = true;
  start_buffer();
  return true;
}

bool AtomicFile::open_duplicate(int descriptor, std::string& error) {
  // A duplicate, so that commit() closes ours and the process's stdout stays open for the
  // final check of standard output (support/standard_output.hpp).
  const int fd = ::fcntl(descriptor, F_DUPFD_CLOEXEC, 0);
  if (fd < 0) {
    error = "cannot write " + (path_ == "-" ? "standard output" : "'" + path_ + "'") + ": " +
            reason_of(errno);
    return false;
  }
  fd_ = fd;
  direct_ = true;
  flush_stdio_ = descriptor == STDOUT_FILENO || descriptor == STDERR_FILENO;
  start_buffer();
  return true;
}

void AtomicFile::start_buffer() {
  if (!buffer_) buffer_ = std::make_unique<char[]>(kBufferSize);
  capacity_ = kBufferSize;
  used_ = 0;
}

std::string AtomicFile::target() const {
  if (path_ == "-") return "standard output";
  return "'" + (direct_ ? path_ : temporary_path_.empty() ? destination_ : temporary_path_) + "'";
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
  if (flush_stdio_) {
    // What the program printed before this file's bytes must arrive before them.
    std::cout.flush();
    std::cerr.flush();
    std::fflush(stdout);
    std::fflush(stderr);
  }
  while (size > 0) {
    const ssize_t written = ::write(fd_, data, size);
    if (written < 0) {
      if (errno == EINTR) continue;
      fail("cannot write " + target() + ": " + reason_of(errno));
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

// Gives the anonymous temporary file a name in the destination's directory: the destination
// itself when it does not exist yet (no rename needed), else a hidden sibling to rename.
void AtomicFile::set_temporary_path(std::string path) {
  temporary_path_ = std::move(path);
  cleanup_ = interrupt::CleanupPath(temporary_path_, interrupt::CleanupPath::Kind::kFile);
}

bool AtomicFile::name_temporary(bool may_take_destination, std::string& error) {
  const std::string descriptor_path = "/proc/self/fd/" + std::to_string(fd_);
  const auto link_as = [&](const std::string& name) {
    return ::linkat(AT_FDCWD, descriptor_path.c_str(), AT_FDCWD, name.c_str(), AT_SYMLINK_FOLLOW) ==
           0;
  };
  if (may_take_destination) {
    if (link_as(destination_)) {
      anonymous_ = false;
      return true;
    }
    if (errno != EEXIST) {
      error = "cannot create '" + destination_ + "': " + reason_of(errno);
      return false;
    }
  }
  const std::string prefix = directory_of(destination_) + "/" + temporary_prefix(destination_);
  const interrupt::CommitSection section;  // a signal waits until the new name is registered
  for (unsigned attempt = 0; attempt < 100; ++attempt) {
    std::string candidate = prefix + unique_suffix(attempt);
    if (link_as(candidate)) {
      set_temporary_path(std::move(candidate));
      anonymous_ = false;
      return true;
    }
    if (errno != EEXIST) break;
  }
  error = "cannot name a temporary file next to '" + path_ + "': " + reason_of(errno);
  return false;
}

// Flushes and syncs the bytes, and gives an anonymous temporary file a name: the destination's
// own when that is allowed and free (the file is then in place), else a hidden sibling.
bool AtomicFile::finish_writing(bool may_take_destination) {
  if (fd_ < 0 && good()) fail("file '" + path_ + "' was not opened");
  flush_buffer();
  if (good() && !direct_ && ::fsync(fd_) != 0)
    fail("cannot sync " + target() + ": " + reason_of(errno));
  if (good() && anonymous_) {
    std::string naming_error;
    if (!name_temporary(may_take_destination, naming_error)) fail(std::move(naming_error));
  }
  return good();
}

bool AtomicFile::prepare(std::string& error) {
  if (finish_writing(false)) return true;
  error = error_;
  discard();
  return false;
}

bool AtomicFile::install(std::string& error) {
  if (!move_into_place(error)) return false;
  // Outside the commit section: a directory's sync can wait seconds for a busy disk, and a
  // signal must not wait that long (mpirun sends SIGKILL one second after SIGTERM).
  if (!direct_) sync_directory(directory_of(destination_));
  return true;
}

bool AtomicFile::move_into_place(std::string& error) {
  // A signal waits until the file is in place and no longer registered for clean-up.
  const interrupt::CommitSection section;
  if (fd_ < 0 && good()) fail("file '" + path_ + "' was not prepared");
  if (good() && !temporary_path_.empty() &&
      ::rename(temporary_path_.c_str(), destination_.c_str()) != 0) {
    fail("cannot rename '" + temporary_path_ + "' to '" + destination_ + "': " + reason_of(errno));
  }
  if (good()) {
    // Closed after the rename: the flock must cover the temporary file's whole named life.
    const int result = ::close(fd_);
    fd_ = -1;
    if (result != 0 && direct_) fail("cannot close " + target() + ": " + reason_of(errno));
  }
  if (!good()) {
    error = error_;
    discard();
    return false;
  }
  temporary_path_.clear();
  cleanup_.release();
  capacity_ = 0;
  return true;
}

bool AtomicFile::commit(std::string& error) {
  if (!finish_writing(true)) {
    error = error_;
    discard();
    return false;
  }
  return install(error);
}

void AtomicFile::discard() {
  close_descriptor();  // an anonymous temporary file disappears with its last descriptor
  if (!temporary_path_.empty()) ::unlink(temporary_path_.c_str());
  temporary_path_.clear();
  cleanup_.release();
  anonymous_ = false;
  capacity_ = 0;
  used_ = 0;
}

}  // namespace oasis
