#include "fit/csv_table.hpp"

#include <charconv>
#include <cmath>
#include <utility>

#include "support/text.hpp"

namespace oasis::fit {
namespace {

bool is_blank(char c) {
  return c == ' ' || c == '\t';
}

class CsvParser {
 public:
  CsvParser(const SourceFile& source, FileId file, DiagnosticEngine& diagnostics)
      : text_(source.text()), file_(file), diagnostics_(diagnostics) {}

  std::optional<CsvTable> parse(const std::string& path) {
    CsvTable table;
    table.path = path;
    table.file = file_;
    bool has_header = false;
    std::size_t pos = 0;
    while (pos < text_.size()) {
      std::size_t end = text_.find('\n', pos);
      if (end == std::string_view::npos) end = text_.size();
      std::size_t content_end = end;
      if (content_end > pos && text_[content_end - 1] == '\r') --content_end;
      const std::size_t line_begin = pos;
      pos = end + 1;
      std::size_t first = line_begin;
      while (first < content_end && is_blank(text_[first]))
        ++first;
      if (first == content_end || text_[first] == '#') continue;
      CsvRow row;
      if (!split(line_begin, content_end, row)) {
        if (diagnostics_.should_stop()) return std::nullopt;
        continue;
      }
      if (!has_header) {
        table.header = std::move(row.cells);
        has_header = true;
        check_header(table.header);
        continue;
      }
      if (row.cells.size() != table.header.size()) {
        ragged(table, row);
        if (diagnostics_.should_stop()) return std::nullopt;
        continue;
      }
      table.rows.push_back(std::move(row));
    }
    if (!has_header) {
      diagnostics_.file_error(path, "no header row: the file has no records");
      return std::nullopt;
    }
    if (diagnostics_.has_errors()) return std::nullopt;
    return table;
  }

 private:
  SourceLocation at(std::size_t offset) const { return {file_, offset}; }

  // Splits text_[begin, end) into cells. false after reporting an unterminated quote.
  bool split(std::size_t begin, std::size_t end, CsvRow& row) {
    row.line_end = at(end);
    std::size_t pos = begin;
    for (;;) {
      std::size_t cell_begin = pos;
      while (cell_begin < end && is_blank(text_[cell_begin]))
        ++cell_begin;
      CsvCell cell;
      std::size_t next = cell_begin;
      if (cell_begin < end && text_[cell_begin] == '"') {
        std::size_t q = cell_begin + 1;
        bool closed = false;
        while (q < end) {
          if (text_[q] == '"') {
            if (q + 1 < end && text_[q + 1] == '"') {
              cell.text += '"';
              q += 2;
              continue;
            }
            closed = true;
            break;
          }
          cell.text += text_[q++];
        }
        if (!closed) {
          diagnostics_.error(SourceRange{at(cell_begin), 1}, "unterminated quoted cell");
          return false;
        }
        next = q + 1;
        cell.where = {at(cell_begin), static_cast<std::uint32_t>(next - cell_begin)};
        while (next < end && is_blank(text_[next]))
          ++next;
        if (next < end && text_[next] != ',') {
          diagnostics_.error(SourceRange{at(next), 1},
                             "expected ',' or the end of the line after a quoted cell");
          return false;
        }
      } else {
        while (next < end && text_[next] != ',')
          ++next;
        std::size_t cell_end = next;
        while (cell_end > cell_begin && is_blank(text_[cell_end - 1]))
          --cell_end;
        cell.text = std::string(text_.substr(cell_begin, cell_end - cell_begin));
        cell.where = {at(cell_begin),
                      static_cast<std::uint32_t>(std::max<std::size_t>(1, cell_end - cell_begin))};
      }
      row.cells.push_back(std::move(cell));
      if (next >= end) return true;
      pos = next + 1;  // past the comma
    }
  }

  void check_header(const std::vector<CsvCell>& header) {
    for (std::size_t i = 0; i < header.size(); ++i) {
      if (header[i].text.empty()) {
        diagnostics_.error(header[i].where, "empty column name in the header");
        continue;
      }
      for (std::size_t j = 0; j < i; ++j)
        if (header[j].text == header[i].text)
          diagnostics_.error(header[i].where,
                             "column " + quoted(header[i].text) + " appears twice in the header");
    }
  }

  void ragged(const CsvTable& table, const CsvRow& row) {
    const std::string message = "expected " + std::to_string(table.header.size()) +
                                " cells as in the header, found " +
                                std::to_string(row.cells.size());
    if (row.cells.size() > table.header.size()) {
      diagnostics_.error(row.cells[table.header.size()].where, message);
    } else {
      diagnostics_.error(SourceRange{row.line_end, 1}, message);
    }
  }

  std::string_view text_;
  FileId file_;
  DiagnosticEngine& diagnostics_;
};

}  // namespace

std::optional<std::size_t> CsvTable::column(std::string_view name) const {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i].text == name) return i;
  return std::nullopt;
}

std::optional<CsvTable> read_csv(const std::string& path, SourceManager& sources,
                                 DiagnosticEngine& diagnostics, const CsvReadOptions& options) {
  MappedFile contents;
  std::string reason;
  // Cells are located by 32-bit offsets, whatever the option says.
  if (!contents.open(path, options.max_bytes, reason)) {
    diagnostics.file_error(path, "cannot read: " + reason);
    return std::nullopt;
  }
  const FileId file = sources.add(path, std::move(contents));
  return CsvParser(sources.file(file), file, diagnostics).parse(path);
}

std::optional<CsvTable> read_csv_text(const std::string& path, std::string text,
                                      SourceManager& sources, DiagnosticEngine& diagnostics) {
  const FileId file = sources.add(path, std::move(text));
  return CsvParser(sources.file(file), file, diagnostics).parse(path);
}

bool missing_column(const CsvTable& table, std::string_view name, DiagnosticEngine& diagnostics) {
  std::string columns;
  for (const CsvCell& cell : table.header)
    columns += (columns.empty() ? "" : ", ") + cell.text;
  const SourceLocation header_start =
      table.header.empty() ? SourceLocation{table.file, 0} : table.header.front().where.begin;
  diagnostics.error(SourceRange{header_start, 1},
                    "the header has no column " + quoted(name) + " (columns: " + columns + ")");
  return false;
}

std::optional<double> parse_number(const CsvCell& cell, std::string_view what,
                                   DiagnosticEngine& diagnostics) {
  const std::string& text = cell.text;
  const char* begin = text.data();
  const char* end = begin + text.size();
  if (begin != end && *begin == '+') ++begin;  // from_chars refuses a leading '+'
  double value = 0.0;
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value)) {
    diagnostics.error(cell.where, "expected a number for " + std::string(what) + ", found " +
                                      (text.empty() ? std::string("an empty cell") : quoted(text)));
    return std::nullopt;
  }
  return value;
}

std::optional<std::uint64_t> parse_count(const CsvCell& cell, std::string_view what,
                                         DiagnosticEngine& diagnostics) {
  const std::string& text = cell.text;
  std::uint64_t value = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || ptr != text.data() + text.size()) {
    diagnostics.error(cell.where, "expected a non-negative integer for " + std::string(what) +
                                      ", found " +
                                      (text.empty() ? std::string("an empty cell") : quoted(text)));
    return std::nullopt;
  }
  return value;
}

}  // namespace oasis::fit
