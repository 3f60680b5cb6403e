#pragma once
// A size in bytes as messages print it: "900 bytes", "1.5 GiB", "16.0 MiB" (binary units, one
// decimal). The one rule of every message that names an amount of memory: the memory budget's
// refusals and a model file's header declaring more than it. Header-only, C++17.

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

namespace oasis::text {

inline std::string describe_bytes(std::uint64_t bytes) {
  static constexpr std::array<const char*, 7> kUnits{"bytes", "KiB", "MiB", "GiB",
                                                     "TiB",   "PiB", "EiB"};
  double value = static_cast<double>(bytes);
  std::size_t unit = 0;
  while (value >= 1024 && unit + 1 < kUnits.size()) {
    value /= 1024;
    ++unit;
  }
  char text[40];
  if (unit == 0) {
    std::snprintf(text, sizeof text, "%llu bytes", static_cast<unsigned long long>(bytes));
  } else {
    std::snprintf(text, sizeof text, "%.1f %s", value, kUnits[unit]);
  }
  return text;
}

}  // namespace oasis::text
