#include "formats/value_cache.hpp"

#include "support/double_range.hpp"

namespace oasis::formats {
namespace {

constexpr std::size_t kMaxSmallDigits = 19;  // 10^19 - 1 < 2^64

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

// `digits[.digits]` with at most 19 digits in all, as (digits without the point, 10^scale).
// Anything else (an exponent, a sign, more digits) is left to the GMP path.
std::optional<SmallFraction> parse_small_decimal(std::string_view text) {
  std::uint64_t value = 0;
  std::uint64_t scale = 1;
  std::size_t digits = 0;
  bool point = false;
  for (char c : text) {
    if (c == '.' && !point) {
      point = true;
      continue;
    }
    if (!is_digit(c) || ++digits > kMaxSmallDigits) return std::nullopt;
    value = value * 10 + static_cast<std::uint64_t>(c - '0');
    if (point) scale *= 10;
  }
  if (digits == 0) return std::nullopt;
  return SmallFraction{value, scale};
}

std::optional<SmallFraction> parse_small(std::string_view text) {
  const std::size_t slash = text.find('/');
  if (slash == std::string_view::npos) return parse_small_decimal(text);
  const auto numerator = parse_small_decimal(text.substr(0, slash));
  const auto denominator = parse_small_decimal(text.substr(slash + 1));
  if (!numerator || !denominator || numerator->denominator != 1 || denominator->denominator != 1) {
    return std::nullopt;  // "0.5/2": rare, exact through GMP
  }
  return SmallFraction{numerator->numerator, denominator->numerator};
}

}  // namespace

ValueCache::ValueCache(RationalPool& pool, std::size_t max_number_bits)
    : pool_(pool), max_number_bits_(max_number_bits) {
  for (ValueId id = 0; id < pool_.size(); ++id)
    remember_small(id);
}

void ValueCache::remember_small(ValueId id) {
  if (small_.size() <= id) small_.resize(std::size_t{id} + 1);
  const Rational& value = pool_[id];
  if (sgn(value) < 0 || !value.get_num().fits_ulong_p() || !value.get_den().fits_ulong_p()) return;
  small_[id] = SmallFraction{value.get_num().get_ui(), value.get_den().get_ui()};
}

ValueId ValueCache::intern(const Rational& value) {
  const std::size_t before = pool_.size();
  const ValueId id = pool_.intern(value);
  if (pool_.size() != before) remember_small(id);
  return id;
}

bool ValueCache::check_carried(ValueId id, std::string_view what, SourceRange where,
                               DiagnosticEngine& diagnostics) {
  if (judged_.size() <= id) judged_.resize(std::size_t{id} + 1, Judged::kNotYet);
  Judged& judged = judged_[id];
  if (judged == Judged::kFaithful || judged == Judged::kWarned) return true;
  if (bit_size(pool_[id]) > max_number_bits_) {
    judged = Judged::kRefused;
    diagnostics.error(where,
                      std::string(what) + " " + too_long_message(pool_[id], max_number_bits_));
    return false;
  }
  const DoubleFit fit = double_fit(pool_[id]);
  const std::string message = carried_value_message(pool_[id], fit, what);
  switch (fit) {
    case DoubleFit::kFaithful:
      judged = Judged::kFaithful;
      return true;
    case DoubleFit::kSubnormal:
      judged = Judged::kWarned;
      diagnostics.warning(where, message);
      return true;
    case DoubleFit::kUnderflow:
    case DoubleFit::kOverflow:
      judged = Judged::kRefused;
      diagnostics.error(where, message);
      return false;
  }
  return false;
}

ValueId ValueCache::intern_fraction_slow(std::uint64_t numerator, std::uint64_t denominator,
                                         Slot& slot) {
  static_assert(sizeof(unsigned long) == sizeof(std::uint64_t), "mpz from 64-bit parts");
  Rational value{mpz_class(static_cast<unsigned long>(numerator)),
                 mpz_class(static_cast<unsigned long>(denominator))};
  value.canonicalize();
  const ValueId id = intern(value);
  slot = Slot{numerator, denominator, id};
  return id;
}

std::optional<ValueId> ValueCache::intern_text(std::string_view text) {
  if (const auto small = parse_small(text)) {
    if (small->denominator == 0) return std::nullopt;
    return intern_fraction(small->numerator, small->denominator);
  }
  if (const auto found = by_text_.find(text); found != by_text_.end()) return found->second;
  const std::optional<Rational> value = parse_rational(text);
  if (!value) return std::nullopt;
  const ValueId id = intern(*value);
  by_text_.emplace(std::string(text), id);
  return id;
}

}  // namespace oasis::formats
