#pragma once
// Lost output is an error. A program that prints its result and exits 0 although the bytes
// never arrived (a full disk, a closed pipe, /dev/full) tells its caller a lie, so every
// command-line tool ends through finish_standard_output().

#include <string_view>

namespace oasis {

// Flushes std::cout and the C stdout beneath it and closes stdout, so that buffered bytes
// and the close itself are checked. Returns `status` when everything was written; otherwise
// prints "PROGRAM: error: cannot write standard output: REASON" on stderr and returns 1
// (or `status` if that is already non-zero). Call it once, as the last thing before exit.
int finish_standard_output(std::string_view program, int status);

}  // namespace oasis
