// The main of a fuzz target built without libFuzzer: runs LLVMFuzzerTestOneInput once on every
// file named on the command line, or found (recursively) in a named directory, in sorted order.
// It exits non-zero when an argument does not exist or when no input was found, so that an
// empty or misplaced corpus cannot pass as a successful replay.

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz_target.hpp"

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  std::vector<fs::path> inputs;
  for (int i = 1; i < argc; ++i) {
    const fs::path argument(argv[i]);
    std::error_code ec;
    if (fs::is_directory(argument, ec)) {
      for (const auto& entry : fs::recursive_directory_iterator(argument, ec))
        if (entry.is_regular_file()) inputs.push_back(entry.path());
    } else if (fs::is_regular_file(argument, ec)) {
      inputs.push_back(argument);
    } else {
      std::cerr << argv[0] << ": error: no such file or directory: " << argument.string() << '\n';
      return 2;
    }
  }
  std::sort(inputs.begin(), inputs.end());
  if (inputs.empty()) {
    std::cerr << argv[0] << ": error: no inputs (give corpus files or directories)\n";
    return 2;
  }
  for (const fs::path& path : inputs) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (!in.good() && !in.eof()) {
      std::cerr << argv[0] << ": error: cannot read " << path.string() << '\n';
      return 2;
    }
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  std::cout << "replayed " << inputs.size() << " inputs\n";
  return 0;
}
