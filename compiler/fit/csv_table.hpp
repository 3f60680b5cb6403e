#pragma once
// The CSV files the fits read (docs/fitting.md): a header row naming the columns, then one
// record per line. Cells are separated by commas and trimmed of spaces and tabs; a cell may
// be double-quoted ("a, b", with "" for a quote) but may not span lines. Blank lines and
// lines whose first character is '#' are skipped. Every cell keeps its place in the file so
// that a bad value is reported as file:line:col with the line and a caret.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "support/diagnostics.hpp"
#include "support/limits.hpp"

namespace oasis::fit {

struct CsvCell {
  std::string text;  // unquoted and trimmed
  SourceRange where;
};

struct CsvRow {
  std::vector<CsvCell> cells;
  SourceLocation line_end;  // just after the last character of the line, for missing cells
};

struct CsvTable {
  std::string path;
  FileId file = 0;
  std::vector<CsvCell> header;
  std::vector<CsvRow> rows;

  // The index of the column named `name` (case-sensitive), if the header has it.
  [[nodiscard]] std::optional<std::size_t> column(std::string_view name) const;
};

struct CsvReadOptions {
  std::size_t max_bytes = limits::kDefaultMaxInputBytes;
};

// Reads `path` (added to `sources`). Every record must have as many cells as the header.
// nullopt after reporting errors through `diagnostics` (an unreadable file, no header, a
// ragged or unterminated record).
std::optional<CsvTable> read_csv(const std::string& path, SourceManager& sources,
                                 DiagnosticEngine& diagnostics, const CsvReadOptions& options = {});

// The same for text already in memory (tests; `path` names it in messages).
std::optional<CsvTable> read_csv_text(const std::string& path, std::string text,
                                      SourceManager& sources, DiagnosticEngine& diagnostics);

// Reports a missing column at the header line: "the header has no column 'name' (columns:
// ...)". Returns false so callers can write `if (!column) return missing_column(...)`.
bool missing_column(const CsvTable& table, std::string_view name, DiagnosticEngine& diagnostics);

// A finite number in `cell`; nullopt after reporting "expected a number" at the cell.
std::optional<double> parse_number(const CsvCell& cell, std::string_view what,
                                   DiagnosticEngine& diagnostics);

// A non-negative integer in `cell`; nullopt after reporting an error at the cell.
std::optional<std::uint64_t> parse_count(const CsvCell& cell, std::string_view what,
                                         DiagnosticEngine& diagnostics);

}  // namespace oasis::fit
