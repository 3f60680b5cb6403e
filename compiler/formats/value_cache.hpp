#pragma once
// Turns the number texts of a model file into RationalPool ids without going through GMP for
// every occurrence. A file with 3*10^7 edges typically has a handful of distinct
// probabilities ("1/2", "0.25"), so a small direct-mapped cache keyed by the parsed
// numerator and denominator answers almost every lookup with two integer compares; only a
// miss builds an mpq and interns it. Texts too long for 64-bit parts (or with an exponent
// or a sign) take a slower path keyed by the text itself.
//
// The cache also remembers, per pool id, the value as a 64-bit fraction when it fits, so
// that ExactSum can add probabilities with integer arithmetic.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "support/diagnostics.hpp"
#include "support/limits.hpp"
#include "support/rational.hpp"

namespace oasis::formats {

// numerator / denominator with both parts below 2^64; denominator 0 means "no such form".
struct SmallFraction {
  std::uint64_t numerator = 0;
  std::uint64_t denominator = 0;
};

class ValueCache {
 public:
  // Values whose numerator or denominator has more than `max_number_bits` bits are refused by
  // check_carried (support/limits.hpp).
  explicit ValueCache(RationalPool& pool,
                      std::size_t max_number_bits = limits::kDefaultMaxNumberBits);

  // numerator / denominator; the denominator must not be 0.
  ValueId intern_fraction(std::uint64_t numerator, std::uint64_t denominator) {
    Slot& slot = slots_[slot_of(numerator, denominator)];
    if (slot.denominator == denominator && slot.numerator == numerator) return slot.id;
    return intern_fraction_slow(numerator, denominator, slot);
  }
  // A decimal (`0.25`, `.5`, `3`, `1e-3`) or fraction (`1/3`, `0.5/2`), optionally signed.
  // nullopt when the text is not a number, or is a fraction with a zero denominator.
  std::optional<ValueId> intern_text(std::string_view text);

  // The 64-bit form of a pool value, or nullptr when it has none (negative or huge).
  [[nodiscard]] const SmallFraction* small(ValueId id) const {
    return id < small_.size() && small_[id].denominator != 0 ? &small_[id] : nullptr;
  }
  [[nodiscard]] RationalPool& pool() { return pool_; }
  [[nodiscard]] const RationalPool& pool() const { return pool_; }
  // Interns a value computed elsewhere, keeping the 64-bit form table up to date.
  ValueId intern(const Rational& value);

  // Reports a value longer than the number-size limit, or one a catalog cannot carry as a
  // double (support/double_range.hpp), at `where`:
  // an error at every occurrence, a warning for a lossy (subnormal) value at its first one
  // only. Each distinct value is judged once, so the cost per occurrence is a lookup.
  // Returns false after an error.
  bool check_carried(ValueId id, std::string_view what, SourceRange where,
                     DiagnosticEngine& diagnostics);

 private:
  struct Slot {
    std::uint64_t numerator = 0;
    std::uint64_t denominator = 0;  // 0: empty
    ValueId id = 0;
  };
  struct TextHash {
    using is_transparent = void;  // NOLINT(readability-identifier-naming): the standard's name
    std::size_t operator()(std::string_view text) const {
      return std::hash<std::string_view>{}(text);
    }
  };
  static constexpr std::size_t kSlots = 4096;

  static std::size_t slot_of(std::uint64_t numerator, std::uint64_t denominator) {
    const std::uint64_t mixed =
        (numerator * 0x9e3779b97f4a7c15ULL) ^ (denominator * 0xc2b2ae3d27d4eb4fULL);
    return static_cast<std::size_t>(mixed >> 52) & (kSlots - 1);
  }
  ValueId intern_fraction_slow(std::uint64_t numerator, std::uint64_t denominator, Slot& slot);
  void remember_small(ValueId id);

  RationalPool& pool_;
  std::array<Slot, kSlots> slots_{};
  std::unordered_map<std::string, ValueId, TextHash, std::equal_to<>> by_text_;
  std::vector<SmallFraction> small_;
  enum class Judged : std::uint8_t { kNotYet, kFaithful, kWarned, kRefused };
  std::vector<Judged> judged_;  // by ValueId
  std::size_t max_number_bits_;
};

}  // namespace oasis::formats
