#include "command_line/memory_budget.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>

#include <sys/resource.h>
#include <unistd.h>

#include "text/byte_size.hpp"

// GCC defines __SANITIZE_ADDRESS__ / __SANITIZE_THREAD__; clang answers __has_feature.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define OASIS_SHADOW_MEMORY_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
#define OASIS_SHADOW_MEMORY_SANITIZER 1
#endif
#endif

namespace oasis {
namespace {

constexpr std::uint64_t kUnlimited = std::numeric_limits<std::uint64_t>::max();

// The soft data limit apply_memory_budget() lowered, for lift_memory_budget().
std::optional<rlim_t> soft_limit_before;

// A number of bytes in a control-group file ("max" or a number); nullopt when absent or
// unlimited. v1 writes "unlimited" as a huge multiple of the page size.
std::optional<std::uint64_t> read_cgroup_limit(const std::string& path) {
  std::ifstream in(path);
  std::string text;
  if (!(in >> text) || text == "max") return std::nullopt;
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  if (value >= (std::uint64_t{1} << 62)) return std::nullopt;
  return value;
}

// The memory limit of this process's control group and of its ancestors (the tightest wins),
// from /proc/self/cgroup: "0::/path" is cgroup v2, "N:memory:/path" the v1 memory controller.
std::optional<std::uint64_t> cgroup_memory_limit() {
  std::ifstream in("/proc/self/cgroup");
  std::optional<std::uint64_t> tightest;
  std::string line;
  while (std::getline(in, line)) {
    const std::size_t first = line.find(':');
    const std::size_t second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    const std::string controllers = line.substr(first + 1, second - first - 1);
    std::string group = line.substr(second + 1);
    std::string root;
    const char* file = nullptr;
    if (controllers.empty()) {
      root = "/sys/fs/cgroup";
      file = "memory.max";
    } else if (controllers == "memory" || controllers.find("memory,") != std::string::npos ||
               controllers.ends_with(",memory")) {
      root = "/sys/fs/cgroup/memory";
      file = "memory.limit_in_bytes";
    } else {
      continue;
    }
    // Walk from the process's group up to the root of the hierarchy.
    for (;;) {
      const std::string directory = group == "/" ? root : root + group;
      if (const auto limit = read_cgroup_limit(directory + "/" + file))
        tightest = std::min(tightest.value_or(kUnlimited), *limit);
      if (group == "/" || group.empty()) break;
      const std::size_t slash = group.rfind('/');
      group = slash == 0 ? "/" : group.substr(0, slash);
    }
  }
  return tightest;
}

// "512M", "4GiB", "1.5g", "65536": bytes, with binary units.
std::optional<std::uint64_t> parse_size(std::string_view text) {
  double number = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
  if (error != std::errc() || end == text.data() || !std::isfinite(number) || number < 0)
    return std::nullopt;
  std::string unit(end, text.data() + text.size());
  std::transform(unit.begin(), unit.end(), unit.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (unit.ends_with("ib")) unit.erase(unit.size() - 2);
  if (unit.ends_with("b")) unit.erase(unit.size() - 1);
  static constexpr std::array<std::pair<std::string_view, int>, 6> kUnits{
      {{"", 0}, {"k", 10}, {"m", 20}, {"g", 30}, {"t", 40}, {"p", 50}}};
  for (const auto& [name, shift] : kUnits) {
    if (unit != name) continue;
    const double bytes = std::ldexp(number, shift);
    if (bytes >= 0x1p63) return std::nullopt;
    return static_cast<std::uint64_t>(bytes);
  }
  return std::nullopt;
}

}  // namespace

bool memory_budget_enforceable() {
#ifdef OASIS_SHADOW_MEMORY_SANITIZER
  return false;
#else
  return true;
#endif
}

std::optional<std::uint64_t> available_memory_bytes() {
  std::optional<std::uint64_t> available;
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page_size = ::sysconf(_SC_PAGESIZE);
  if (pages > 0 && page_size > 0)
    available = static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page_size);
  if (const auto limit = cgroup_memory_limit())
    available = std::min(available.value_or(kUnlimited), *limit);
  return available;
}

std::optional<std::uint64_t> parse_memory_budget(std::string_view text, std::string& error) {
  if (text == "none") return 0;
  std::optional<std::uint64_t> bytes;
  const bool is_auto = text == "auto";
  if (is_auto || text.ends_with('%')) {
    unsigned percent = kDefaultMemoryBudgetPercent;
    if (!is_auto) {
      const auto [end, code] = std::from_chars(text.data(), text.data() + text.size() - 1, percent);
      if (code != std::errc() || end != text.data() + text.size() - 1 || percent < 1 ||
          percent > 100) {
        error = "a percentage of the memory must be between 1% and 100%, not " + std::string(text);
        return std::nullopt;
      }
    }
    const auto available = available_memory_bytes();
    if (!available) {
      if (is_auto) return 0;  // unknown: no budget rather than a guess
      error = "the machine's memory is unknown here; give the budget in bytes (e.g. 4G)";
      return std::nullopt;
    }
    bytes = *available / 100 * percent;
  } else {
    bytes = parse_size(text);
    if (!bytes) {
      error = "expected a size such as 512M, 4G or 75%, or 'none', not '" + std::string(text) + "'";
      return std::nullopt;
    }
  }
  if (*bytes < kMinMemoryBudgetBytes) {
    error = "a memory budget must be at least " + text::describe_bytes(kMinMemoryBudgetBytes) +
            ", not " + text::describe_bytes(*bytes);
    return std::nullopt;
  }
  return bytes;
}

std::optional<std::uint64_t> apply_memory_budget(std::uint64_t bytes, std::string& error) {
  rlimit limit{};
  if (::getrlimit(RLIMIT_DATA, &limit) != 0) {
    error = std::string("cannot read the data limit: ") + std::strerror(errno);
    return std::nullopt;
  }
  const auto current = limit.rlim_cur == RLIM_INFINITY ? kUnlimited : limit.rlim_cur;
  const auto hard = limit.rlim_max == RLIM_INFINITY ? kUnlimited : limit.rlim_max;
  const std::uint64_t wanted = bytes == 0 ? kUnlimited : std::min(bytes, hard);
  if (wanted >= current) return current == kUnlimited ? 0 : current;  // never raised
  soft_limit_before = limit.rlim_cur;
  limit.rlim_cur = static_cast<rlim_t>(wanted);
  if (::setrlimit(RLIMIT_DATA, &limit) != 0) {
    error = std::string("cannot set the data limit: ") + std::strerror(errno);
    return std::nullopt;
  }
  return wanted;
}

void lift_memory_budget() {
  rlimit limit{};
  if (!soft_limit_before || ::getrlimit(RLIMIT_DATA, &limit) != 0) return;
  limit.rlim_cur = *soft_limit_before;
  ::setrlimit(RLIMIT_DATA, &limit);  // only ever raises the soft limit back: cannot fail
}

std::optional<std::uint64_t> address_space_limit() {
  rlimit limit{};
  if (::getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return std::nullopt;
  return static_cast<std::uint64_t>(limit.rlim_cur);
}

}  // namespace oasis
