#pragma once
// Small helpers of the output writers (AtomicFile, AtomicFileSet and its journal,
// StagedDirectory): an errno as the lower-case fragment our messages use, the directory part of a
// path, and making a rename in a directory durable.

#include <cstring>
#include <string>

#include <fcntl.h>
#include <unistd.h>

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

// Makes the renames in `directory` durable. Best effort: some file systems refuse fsync on a
// directory, and the data is already safe.
inline void sync_directory(const std::string& directory) {
  const int fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace oasis
