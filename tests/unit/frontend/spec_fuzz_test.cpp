// A deterministic fuzz test of the front end and exploration.
//
// For every shipped spec (specs/*.oasis), every golden bad spec (tests/specs/bad/*.oasis)
// and two seeds written below, the front end and exploration run in-process on
//   (a) truncations of the file at ~200 offsets spread over it, and
//   (b) ~2000 mutants made by seeded random edits: byte flips, insertions (of bytes and of
//       spec fragments), deletions, digit changes and duplicated spans,
// and each run must end with either a model or at least one reported error: never both, never
// neither, no escaping exception, and an explored model passes find_structural_problem.
// A process-level part writes ~50 mutants to a temporary directory and runs
// `oasisc check` on each: it must exit with status 0 or 1 (no signal, no usage error 2) and
// its stderr must not mention a sanitizer.
//
// Everything is seeded, so a failure names the spec, the seed and the mutant's index, and
// the failing text is written to a file for reproduction.
//
// The test never times itself (a clock bound fails on a busy machine or under sanitizers and
// proves nothing on a fast one). Instead the work is bounded and the bounds are checked: a
// fixed number of inputs per spec, each at most kMaxGrowth bytes longer than its original,
// exploration capped at kMaxStates, and each `oasisc check` limited to kCpuSecondsPerCheck
// of CPU time (RLIMIT_CPU: the process's own work, not the machine's load), past which it
// is killed and the input reported as a blow-up.

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "../../support/scratch_directory.hpp"
#include "frontend/load_spec.hpp"
#include "model/explorer.hpp"
#include "oasis/rt/spec_hash.hpp"

namespace oasis {
namespace {

namespace fs = std::filesystem;

// Mutants per spec, truncation offsets per spec, and files for the process-level part. For a
// longer hunt, set OASIS_FUZZ_MUTANTS (e.g. 100000): the first 2000 mutants stay the same.
constexpr int kMutantsPerSpec = 2000;
constexpr int kTruncationsPerSpec = 200;
constexpr int kProcessFiles = 50;
constexpr std::uint64_t kSeed = 0x0a515eedULL;
// A mutant may turn `[0 .. 4]` into `[0 .. 40000]`: keep exploration small.
constexpr std::uint32_t kMaxStates = 20000;
// mutate() makes at most 3 edits, each adding at most 40 bytes (a duplicated span; every
// fragment is shorter), so no mutant outgrows its original by more than this.
constexpr std::size_t kMaxGrowth = 3 * 40;
// CPU time one `oasisc check` of a mutant may use; a normal one needs well under a second,
// even under ASan, so only a blow-up reaches it.
constexpr rlim_t kCpuSecondsPerCheck = 60;

struct SpecInput {
  std::string name;  // e.g. "bad_type_error": usable as a test name
  std::string text;
};

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string test_name(const std::string& prefix, const fs::path& path) {
  std::string name = prefix + path.stem().string();
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

// Two more seeds, written here, for what the files above hardly use: factored models with
// contexts, state-dependent probabilities and rewards, and explicit catalogs with a full
// switching matrix.
constexpr const char* kFactoredSeed = R"(mdp grid {
  const N = 4;
  var x : [0 .. N-1] init 1;
  var y : [0 .. N-1];
  actions right, up, back, left;
  default self;
  [right] x < N-1 -> 0.9: (x' = x + 1) + 0.1: true;
  [up] y < N-1 -> 1/2 : (y' = y + 1) + y/(2*N) : true + (N - y)/(2*N) : (x' = max(x - 1, 0));
  [left] x > 0 -> (x + 1)/(N + 1) : (x' = x - 1) + (N - x)/(N + 1) : (y' = 0);
  [back] x > 0 & y > 0 -> (x' = x - 1) & (y' = mod(y * 3, N));
  reward x == N-1 & y == N-1 : 1;
  reward [back] true : -1/10;
  horizon 20;
}
catalog {
  context calm = base;
  context windy { [right] x < N-1 -> 1/2: (x' = x + 1) + 1/2: (y' = 0); reward y == 0 : 2; }
  switching stay 0.75;
  prior 1/4: calm + 3/4: windy;
}
)";

constexpr const char* kExplicitSeed = R"(mdp chain {
  states a, b, c;
  actions go, wait;
  init a;
  default disabled;
  a, go -> 1/3: b + 2/3: a;
  b, go -> c;
  c, wait -> 0.5: a + 0.25: b + 0.25: c;
  reward c | b : 1;
  discount 0.95;
}
catalog {
  context one { b, go -> a; }
  context two { reward [wait] c : 3; }
  context three = base;
  switching {
    one -> 0.5: one + 0.5: two;
    two -> 1: three;
    three -> 0.2: one + 0.3: two + 0.5: three;
  }
}
)";

std::vector<SpecInput> spec_inputs() {
  std::vector<SpecInput> inputs{{"seed_factored", kFactoredSeed}, {"seed_explicit", kExplicitSeed}};
  const fs::path root(OASIS_SOURCE_DIR);
  for (const auto& [folder, prefix] : {std::pair{root / "specs", "shipped_"},
                                       std::pair{root / "tests" / "specs" / "bad", "bad_"}}) {
    std::vector<fs::path> paths;
    for (const auto& entry : fs::directory_iterator(folder)) {
      if (entry.path().extension() == ".oasis") paths.push_back(entry.path());
    }
    std::sort(paths.begin(), paths.end());
    for (const fs::path& path : paths)
      inputs.push_back({test_name(prefix, path), read_file(path)});
  }
  return inputs;
}

// ---- mutation -------------------------------------------------------------------------------

// Pieces of spec text that a random insertion or replacement draws from, so that mutants get
// past the lexer and reach the parser, the checker and exploration.
// clang-format off
constexpr std::array kFragments = {
    "mdp", "catalog", "context", "states", "actions", "init", "const", "var", "continuous",
    "default", "reward", "region", "dynamics", "disturbance", "switching", "prior", "discount",
    "horizon", "period", "true", "false", "self", "disabled", "stay", "uniform", "base", "in",
    "gaussian", "x", "y", "s1", "go", "->", "..", "'", "==", "!=", "<=", ">=", "&", "|", "!",
    "(", ")", "[", "]", "{", "}", ";", ":", ",", "+", "-", "*", "/", "=", "0", "1", "1/2",
    "0.5", "1e-3", "1e100000", "-1", "99999999999999999999", "9223372036854775807",
    "-9223372036854775807 - 1", "4611686018427387904", "1099511627775", "min(", "max(",
    "floor(", "ceil(", "abs(", "mod(", "/*", "*/", "//", "\n", " ", "x' = x + 1",
    "[go] true -> ", "(x' = 0)", "default self;", "\xc3\xa9", "\t", "((((((((((",
    "))))))))))",
};
// clang-format on

std::string mutate(const std::string& text, std::mt19937_64& rng) {
  std::string result = text;
  auto uniform = [&](std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(rng() % n); };
  auto random_piece = [&]() -> std::string {
    const std::size_t kind = uniform(10);
    if (kind < 6) return kFragments[uniform(kFragments.size())];
    if (kind < 9) return std::string(1, static_cast<char>(0x20 + uniform(0x5f)));  // printable
    return std::string(1, static_cast<char>(uniform(256)));                        // any byte
  };
  const std::size_t edits = 1 + uniform(3);
  for (std::size_t i = 0; i < edits; ++i) {
    const std::size_t at = uniform(result.size() + 1);
    switch (uniform(5)) {
      case 0:  // flip one byte: a random bit, or a whole new byte
        if (at < result.size()) {
          if (uniform(2) == 0) {
            result[at] = static_cast<char>(result[at] ^ (1U << uniform(8)));
          } else {
            result[at] = random_piece()[0];
          }
        }
        break;
      case 1:  // insert
        result.insert(at, random_piece());
        break;
      case 2:  // delete a short span
        if (at < result.size()) result.erase(at, 1 + uniform(8));
        break;
      case 3: {  // change a digit: a probability, a bound, a constant
        const std::size_t digit = result.find_first_of("0123456789", at);
        if (digit != std::string::npos) result[digit] = static_cast<char>('0' + uniform(10));
        break;
      }
      default:  // duplicate a span elsewhere (repeats items, nests blocks)
        if (!result.empty()) {
          const std::size_t from = uniform(result.size());
          const std::string span = result.substr(from, 1 + uniform(40));
          result.insert(at, span);
        }
        break;
    }
  }
  return result;
}

// ---- one run --------------------------------------------------------------------------------

struct RunResult {
  bool has_model = false;
  std::uint32_t states = 0;  // of the explored model
  std::size_t errors = 0;
  std::string problem;  // empty when the run was sound
};

RunResult run_front_end(const std::string& text) {
  RunResult result;
  try {
    SourceManager sources;
    std::ostringstream out;
    DiagnosticEngine diagnostics(sources, out);
    const FileId file = sources.add("fuzz.oasis", text);
    const auto ir = frontend::check_spec_text(file, diagnostics);
    if (ir && (ir->kind == model::ModelKind::Continuous || ir->imported)) {
      // Continuous models are not explored; an imported program is read by the PRISM front
      // end, which has its own fuzz tests, and not from a fuzzed spec's folder.
      result.has_model = true;
    } else if (ir) {
      model::ExploreOptions options;
      options.max_states = kMaxStates;
      const auto explored = model::explore(*ir, diagnostics, options);
      result.has_model = explored.has_value();
      if (explored) {
        result.states = explored->num_states();
        if (auto problem = model::find_structural_problem(*explored)) {
          result.problem = "explored model is unsound: " + *problem;
        }
      }
    }
    result.errors = diagnostics.error_count();
    if (!result.has_model && result.errors == 0) {
      result.problem = "no model, yet no error was reported";
    } else if (result.has_model && result.errors != 0) {
      result.problem = "a model, although errors were reported:\n" + out.str();
    } else if (result.errors != 0 && out.str().find(": error: ") == std::string::npos) {
      result.problem = "errors were counted but none was printed";
    }
  } catch (const std::exception& e) {
    result.problem = std::string("exception escaped: ") + e.what();
  } catch (...) {
    result.problem = "unknown exception escaped";
  }
  return result;
}

// Records a failing input in a file so that it can be replayed with `oasisc check`.
std::string save_failure(const std::string& label, const std::string& text) {
  const fs::path path = fs::temp_directory_path() / ("oasis_fuzz_failure_" + label + ".oasis");
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

void PrintTo(const SpecInput& input, std::ostream* out) {
  *out << input.name;
}

class SpecFuzz : public ::testing::TestWithParam<SpecInput> {
 protected:
  // Runs one input; returns false (after a test failure) when it broke an invariant.
  bool check(const std::string& text, const std::string& label) {
    RunResult result;
    if (text.size() > GetParam().text.size() + kMaxGrowth) {
      result.problem =
          "the input is " + std::to_string(text.size()) + " bytes, more than the mutator's bound";
    } else {
      result = run_front_end(text);
      if (result.states > kMaxStates) {
        result.problem =
            "exploration went past its state limit (" + std::to_string(result.states) + " states)";
      }
    }
    ++runs_;
    if (result.has_model) ++models_;
    if (!result.problem.empty()) {
      ADD_FAILURE() << GetParam().name << ", " << label << ": " << result.problem
                    << "\ninput saved as " << save_failure(GetParam().name + "_" + label, text);
      return false;
    }
    return true;
  }

  void TearDown() override {
    RecordProperty("runs", runs_);
    RecordProperty("models", models_);
  }

  int runs_ = 0;
  int models_ = 0;
};

TEST_P(SpecFuzz, OriginalIsHandled) {
  const RunResult result = run_front_end(GetParam().text);
  EXPECT_EQ(result.problem, "");
  // Shipped specs and the seeds above are sound; golden bad specs are not.
  EXPECT_EQ(result.has_model, GetParam().name.rfind("bad_", 0) != 0);
}

TEST_P(SpecFuzz, Truncations) {
  const std::string& text = GetParam().text;
  const std::size_t size = text.size();
  const std::size_t count = std::min<std::size_t>(size + 1, kTruncationsPerSpec);
  int failures = 0;
  for (std::size_t i = 0; i < count && failures < 5; ++i) {
    // Offsets spread evenly over [0, size], both ends included.
    const std::size_t offset = count == 1 ? 0 : i * size / (count - 1);
    if (!check(text.substr(0, offset), "truncated_at_" + std::to_string(offset))) ++failures;
  }
  if (failures == 0) {
    EXPECT_EQ(runs_, static_cast<int>(count));
  }
}

TEST_P(SpecFuzz, Mutations) {
  const std::uint64_t seed = kSeed ^ rt::spec_hash(GetParam().name);
  std::mt19937_64 rng(seed);
  int failures = 0;
  const char* override_count = std::getenv("OASIS_FUZZ_MUTANTS");
  const int count = override_count != nullptr ? std::atoi(override_count) : kMutantsPerSpec;
  for (int i = 0; i < count && failures < 5; ++i) {
    const std::string mutant = mutate(GetParam().text, rng);
    if (!check(mutant, "seed_" + std::to_string(seed) + "_mutant_" + std::to_string(i))) {
      ++failures;
    }
  }
  if (failures == 0) {
    EXPECT_EQ(runs_, count);
  }
}

INSTANTIATE_TEST_SUITE_P(Specs, SpecFuzz, ::testing::ValuesIn(spec_inputs()),
                         [](const ::testing::TestParamInfo<SpecInput>& param_info) {
                           return param_info.param.name;
                         });

// ---- process level --------------------------------------------------------------------------

struct ProcessResult {
  bool exited = false;  // false: killed by a signal (SIGXCPU: past kCpuSecondsPerCheck)
  int status = -1;      // exit status, or the signal number
  std::string err;
};

// Runs `oasisc check --max-states N FILE` with stdout discarded, stderr captured and the CPU
// time limited to kCpuSecondsPerCheck.
ProcessResult run_oasisc_check(const fs::path& file, const fs::path& stderr_file) {
  ProcessResult result;
  const std::string max_states = std::to_string(kMaxStates);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    const int err = ::open(stderr_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (null < 0 || err < 0) ::_exit(126);
    const rlimit cpu{kCpuSecondsPerCheck, kCpuSecondsPerCheck + 5};
    if (::setrlimit(RLIMIT_CPU, &cpu) != 0) ::_exit(126);
    ::dup2(null, STDOUT_FILENO);
    ::dup2(err, STDERR_FILENO);
    const std::string path = file.string();
    const char* argv[] = {OASISC_PATH,        "check",      "--max-states",
                          max_states.c_str(), path.c_str(), nullptr};
    ::execv(OASISC_PATH, const_cast<char* const*>(argv));
    const char message[] = "spec_fuzz_test: cannot execute " OASISC_PATH "\n";
    [[maybe_unused]] const auto written = ::write(STDERR_FILENO, message, sizeof message - 1);
    ::_exit(127);
  }
  if (pid < 0) return result;
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  result.exited = WIFEXITED(status);
  result.status = result.exited ? WEXITSTATUS(status) : WTERMSIG(status);
  result.err = read_file(stderr_file);
  return result;
}

TEST(SpecFuzzProcess, OasiscCheckSurvivesMutatedFiles) {
  ASSERT_TRUE(fs::exists(OASISC_PATH)) << OASISC_PATH << " is missing: build oasisc first";
  const std::vector<SpecInput> inputs = spec_inputs();
  ASSERT_FALSE(inputs.empty());
  const test::ScratchDirectory scratch("oasis_spec_fuzz");
  const fs::path& directory = scratch.path();

  std::mt19937_64 rng(kSeed);
  std::vector<std::string> texts;
  // A few fixed hard cases, then seeded mutants of every spec in turn.
  texts.emplace_back("");
  texts.emplace_back(std::string(64, '\0'));
  texts.emplace_back("mdp m { const c = " + std::string(100000, '(') + "1; }");
  std::string chain = "mdp m { const c = 1";
  for (int i = 0; i < 5000; ++i)
    chain += "+1";
  texts.push_back(chain + "; }");
  while (texts.size() < static_cast<std::size_t>(kProcessFiles)) {
    const SpecInput& input = inputs[texts.size() % inputs.size()];
    std::string mutant = mutate(input.text, rng);
    if (texts.size() % 3 == 0) mutant = mutate(mutant, rng);  // some get more edits
    texts.push_back(std::move(mutant));
  }

  int failures = 0;
  int ok = 0;
  for (std::size_t i = 0; i < texts.size() && failures < 5; ++i) {
    const fs::path file = directory / ("mutant_" + std::to_string(i) + ".oasis");
    std::ofstream(file, std::ios::binary) << texts[i];
    const ProcessResult result = run_oasisc_check(file, directory / "stderr.txt");
    const bool sound = result.exited && (result.status == 0 || result.status == 1) &&
                       result.err.find("Sanitizer") == std::string::npos &&
                       result.err.find("runtime error") == std::string::npos;
    if (!sound) {
      ++failures;
      ADD_FAILURE() << "oasisc check " << file.string() << ": "
                    << (result.exited ? "exit status " : "signal ") << result.status
                    << (!result.exited && result.status == SIGXCPU
                            ? " (more than " + std::to_string(kCpuSecondsPerCheck) + " s of CPU)"
                            : std::string())
                    << "\nstderr:\n"
                    << result.err.substr(0, 4000) << "\ninput kept as "
                    << save_failure("process_" + std::to_string(i), texts[i]);
      continue;
    }
    if (result.status == 0) ++ok;
  }
  RecordProperty("files_that_checked_ok", ok);
}

}  // namespace
}  // namespace oasis
