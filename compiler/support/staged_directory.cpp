#include "support/staged_directory.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "support/atomic_file.hpp"
#include "support/path_text.hpp"

namespace oasis {
namespace {

namespace fs = std::filesystem;

// The kernel's own limit on symbolic links followed in one lookup (ELOOP past it).
constexpr int kMaxLinksFollowed = 40;

std::string staging_prefix(const fs::path& target) {
  return "." + target.filename().string() + ".oasisc-staging.";
}

void sync_path(const fs::path& directory) {
  sync_directory(directory.string());
}

// Staging directories of killed writers: their flock is free. A live writer holds it.
void remove_stale_siblings(const fs::path& target) {
  const std::string prefix = staging_prefix(target);
  std::error_code ec;
  std::vector<fs::path> stale;
  for (const auto& entry : fs::directory_iterator(target.parent_path(), ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const int fd = ::open(entry.path().c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC | O_NOFOLLOW);
    if (fd < 0) continue;
    if (::flock(fd, LOCK_EX | LOCK_NB) == 0) stale.push_back(entry.path());
    ::close(fd);
  }
  for (const fs::path& path : stale)
    fs::remove_all(path, ec);
}

bool owned_or_empty(const fs::path& target, std::string& error) {
  std::error_code ec;
  if (!fs::exists(target, ec)) return true;
  if (!fs::is_directory(target, ec)) {
    error = "'" + target.string() + "' exists and is not a directory";
    return false;
  }
  if (fs::is_empty(target, ec) || fs::exists(target / StagedDirectory::kMarkerName, ec))
    return true;
  error = "'" + target.string() +
          "' holds files that oasisc did not write; the output directory is replaced as a "
          "whole, so give a new or empty directory (or one an earlier compile wrote)";
  return false;
}

int exchange(const fs::path& from, const fs::path& to) {
  return ::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_EXCHANGE);
}

// Puts `staging` in place of `target`. `old_set` is where the replaced set then lies: the
// staging name after an exchange, a hidden sibling after the fallback's two renames, or ""
// when there was no target.
bool swap_into_place(const fs::path& staging, const fs::path& target, std::string& old_set,
                     std::string& error) {
  std::error_code ec;
  if (!fs::exists(target, ec)) {
    if (::rename(staging.c_str(), target.c_str()) != 0) {
      error = "cannot rename '" + staging.string() + "' to '" + target.string() +
              "': " + reason_of(errno);
      return false;
    }
    old_set.clear();
    return true;
  }
  if (exchange(staging, target) == 0) {
    old_set = staging.string();
    return true;
  }
  if (errno != EINVAL && errno != ENOSYS) {
    error = "cannot swap '" + staging.string() + "' into '" + target.string() +
            "': " + reason_of(errno);
    return false;
  }
  // No RENAME_EXCHANGE here: move the old set aside under a staging name (put back by the
  // next open() if we die between the renames), then the new one in.
  const fs::path aside = target.parent_path() / (staging_prefix(target) + "old");
  fs::remove_all(aside, ec);
  if (::rename(target.c_str(), aside.c_str()) != 0 ||
      ::rename(staging.c_str(), target.c_str()) != 0) {
    error = "cannot move '" + staging.string() + "' into '" + target.string() +
            "': " + reason_of(errno);
    return false;
  }
  old_set = aside.string();
  return true;
}

}  // namespace

StagedDirectory::~StagedDirectory() {
  discard();
}

bool StagedDirectory::open(const std::string& target, std::string& error) {
  discard();
  std::error_code ec;
  fs::path resolved = fs::weakly_canonical(fs::absolute(target, ec), ec);
  // weakly_canonical stops at a dangling link (its target does not exist yet): the output
  // goes where the link points, as for a plain mkdir through it, and the link stays.
  std::error_code missing;  // a path that does not exist is no link: the loop ends
  for (int followed = 0; !ec && fs::is_symlink(fs::symlink_status(resolved, missing)); ++followed) {
    if (followed == kMaxLinksFollowed) {
      error = "'" + target + "': " + reason_of(ELOOP);
      return false;
    }
    const fs::path link = fs::read_symlink(resolved, ec);
    resolved = fs::weakly_canonical(resolved.parent_path() / link, ec);
  }
  if (ec || resolved.filename().empty() || resolved == resolved.root_path()) {
    error = "'" + target + "' cannot be an output directory";
    return false;
  }
  if (!owned_or_empty(resolved, error)) return false;
  fs::create_directories(resolved.parent_path(), ec);
  if (ec) {
    error = "cannot create '" + resolved.parent_path().string() + "': " + ec.message();
    return false;
  }
  // A writer killed between the two renames of the fallback swap left the old set aside and
  // no target: put it back before anything else.
  const fs::path aside = resolved.parent_path() / (staging_prefix(resolved) + "old");
  if (!fs::exists(resolved, ec) && fs::exists(aside, ec)) fs::rename(aside, resolved, ec);
  remove_stale_siblings(resolved);
  std::string pattern = (resolved.parent_path() / (staging_prefix(resolved) + "XXXXXX")).string();
  const interrupt::CommitSection section;  // a signal waits until the new directory is registered
  if (::mkdtemp(pattern.data()) == nullptr) {
    error =
        "cannot create a staging directory beside '" + resolved.string() + "': " + reason_of(errno);
    return false;
  }
  // mkdtemp makes the directory private (0700); the output gets the permissions a plain
  // mkdir would have given it.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::chmod(pattern.c_str(), 0777 & ~mask);
  lock_fd_ = ::open(pattern.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (lock_fd_ < 0 || ::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
    error = "cannot lock the staging directory '" + pattern + "': " + reason_of(errno);
    fs::remove_all(pattern, ec);
    if (lock_fd_ >= 0) ::close(lock_fd_);
    lock_fd_ = -1;
    return false;
  }
  target_ = resolved.string();
  staging_ = pattern;
  cleanup_ = interrupt::CleanupPath(staging_, interrupt::CleanupPath::Kind::kDirectory);
  return true;
}

bool StagedDirectory::commit(const std::string& marker_text, std::string& error) {
  if (staging_.empty()) {
    error = "no staging directory is open";
    return false;
  }
  AtomicFile marker;
  if (!marker.open((fs::path(staging_) / kMarkerName).string(), error)) return false;
  marker.append(marker_text);
  if (!marker.commit(error)) return false;
  ::fsync(lock_fd_);
  const fs::path target(target_);
  const fs::path staging(staging_);
  std::string old_set;  // where the replaced set lies after the swap ("" if there was none)
  {
    // A signal waits until the swap is done, and no longer: deleting the old set can take
    // seconds on a busy disk (past mpirun's one second between SIGTERM and SIGKILL), so it
    // runs outside the section, with the clean-up slot naming the old set's place. A signal
    // then deletes it in the handler, whose unlinks do not wait for the disk.
    const interrupt::CommitSection section;
    if (!swap_into_place(staging, target, old_set, error)) return false;
    if (old_set.empty())
      cleanup_.release();
    else if (old_set != staging_)
      cleanup_ = interrupt::CleanupPath(old_set, interrupt::CleanupPath::Kind::kDirectory);
  }
  std::error_code ec;
  if (!old_set.empty()) fs::remove_all(old_set, ec);
  sync_path(target.parent_path());
  staging_.clear();
  cleanup_.release();
  ::close(lock_fd_);
  lock_fd_ = -1;
  return true;
}

void StagedDirectory::discard() {
  if (!staging_.empty()) {
    std::error_code ec;
    fs::remove_all(staging_, ec);
    staging_.clear();
  }
  cleanup_.release();
  if (lock_fd_ >= 0) ::close(lock_fd_);
  lock_fd_ = -1;
}

}  // namespace oasis
