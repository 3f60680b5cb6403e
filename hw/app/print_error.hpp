#pragma once
// oasis-go1's error line: "WHERE: error: MESSAGE" on stderr, the format every program of oasis
// reports in (the compiler's), WHERE being the program or the file at fault. Every error that
// ends a command is printed through it.
#include <iostream>
#include <string_view>

namespace oasis::hw::app {

inline constexpr std::string_view kProgram = "oasis-go1";

inline void print_error(std::string_view message, std::string_view where = kProgram) {
  std::cerr << where << ": error: " << message << '\n';
}

}  // namespace oasis::hw::app
