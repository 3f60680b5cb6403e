#include "support/mapped_file.hpp"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <utility>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "files/input_file.hpp"
#include "support/interrupt_cleanup.hpp"
#include "text/printable_text.hpp"

namespace oasis {
namespace {

// The registry of live mappings that the SIGBUS handler reads (see mapped_file.hpp). Slots are
// claimed and freed with atomics only, so that the handler never sees one half-written.
namespace shrink {

constexpr int kSlots = 64;
constexpr std::size_t kMaxPathShown = 1000;
constexpr std::size_t kMaxMessage = kMaxPathShown + 256;

enum SlotState : int { kFree = 0, kFilling = 1, kReady = 2 };

struct Slot {
  std::atomic<int> state{kFree};
  const char* begin = nullptr;
  std::size_t size = 0;
  std::size_t length = 0;
  char message[kMaxMessage] = {};
};

Slot slots[kSlots];
struct sigaction previous_action {};
std::once_flag installed;
std::string note;

void write_all(const char* text, std::size_t length) {
  while (length > 0) {
    const ssize_t written = ::write(STDERR_FILENO, text, length);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) return;
    text += written;
    length -= static_cast<std::size_t>(written);
  }
}

void on_bus_error(int /*signal_number*/, siginfo_t* info, void* /*context*/) {
  const auto* address = static_cast<const char*>(info->si_addr);
  for (const Slot& slot : slots) {
    if (slot.state.load(std::memory_order_acquire) != kReady) continue;
    if (address < slot.begin || address >= slot.begin + slot.size) continue;
    write_all(slot.message, slot.length);
    interrupt::remove_unfinished_output_now();
    ::_exit(1);
  }
  // Not a mapping of ours: the handler from before takes over when the access is repeated on
  // return; a SIGBUS that was sent rather than caused would not repeat, so it is sent again.
  ::sigaction(SIGBUS, &previous_action, nullptr);
  if (info->si_code <= 0) ::raise(SIGBUS);
}

// Installed with the first mapping, which in oasisc-mpi comes after MPI_Init has put OpenMPI's
// handler in place: ours is then the one in force, and OpenMPI's the one it hands over to.
void install_handler() {
  struct sigaction action {};
  action.sa_sigaction = on_bus_error;
  action.sa_flags = SA_SIGINFO;
  sigemptyset(&action.sa_mask);
  ::sigaction(SIGBUS, &action, &previous_action);
}

// The slot now watching [begin, begin + size), or -1 when every slot is taken (the file is
// then read unwatched, as before).
int watch(const char* begin, std::size_t size, const std::string& path) {
  std::call_once(installed, install_handler);
  const std::string message = text::printable_excerpt(path, kMaxPathShown) +
                              ": error: the file changed size while being read" + note + "\n";
  const std::size_t length = std::min(message.size(), kMaxMessage);
  for (int i = 0; i < kSlots; ++i) {
    int expected = kFree;
    if (!slots[i].state.compare_exchange_strong(expected, kFilling)) continue;
    slots[i].begin = begin;
    slots[i].size = size;
    std::memcpy(slots[i].message, message.data(), length);
    slots[i].length = length;
    slots[i].state.store(kReady, std::memory_order_release);
    return i;
  }
  return -1;
}

void unwatch(int slot) {
  if (slot >= 0) slots[slot].state.store(kFree, std::memory_order_release);
}

}  // namespace shrink

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

std::string too_large_message(std::size_t max_bytes) {
  return "file is larger than the limit of " + std::to_string(max_bytes) + " bytes";
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
    fault_slot_ = std::exchange(other.fault_slot_, -1);
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
  shrink::unwatch(std::exchange(fault_slot_, -1));  // before the range can be mapped again
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
  // The readers' one rule (common/files/input_file.hpp): a directory, device or socket is
  // refused, and a pipe is read once its writer has written (refused after 5 s of silence).
  struct stat info {};
  FileDescriptor fd(files::open_input(path, info, error));
  if (fd.get() < 0) return false;
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
      fault_slot_ = shrink::watch(data_, size_, path);
      return true;
    }
  }
  // Pipes and empty files: read what there is, up to the limit.
  const files::ReadResult read = files::read_to_end(fd.get(), max_bytes, owned_, error);
  if (read != files::ReadResult::kWhole) {
    if (read == files::ReadResult::kTooLarge) error = too_large_message(max_bytes);
    owned_.clear();
    return false;
  }
  data_ = owned_.data();
  size_ = owned_.size();
  return true;
}

void MappedFile::shrink_if_testing(const std::string& path) const {
  const char* wanted = std::getenv("OASIS_TEST_SHRINK_INPUT");
  if (wanted == nullptr || !mapped_) return;
  std::uint64_t bytes = 0;
  const char* end = wanted + std::strlen(wanted);
  const auto [stop, code] = std::from_chars(wanted, end, bytes);
  if (code != std::errc() || stop != end || bytes >= size_) return;
  // Should the cut fail, the reader meets the whole file and the test that asked fails.
  if (::truncate(path.c_str(), static_cast<off_t>(bytes)) != 0) return;
}

void set_changed_size_note(const std::string& note) {
  shrink::note = note;
}

}  // namespace oasis
