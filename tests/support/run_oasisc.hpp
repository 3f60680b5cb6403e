#pragma once
// Runs the oasisc binary under test (OASISC_PATH, a compile definition of every unit test)
// through the shell and collects its exit status and output, for end-to-end tests.

#include <array>
#include <cstdio>
#include <string>

#include <sys/wait.h>

namespace oasis::test {

struct CommandResult {
  int status = -1;     // the exit status; -1 when the program did not exit normally
  std::string output;  // stdout and stderr together
};

// `arguments` is shell text: quote paths that may hold spaces. A redirection of stdout in it
// (`> /dev/full`) applies to stdout alone: stderr is joined to the pipe before it.
inline CommandResult run_oasisc(const std::string& arguments) {
  const std::string command = std::string(OASISC_PATH) + " 2>&1 " + arguments;
  CommandResult result;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  std::size_t count = 0;
  while ((count = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    result.output.append(buffer.data(), count);
  const int status = ::pclose(pipe);
  result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

}  // namespace oasis::test
