#include "support/standard_output.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>

#include "support/error_report.hpp"

namespace oasis {

int finish_standard_output(std::string_view program, int status) {
  errno = 0;
  std::cout.flush();
  const bool stream_failed = !std::cout;
  // std::cout writes through stdout's buffer (synchronised with stdio), so the bytes are
  // only known to have arrived once fflush and fclose succeed.
  const bool flush_failed = std::fflush(stdout) != 0 || std::ferror(stdout) != 0;
  int saved = errno;
  const bool close_failed = std::fclose(stdout) != 0;
  if (close_failed && saved == 0) saved = errno;
  if (!stream_failed && !flush_failed && !close_failed) return status;
  std::string message = "cannot write standard output";
  if (saved != 0) message += std::string(": ") + std::strerror(saved);
  report_error(program, message);
  return status != 0 ? status : 1;
}

}  // namespace oasis
