#include "support/source_manager.hpp"

#include <algorithm>
#include <utility>

namespace oasis {

SourceFile::SourceFile(std::string path, MappedFile contents)
    : path_(std::move(path)), mapped_(std::move(contents)), text_(mapped_.text()) {}

SourceFile::SourceFile(std::string path, std::string contents)
    : path_(std::move(path)), owned_(std::move(contents)), text_(owned_) {}

void SourceFile::index_lines_to(SourceOffset offset) const {
  if (line_starts_.empty()) line_starts_.push_back(0);
  const std::size_t end = std::min<SourceOffset>(offset, text_.size());
  for (std::size_t i = indexed_to_; i < end; ++i) {
    if (text_[i] == '\n') line_starts_.push_back(i + 1);
  }
  indexed_to_ = std::max<SourceOffset>(indexed_to_, end);
}

std::size_t SourceFile::line_index(SourceOffset offset) const {
  // A line starts at `offset` when the byte before it is a newline: index up to it.
  index_lines_to(offset);
  const auto next = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  return static_cast<std::size_t>(next - line_starts_.begin()) - 1;
}

LineColumn SourceFile::line_column(SourceOffset offset) const {
  offset = std::min<SourceOffset>(offset, text_.size());
  const std::size_t line = line_index(offset);
  std::uint32_t column = 1;
  for (SourceOffset i = line_starts_[line]; i < offset; ++i) {
    // Count code points: skip UTF-8 continuation bytes (10xxxxxx).
    if ((static_cast<unsigned char>(text_[i]) & 0xC0U) != 0x80U) ++column;
  }
  return {line + 1, column};
}

std::string_view SourceFile::line_text(SourceOffset offset) const {
  offset = std::min<SourceOffset>(offset, text_.size());
  const std::size_t line = line_index(offset);
  const std::size_t begin = line_starts_[line];
  std::size_t end = text_.find('\n', begin);
  if (end == std::string_view::npos) end = text_.size();
  if (end > begin && text_[end - 1] == '\r') --end;
  return text_.substr(begin, end - begin);
}

FileId SourceManager::add(std::string path, MappedFile contents) {
  contents.shrink_if_testing(path);  // every reader of a mapped file passes here before reading
  files_.emplace_back(std::move(path), std::move(contents));
  return static_cast<FileId>(files_.size() - 1);
}

FileId SourceManager::add(std::string path, std::string contents) {
  files_.emplace_back(std::move(path), std::move(contents));
  return static_cast<FileId>(files_.size() - 1);
}

}  // namespace oasis
