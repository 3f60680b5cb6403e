#pragma once
// Several output files that change as one unit: after commit() every file is new, or, if any
// could not be put in place, every file is as it was before (PRISM's .tra/.lab/.srew/...,
// one .aut per context). AtomicFile gives each file that guarantee alone; writing them one by
// one could leave a .tra from this run beside an .srew from the last.
//
// commit() first completes every file beside its destination (written, synced, named), so
// nothing that can fail for lack of space or a bad folder happens once the first file is in
// place. It then keeps each existing destination as a hidden hard link, renames the new files
// in, and, if a rename fails (a destination that became a directory, say), renames the old
// ones back. SIGINT and SIGTERM wait until the set is in place (interrupt::CommitSection). A
// SIGKILL or a power cut during the renames leaves a journal (file_set_journal.hpp) from which
// the next writer in that folder finishes the set: a mix lasts only until then.

#include <memory>
#include <string>
#include <vector>

#include "support/atomic_file.hpp"
#include "support/file_set_journal.hpp"

namespace oasis {

class AtomicFileSet {
 public:
  // Opens one more file of the set (AtomicFile::open); nullptr and `error` on failure.
  [[nodiscard]] AtomicFile* add(const std::string& path, std::string& error);
  // A file the committed set must not include, such as a stale .sta when the model has no
  // variables: deleted at commit, and kept if the commit fails.
  void remove_at_commit(const std::string& path);

  // Puts the whole set in place, or leaves every destination as it was and sets `error`.
  [[nodiscard]] bool commit(std::string& error);
  // Removes every temporary file; the destinations are left as they were.
  void discard();

 private:
  struct Replaced;
  bool keep_old(const std::string& destination, Replaced& replaced, std::string& error);
  bool write_journal(const std::vector<Replaced>& replaced, FileSetJournal& journal,
                     std::string& error) const;
  static void restore(const std::vector<Replaced>& replaced);

  std::vector<std::unique_ptr<AtomicFile>> files_;
  std::vector<std::string> removals_;
};

}  // namespace oasis
