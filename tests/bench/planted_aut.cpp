// oasis-planted: writes a random MDP with a planted bisimulation structure as an mCRL2 .aut
// file, and prints the number of blocks its coarsest bisimulation has.
//
// Construction. A small random "quotient" MDP over K blocks: for each block and action, a
// reward in {0, 1} and a distribution over 3 distinct blocks with dyadic probabilities (or,
// with --targets MIN-MAX, over MIN to MAX blocks, the count drawn per block and action).
// Every concrete state belongs to a block (state mod K); its distribution for an action is
// the block's, with each target block replaced by a random member of that block. So the
// partition by block is a bisimulation of the concrete model. It is the coarsest one when
// the quotient itself is minimal; the quotient may not be (rewards come from {0, 1}), so the
// program minimises the quotient with a naive signature refinement (integer arithmetic:
// probabilities are multiples of 1/8) and prints that block count: the known answer.
//
//   oasis-planted --transitions 10000000 --blocks 1000 --seed 1 -o model.aut
//   oasis-planted --transitions 10000000 --blocks 250000 --targets 2-4 --seed 1 -o many.aut

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace {

constexpr int kActions = 4;
constexpr int kMinTargets = 2;
constexpr int kMaxTargets = 4;
// Four probability patterns (in eighths, summing to 8) per number of targets. The patterns
// for 3 targets are the generator's original ones: the default files have not changed.
constexpr std::array<std::array<std::array<int, kMaxTargets>, 4>, kMaxTargets + 1> kEighths = {{
    {},
    {},
    {{{4, 4}, {6, 2}, {5, 3}, {1, 7}}},
    {{{4, 2, 2}, {2, 2, 4}, {1, 3, 4}, {6, 1, 1}}},
    {{{2, 2, 2, 2}, {4, 2, 1, 1}, {1, 3, 2, 2}, {1, 1, 1, 5}}},
}};

struct Options {
  std::uint64_t transitions = 1'000'000;  // action transitions: states * 4
  std::uint32_t blocks = 1000;
  int min_targets = 3;
  int max_targets = 3;
  std::uint64_t seed = 1;
  std::string output;
};

struct BlockChoice {
  int reward;
  int targets;
  std::array<std::uint32_t, kMaxTargets> target;
  std::array<int, kMaxTargets> eighths;
};

[[noreturn]] void usage(const char* message) {
  std::fprintf(stderr,
               "oasis-planted: %s\nusage: oasis-planted [--transitions N] [--blocks K] "
               "[--targets MIN-MAX] [--seed S] -o FILE.aut\n",
               message);
  std::exit(2);
}

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (i + 1 >= argc) usage(("missing value after " + flag).c_str());
    const char* value = argv[++i];
    if (flag == "--transitions") {
      options.transitions = std::strtoull(value, nullptr, 10);
    } else if (flag == "--blocks") {
      options.blocks = static_cast<std::uint32_t>(std::strtoul(value, nullptr, 10));
    } else if (flag == "--targets") {
      // "3" or "2-4"
      char* rest = nullptr;
      options.min_targets = static_cast<int>(std::strtol(value, &rest, 10));
      options.max_targets =
          *rest == '-' ? static_cast<int>(std::strtol(rest + 1, nullptr, 10)) : options.min_targets;
    } else if (flag == "--seed") {
      options.seed = std::strtoull(value, nullptr, 10);
    } else if (flag == "-o") {
      options.output = value;
    } else {
      usage(("unknown option " + flag).c_str());
    }
  }
  if (options.output.empty()) usage("give an output file with -o");
  if (options.min_targets < kMinTargets || options.max_targets > kMaxTargets ||
      options.min_targets > options.max_targets)
    usage("--targets must be MIN-MAX with 2 <= MIN <= MAX <= 4");
  if (options.blocks < static_cast<std::uint32_t>(options.max_targets))
    usage("--blocks must be at least the largest number of targets");
  if (options.transitions / kActions < options.blocks) usage("fewer states than blocks");
  return options;
}

std::vector<BlockChoice> random_quotient(const Options& options, std::mt19937_64& rng) {
  const std::uint32_t blocks = options.blocks;
  std::vector<BlockChoice> quotient(std::size_t{blocks} * kActions);
  std::uniform_int_distribution<std::uint32_t> any_block(0, blocks - 1);
  const auto spread = static_cast<std::uint64_t>(options.max_targets - options.min_targets + 1);
  for (BlockChoice& choice : quotient) {
    choice.reward = static_cast<int>(rng() % 2);
    // A fixed count draws nothing, so that the default files stay as they were.
    choice.targets = options.min_targets + (spread > 1 ? static_cast<int>(rng() % spread) : 0);
    const auto& patterns = kEighths[static_cast<std::size_t>(choice.targets)];
    choice.eighths = patterns[rng() % patterns.size()];
    for (int k = 0; k < choice.targets; ++k) {
      do {
        choice.target[k] = any_block(rng);
      } while (std::find(choice.target.begin(), choice.target.begin() + k, choice.target[k]) !=
               choice.target.begin() + k);
    }
  }
  return quotient;
}

// Naive signature refinement of the quotient: the number of blocks of its coarsest
// bisimulation. Independent of oasisc's algorithm on purpose.
std::uint32_t minimal_blocks(const std::vector<BlockChoice>& quotient, std::uint32_t blocks) {
  std::vector<std::uint32_t> label(blocks, 0);
  std::uint32_t count = 0;
  for (;;) {
    std::map<std::vector<std::int64_t>, std::uint32_t> signatures;
    std::vector<std::uint32_t> next(blocks);
    for (std::uint32_t z = 0; z < blocks; ++z) {
      std::vector<std::int64_t> signature{label[z]};
      for (int a = 0; a < kActions; ++a) {
        const BlockChoice& choice = quotient[std::size_t{z} * kActions + a];
        std::map<std::uint32_t, int> mass;
        for (int k = 0; k < choice.targets; ++k)
          mass[label[choice.target[k]]] += choice.eighths[k];
        signature.push_back(-1 - choice.reward);
        for (const auto& [target, eighths] : mass) {
          signature.push_back(target);
          signature.push_back(eighths);
        }
      }
      next[z] = signatures.try_emplace(signature, static_cast<std::uint32_t>(signatures.size()))
                    .first->second;
    }
    const auto new_count = static_cast<std::uint32_t>(signatures.size());
    label.swap(next);
    if (new_count == count) return count;
    count = new_count;
  }
}

class Writer {
 public:
  explicit Writer(const std::string& path) : file_(std::fopen(path.c_str(), "wb")) {
    if (file_ == nullptr) usage(("cannot write " + path).c_str());
    buffer_.reserve(1 << 22);
  }
  ~Writer() {
    flush();
    std::fclose(file_);
  }
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  void text(const char* s) { buffer_.append(s); }
  void number(std::uint64_t n) {
    char digits[24];
    int length = 0;
    do {
      digits[length++] = static_cast<char>('0' + n % 10);
      n /= 10;
    } while (n != 0);
    while (length > 0)
      buffer_.push_back(digits[--length]);
    if (buffer_.size() > (1 << 22) - 256) flush();
  }

 private:
  void flush() {
    std::fwrite(buffer_.data(), 1, buffer_.size(), file_);
    buffer_.clear();
  }
  std::FILE* file_;
  std::string buffer_;
};

const char* kLabels[2][kActions] = {
    {"\"a\"", "\"b\"", "\"c\"", "\"d\""},
    {"\"a|reward(1)\"", "\"b|reward(1)\"", "\"c|reward(1)\"", "\"d|reward(1)\""}};
const char* kFractions[9] = {"0", "1/8", "1/4", "3/8", "1/2", "5/8", "3/4", "7/8", "1"};

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  std::mt19937_64 rng(options.seed);
  const std::uint64_t states = options.transitions / kActions;
  const std::uint32_t k = options.blocks;
  const std::vector<BlockChoice> quotient = random_quotient(options, rng);
  const std::uint64_t members_per_block = states / k;  // states s with s mod k == z, below `states`
  auto random_member = [&](std::uint32_t block) {
    const std::uint64_t count = members_per_block + (block < states % k ? 1 : 0);
    return block + k * (rng() % count);
  };
  Writer out(options.output);
  out.text("des (0,");
  out.number(states * kActions);
  out.text(",");
  out.number(states);
  out.text(")\n");
  for (std::uint64_t s = 0; s < states; ++s) {
    const auto block = static_cast<std::uint32_t>(s % k);
    for (int a = 0; a < kActions; ++a) {
      const BlockChoice& choice = quotient[std::size_t{block} * kActions + a];
      out.text("(");
      out.number(s);
      out.text(",");
      out.text(kLabels[choice.reward][a]);
      out.text(",");
      for (int t = 0; t < choice.targets; ++t) {
        out.number(random_member(choice.target[t]));
        if (t + 1 < choice.targets) {
          out.text(" ");
          out.text(kFractions[choice.eighths[t]]);
          out.text(" ");
        }
      }
      out.text(")\n");
    }
  }
  std::printf("%u\n", minimal_blocks(quotient, k));
  return 0;
}
