#pragma once
// The messages a program prints itself, outside a DiagnosticEngine (support/diagnostics.hpp),
// in the engine's unlocated shape:
//
//   WHERE: error: MESSAGE
//
// WHERE is the file or folder the problem belongs to, else the program's name ("oasisc",
// "oasisc-mpi", "oasis-sim", possibly followed by its command: "oasisc: fit noise"). MESSAGE is
// a lower-case fragment without a final period, printed as given: a caller that quotes input
// makes it printable first (common/text/printable_text.hpp). Written to std::cerr as one string, so
// that a rank whose std::cerr is silenced (oasisc-mpi) stays silent.

#include <string>
#include <string_view>

namespace oasis {

// "WHERE: SEVERITY: MESSAGE\n" (SEVERITY: error, warning or note).
std::string report_line(std::string_view where, std::string_view severity,
                        std::string_view message);

void report_error(std::string_view where, std::string_view message);
void report_warning(std::string_view where, std::string_view message);
void report_note(std::string_view where, std::string_view message);

}  // namespace oasis
