#include "sim/treat_schedule.hpp"

#include <algorithm>

#include "random/seeded_random.hpp"

namespace oasis::hw::sim {
namespace {

constexpr std::uint64_t kScheduleStream = 1;
constexpr int kMaxDraws = 1000;  // rejection sampling of the gaps; then fewer hand-offs

TreatHolder other_than(TreatHolder holder) {
  return holder == TreatHolder::kHuman1 ? TreatHolder::kHuman2 : TreatHolder::kHuman1;
}

bool gaps_hold(const std::vector<double>& times, double min_gap_s) {
  for (std::size_t k = 1; k < times.size(); ++k)
    if (times[k] - times[k - 1] < min_gap_s) return false;
  return true;
}

// `count` uniform times in the window, sorted, at least min_gap apart: uniform over the allowed
// schedules, by rejection; with a window too tight for it, one hand-off fewer.
std::vector<double> hand_off_times(const TreatSettings& treat, double duration_s, int count,
                                   SeededRandom& random) {
  const double begin = treat.first_after_s;
  const double end = std::max(begin, duration_s - treat.last_before_s);
  for (; count > 0; --count) {
    for (int draw = 0; draw < kMaxDraws; ++draw) {
      std::vector<double> times;
      for (int k = 0; k < count; ++k)
        times.push_back(random.uniform(begin, end));
      std::sort(times.begin(), times.end());
      if (gaps_hold(times, treat.min_gap_s)) return times;
    }
  }
  return {};
}

// A Poisson process of hiding episodes, each of a uniform length.
std::vector<TimeInterval> hiding(const TreatSettings& treat, double duration_s,
                                 SeededRandom& random) {
  std::vector<TimeInterval> hidden;
  if (!(treat.hides_per_minute > 0.0)) return hidden;
  const double mean_gap_s = 60.0 / treat.hides_per_minute;
  for (double t = random.exponential(mean_gap_s); t < duration_s;
       t += random.exponential(mean_gap_s)) {
    const double length = random.uniform(treat.hide_min_s, treat.hide_max_s);
    hidden.push_back({t, t + length});
    t += length;
  }
  return hidden;
}

}  // namespace

int TreatSchedule::hand_offs_decided_by(double time_s) const {
  return static_cast<int>(std::count_if(hand_off_s.begin(), hand_off_s.end(),
                                        [time_s](double at) { return at <= time_s; }));
}

TreatHolder TreatSchedule::holder_at(double time_s) const {
  return hand_offs_decided_by(time_s) % 2 == 0 ? first_holder : other_than(first_holder);
}

bool TreatSchedule::hidden_at(double time_s) const {
  return std::any_of(hidden.begin(), hidden.end(), [time_s](const TimeInterval& interval) {
    return interval.begin_s <= time_s && time_s < interval.end_s;
  });
}

TreatSchedule draw_treat_schedule(const HallwayScenario& scenario, std::uint64_t seed) {
  SeededRandom random = SeededRandom::stream(seed, kScheduleStream);
  TreatSchedule schedule;
  schedule.first_holder = random.chance(0.5) ? TreatHolder::kHuman1 : TreatHolder::kHuman2;
  const int count = random.integer(scenario.treat.hand_offs_min, scenario.treat.hand_offs_max);
  schedule.hand_off_s = hand_off_times(scenario.treat, scenario.trial.duration_s, count, random);
  schedule.hidden = hiding(scenario.treat, scenario.trial.duration_s, random);
  return schedule;
}

}  // namespace oasis::hw::sim
