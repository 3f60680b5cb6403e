#include "support/atomic_file_set.hpp"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>

#include <sys/stat.h>
#include <unistd.h>

#include "support/path_text.hpp"

namespace oasis {
namespace {

// A fresh hidden name beside `destination`, under AtomicFile's prefix so that the next writer
// of that destination removes it if we are killed while it exists.
std::string old_copy_name(const std::string& destination) {
  static std::atomic<unsigned> counter{0};
  return directory_of(destination) + "/" + temporary_sibling_prefix(destination) + "old." +
         std::to_string(::getpid()) + "." + std::to_string(++counter);
}

}  // namespace

// A destination as it was before the commit: `old_copy` is a hard link to its old file, or
// empty when there was none.
struct AtomicFileSet::Replaced {
  std::string destination;
  std::string old_copy;
  bool done = false;  // the new file (or the removal) is in place
};

AtomicFile* AtomicFileSet::add(const std::string& path, std::string& error) {
  auto file = std::make_unique<AtomicFile>();
  if (!file->open(path, error)) return nullptr;
  files_.push_back(std::move(file));
  return files_.back().get();
}

void AtomicFileSet::remove_at_commit(const std::string& path) {
  removals_.push_back(path);
}

bool AtomicFileSet::keep_old(const std::string& destination, Replaced& replaced,
                             std::string& error) {
  replaced.destination = destination;
  struct stat status {};
  if (::lstat(destination.c_str(), &status) != 0) return true;  // nothing to keep
  if (S_ISDIR(status.st_mode)) {
    error = "cannot replace '" + destination + "': it is a directory";
    return false;
  }
  for (int attempt = 0; attempt < 10; ++attempt) {
    std::string name = old_copy_name(destination);
    if (::link(destination.c_str(), name.c_str()) == 0) {
      replaced.old_copy = std::move(name);
      return true;
    }
    if (errno != EEXIST) break;
  }
  error = "cannot keep '" + destination + "' until the new set is in place: " + reason_of(errno);
  return false;
}

void AtomicFileSet::restore(const std::vector<Replaced>& replaced) {
  for (const Replaced& entry : replaced) {
    if (entry.done) {
      if (entry.old_copy.empty()) {
        ::unlink(entry.destination.c_str());
      } else {
        ::rename(entry.old_copy.c_str(), entry.destination.c_str());
      }
    } else if (!entry.old_copy.empty()) {
      ::unlink(entry.old_copy.c_str());
    }
  }
}

bool AtomicFileSet::commit(std::string& error) {
  for (auto& file : files_) {
    if (!file->good()) {
      error = file->error();
      discard();
      return false;
    }
    if (!file->prepare(error)) {
      discard();
      return false;
    }
  }
  const interrupt::CommitSection section;  // a signal waits for the whole set
  std::vector<Replaced> replaced(files_.size() + removals_.size());
  for (std::size_t i = 0; i < replaced.size(); ++i) {
    const std::string& destination =
        i < files_.size() ? files_[i]->destination() : removals_[i - files_.size()];
    if (i < files_.size() && files_[i]->writes_directly()) continue;  // a device: no old file
    if (!keep_old(destination, replaced[i], error)) {
      restore(replaced);
      discard();
      return false;
    }
  }
  // From here on every new file is complete: a run killed during the renames is finished by
  // the next writer in this folder (file_set_journal.hpp).
  FileSetJournal journal;
  if (!write_journal(replaced, journal, error)) {
    restore(replaced);
    discard();
    return false;
  }
  const int crash_point = file_set_crash_point_for_testing();
  for (std::size_t i = 0; i < replaced.size(); ++i) {
    if (static_cast<int>(i) == crash_point) ::raise(SIGKILL);
    if (i < files_.size()) {
      if (!files_[i]->install(error)) {
        restore(replaced);
        discard();
        return false;  // the journal goes with its destructor, after the old set is back
      }
    } else if (!replaced[i].old_copy.empty()) {
      ::unlink(replaced[i].destination.c_str());
    }
    replaced[i].done = true;
  }
  journal.finish();
  for (const Replaced& entry : replaced) {
    if (!entry.old_copy.empty()) ::unlink(entry.old_copy.c_str());
  }
  files_.clear();
  removals_.clear();
  return true;
}

bool AtomicFileSet::write_journal(const std::vector<Replaced>& replaced, FileSetJournal& journal,
                                  std::string& error) const {
  std::vector<FileSetEntry> entries;
  for (std::size_t i = 0; i < replaced.size(); ++i) {
    if (replaced[i].destination.empty()) continue;  // written directly: nothing to rename
    FileSetEntry entry{replaced[i].destination, "", replaced[i].old_copy};
    if (i < files_.size()) entry.temporary = files_[i]->temporary_path();
    entries.push_back(std::move(entry));
  }
  if (entries.empty()) return true;
  return journal.write(directory_of(entries.front().destination), entries, error);
}

void AtomicFileSet::discard() {
  files_.clear();  // each AtomicFile removes its temporary file
  removals_.clear();
}

}  // namespace oasis
