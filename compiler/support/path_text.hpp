#pragma once
// Two small helpers of the output writers (AtomicFile, AtomicFileSet, StagedDirectory): an
// errno as the lower-case fragment our messages use, and the directory part of a path.

#include <cstring>
#include <string>

namespace oasis {

// strerror() capitalises; our messages are lower-case fragments ("no such file or directory").
inline std::string reason_of(int code) {
  std::string text = std::strerror(code);
  if (!text.empty() && text[0] >= 'A' && text[0] <= 'Z') {
    text[0] = static_cast<char>(text[0] - 'A' + 'a');
  }
  return text;
}

// "a/b/c" -> "a/b", "c" -> ".", "/c" -> "/".
inline std::string directory_of(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

}  // namespace oasis
