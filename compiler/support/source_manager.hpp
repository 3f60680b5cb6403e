#pragma once
// The text of every input file, and the mapping from byte offsets to line and column that
// diagnostics need. Files are kept for the whole run so locations stay valid.

#include <cstdint>
#include <deque>
#include <string>
#include <string_view>
#include <vector>

#include "support/mapped_file.hpp"

namespace oasis {

using FileId = std::uint32_t;
// A byte offset into an input file: 64-bit, since machine-written models pass 4 GiB (a
// 10^8-transition .aut file is 5.3 GB).
using SourceOffset = std::uint64_t;

// A point in an input file. Offsets are bytes; `file` indexes the SourceManager.
struct SourceLocation {
  FileId file = 0;
  SourceOffset offset = 0;
};

// 1-based line and column. Columns count Unicode code points, so a caret lines up under
// non-ASCII text the way an editor shows it.
struct LineColumn {
  std::uint64_t line = 1;
  std::uint32_t column = 1;
};

class SourceFile {
 public:
  SourceFile(std::string path, MappedFile contents);
  SourceFile(std::string path, std::string contents);

  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] std::string_view text() const { return text_; }
  // The text before `offset` is read: its mapped pages may leave resident memory
  // (MappedFile::release_pages_before). Diagnostics may still read it.
  void release_pages_before(std::size_t offset) const { mapped_.release_pages_before(offset); }

  [[nodiscard]] LineColumn line_column(SourceOffset offset) const;
  // The line that holds `offset`, without its line terminator.
  [[nodiscard]] std::string_view line_text(SourceOffset offset) const;

 private:
  // Finds the line starts up to `offset`, no further.
  void index_lines_to(SourceOffset offset) const;
  [[nodiscard]] std::size_t line_index(SourceOffset offset) const;

  std::string path_;
  MappedFile mapped_;
  std::string owned_;
  std::string_view text_;
  // Computed on the first diagnostic only, and only as far as the diagnostics reach: a clean
  // run over a large mapped file never pays, and an error in the header of a 5 GB file reads
  // one page of it, not all of it (nor an index of its 10^8 lines).
  mutable std::vector<SourceOffset> line_starts_;
  mutable SourceOffset indexed_to_ = 0;  // the bytes before this are in line_starts_
};

class SourceManager {
 public:
  FileId add(std::string path, MappedFile contents);
  FileId add(std::string path, std::string contents);

  [[nodiscard]] const SourceFile& file(FileId id) const { return files_.at(id); }
  // The id the next file added will get.
  [[nodiscard]] FileId num_files() const { return static_cast<FileId>(files_.size()); }

 private:
  std::deque<SourceFile> files_;  // deque: references stay valid as files are added
};

}  // namespace oasis
