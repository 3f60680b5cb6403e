#pragma once
// What every fuzz target here shares. A target defines LLVMFuzzerTestOneInput (libFuzzer's
// entry point); under OASIS_FUZZ it links with libFuzzer, otherwise with replay_main.cpp,
// which feeds it the files of a corpus so that ctest replays the seeds and every saved crash.
//
// A broken invariant is a crash on purpose (fuzz_require), so that libFuzzer saves the input.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace oasis::fuzz {

// The bytes as text (the readers take text; a NUL byte is just another byte to them).
inline std::string text_of(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

[[noreturn]] inline void broken(const char* invariant, const char* file, int line) {
  std::fprintf(stderr, "%s:%d: fuzz invariant broken: %s\n", file, line, invariant);
  std::abort();
}

}  // namespace oasis::fuzz

#define FUZZ_REQUIRE(condition) \
  ((condition) ? static_cast<void>(0) : ::oasis::fuzz::broken(#condition, __FILE__, __LINE__))
