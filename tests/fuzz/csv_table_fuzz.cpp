// The CSV reader of the fits: a table or at least one error, never both; every record of a
// table has as many cells as the header; and every cell's number and count parsers either
// give a value or report an error.

#include <sstream>

#include "fit/csv_table.hpp"
#include "fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace oasis;
  SourceManager sources;
  std::ostringstream messages;
  DiagnosticEngine diagnostics(sources, messages, 1000000);
  const auto table =
      fit::read_csv_text("fuzz.csv", fuzz::text_of(data, size), sources, diagnostics);
  FUZZ_REQUIRE(table.has_value() != (diagnostics.error_count() != 0));
  if (!table) return 0;
  for (const fit::CsvRow& row : table->rows) {
    FUZZ_REQUIRE(row.cells.size() == table->header.size());
    for (const fit::CsvCell& cell : row.cells) {
      const std::size_t before = diagnostics.error_count();
      const bool number = fit::parse_number(cell, "value", diagnostics).has_value();
      FUZZ_REQUIRE(number != (diagnostics.error_count() > before));
      const std::size_t middle = diagnostics.error_count();
      const bool count = fit::parse_count(cell, "count", diagnostics).has_value();
      FUZZ_REQUIRE(count != (diagnostics.error_count() > middle));
    }
  }
  return 0;
}
