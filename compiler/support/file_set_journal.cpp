#include "support/file_set_journal.hpp"

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "support/error_report.hpp"
#include "support/path_text.hpp"

namespace oasis {
namespace {

constexpr std::string_view kPrefix = ".oasis-file-set.";
constexpr std::string_view kTemporarySuffix = ".tmp";
// The first line; the records follow as NUL-terminated fields, three per file.
constexpr std::string_view kHeader = "oasis file set journal 1\n";

std::atomic<int> crash_point{-1};

bool ends_with(std::string_view text, std::string_view suffix) {
  return text.size() >= suffix.size() && text.substr(text.size() - suffix.size()) == suffix;
}

// A path as the journal stores it: the base name when it lies in the journal's own directory
// (so the folder may be moved or reached from another working directory), else absolute.
std::string stored_path(const std::string& path, const std::string& directory) {
  if (path.empty()) return path;
  const std::size_t slash = path.rfind('/');
  if (directory_of(path) == directory && slash != std::string::npos) return path.substr(slash + 1);
  if (slash == std::string::npos && directory == ".") return path;
  if (path.front() == '/') return path;
  char* cwd = ::getcwd(nullptr, 0);
  std::string absolute = cwd != nullptr ? std::string(cwd) + "/" + path : path;
  std::free(cwd);
  return absolute;
}

std::string resolved_path(const std::string& stored, const std::string& directory) {
  if (stored.empty() || stored.front() == '/') return stored;
  return directory + "/" + stored;
}

bool write_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t written = ::write(fd, bytes.data(), bytes.size());
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) return false;
    bytes.remove_prefix(static_cast<std::size_t>(written));
  }
  return true;
}

bool read_all(int fd, std::string& text) {
  char buffer[1 << 14];
  for (;;) {
    const ssize_t got = ::read(fd, buffer, sizeof buffer);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) return false;
    if (got == 0) return true;
    text.append(buffer, static_cast<std::size_t>(got));
    if (text.size() > (std::size_t{64} << 20)) return false;  // no journal is this large
  }
}

// The entries of a journal's text; false when it is not one of ours.
bool parse_journal(std::string_view text, const std::string& directory,
                   std::vector<FileSetEntry>& entries) {
  if (text.substr(0, kHeader.size()) != kHeader) return false;
  text.remove_prefix(kHeader.size());
  std::vector<std::string> fields;
  while (!text.empty()) {
    const std::size_t end = text.find('\0');
    if (end == std::string_view::npos) return false;
    fields.emplace_back(text.substr(0, end));
    text.remove_prefix(end + 1);
  }
  if (fields.size() % 3 != 0) return false;
  for (std::size_t i = 0; i < fields.size(); i += 3)
    entries.push_back({resolved_path(fields[i], directory), resolved_path(fields[i + 1], directory),
                       resolved_path(fields[i + 2], directory)});
  return true;
}

bool exists(const std::string& path) {
  struct stat status {};
  return !path.empty() && ::lstat(path.c_str(), &status) == 0;
}

// Rolls the set forward: every new file still waiting goes in, removed files go, old copies go.
void finish_set(const std::vector<FileSetEntry>& entries) {
  for (const FileSetEntry& entry : entries) {
    if (entry.temporary.empty()) {
      if (!entry.old_copy.empty()) ::unlink(entry.destination.c_str());  // the set removes it
    } else if (exists(entry.temporary)) {
      ::rename(entry.temporary.c_str(), entry.destination.c_str());
    }
  }
  for (const FileSetEntry& entry : entries)
    if (!entry.old_copy.empty()) ::unlink(entry.old_copy.c_str());
}

// Opens `path` and takes its flock without waiting; -1 when a live writer holds it.
int lock_if_abandoned(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return -1;
  struct stat status {};
  if (::fstat(fd, &status) != 0 || !S_ISREG(status.st_mode) ||
      ::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd);
    return -1;
  }
  return fd;
}

// Finishes the set of one abandoned journal; true when it did.
bool repair_one(const std::string& directory, const std::string& name) {
  const std::string path = directory + "/" + name;
  const int fd = lock_if_abandoned(path);
  if (fd < 0) return false;
  if (ends_with(name, kTemporarySuffix)) {  // killed while writing it: no rename had begun
    ::unlink(path.c_str());
    ::close(fd);
    return false;
  }
  std::string text;
  std::vector<FileSetEntry> entries;
  const bool ours = read_all(fd, text) && parse_journal(text, directory, entries);
  if (ours) {
    finish_set(entries);
    sync_directory(directory);
    ::unlink(path.c_str());
    report_note(program_invocation_short_name,
                "finished replacing " + std::to_string(entries.size()) +
                    (entries.size() == 1 ? " file" : " files") + " beside '" +
                    (entries.empty() ? directory : entries.front().destination) +
                    "', which a run killed while it replaced them had left half done");
  }
  ::close(fd);
  return ours;
}

}  // namespace

FileSetJournal::~FileSetJournal() {
  finish();
}

bool FileSetJournal::write(const std::string& directory, const std::vector<FileSetEntry>& entries,
                           std::string& error) {
  static std::atomic<unsigned> counter{0};
  const std::string name = directory + "/" + std::string(kPrefix) + std::to_string(::getpid()) +
                           "." + std::to_string(++counter);
  const std::string temporary = name + std::string(kTemporarySuffix);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) {
    error = "cannot write the journal of the file set in '" + directory + "': " + reason_of(errno);
    return false;
  }
  ::flock(fd, LOCK_EX);  // held until finish(): a live commit is never taken for abandoned
  std::string text(kHeader);
  for (const FileSetEntry& entry : entries) {
    for (const std::string* field : {&entry.destination, &entry.temporary, &entry.old_copy}) {
      text += stored_path(*field, directory);
      text += '\0';
    }
  }
  if (!write_all(fd, text) || ::fsync(fd) != 0 || ::rename(temporary.c_str(), name.c_str()) != 0) {
    error = "cannot write the journal of the file set in '" + directory + "': " + reason_of(errno);
    ::unlink(temporary.c_str());
    ::close(fd);
    return false;
  }
  sync_directory(directory);
  path_ = name;
  fd_ = fd;
  return true;
}

void FileSetJournal::finish() {
  if (fd_ < 0) return;
  ::unlink(path_.c_str());
  ::close(fd_);
  fd_ = -1;
  path_.clear();
}

std::size_t repair_interrupted_file_sets(const std::string& directory) {
  DIR* listing = ::opendir(directory.c_str());
  if (listing == nullptr) return 0;
  std::vector<std::string> journals;
  while (const dirent* entry = ::readdir(listing)) {
    const std::string_view name = entry->d_name;
    if (name.substr(0, kPrefix.size()) == kPrefix) journals.emplace_back(name);
  }
  ::closedir(listing);
  std::size_t repaired = 0;
  for (const std::string& name : journals)
    repaired += repair_one(directory, name) ? 1 : 0;
  return repaired;
}

void set_file_set_crash_point_for_testing(int renames) {
  crash_point.store(renames);
}

int file_set_crash_point_for_testing() {
  return crash_point.load();
}

}  // namespace oasis
