#include "sim/hallway_people.hpp"

#include <algorithm>
#include <cmath>

namespace oasis::hw::sim {
namespace {

constexpr std::uint64_t kPeopleStream = 2;
constexpr double kReachedM = 0.15;       // a target this close is reached
constexpr double kBehindRobotM = 1.5;    // where someone leaving behind the robot goes
constexpr double kBeyondRangeM = 2.0;    // someone leaving ahead goes this far past max range
constexpr double kZigzagSide = 0.7;      // of the half width: zig-zags stay off the walls
constexpr double kWalkLookAheadM = 1.0;  // the holder walks toward a point this far ahead
constexpr double kLeaveAtMostS = 15.0;   // time to get out of view; then away_min_s..away_max_s
constexpr double kGiverWaitsS = 5.0;     // a receiver not there by then: the giver goes to them

double distance(const go1::PlanarPoint& a, const go1::PlanarPoint& b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

std::size_t index_of(TreatHolder holder) {
  return holder == TreatHolder::kHuman2 ? 1 : 0;
}

}  // namespace

HallwayPeople::HallwayPeople(const HallwayScenario& scenario, std::uint64_t seed,
                             TreatHolder first_holder)
    : scenario_(scenario),
      random_(SeededRandom::stream(seed, kPeopleStream)),
      holder_(index_of(first_holder)) {
  const double half = half_width();
  positions_[holder_] = {random_.uniform(scenario.holder.start_min_m, scenario.holder.start_max_m),
                         random_.uniform(-half, half)};
  positions_[1 - holder_] = {random_.uniform(1.0, scenario.camera.max_range_m - 1.0),
                             random_.uniform(-half, half)};
  start_standing(0.0);
  pick_behaviour(0.0, go1::Pose{});
}

double HallwayPeople::half_width() const {
  return scenario_.hallway.width_m / 2.0 - scenario_.hallway.wall_margin_m;
}

void HallwayPeople::start_standing(double time_s) {
  holder_mind_ = HolderMind{};
  holder_mind_.until_s = time_s + random_.exponential(scenario_.holder.mean_stand_s);
}

TreatHolder HallwayPeople::holder() const {
  return holder_of_person(holder_);
}

void HallwayPeople::step(double time_s, double dt_s, const go1::Pose& robot,
                         int decided_hand_offs) {
  step_back_from(robot);
  if (hand_offs_done_ < decided_hand_offs) {
    if (scenario_.treat.hand_off == HandOffStyle::kInstant) {
      pass_the_treat(time_s, robot);
    } else {
      step_hand_off(time_s, dt_s, robot);
      return;
    }
  }
  step_holder(time_s, dt_s, robot, holder_);
  const std::size_t other = 1 - holder_;
  if (time_s >= other_mind_.until_s) pick_behaviour(time_s, robot);
  const go1::PlanarPoint target =
      other_target(time_s, robot, positions_[holder_], positions_[other]);
  walk_toward(other, target, other_mind_.speed_m_s * dt_s, robot);
}

// Nobody lets the robot walk into them: whoever it came nearer than robot_margin_m to steps back
// to that distance, away from it (kept between the walls).
void HallwayPeople::step_back_from(const go1::Pose& robot) {
  const double margin = scenario_.hallway.robot_margin_m;
  const double half = half_width();
  for (go1::PlanarPoint& self : positions_) {
    const double dx = self.x - robot.x, dy = self.y - robot.y;
    const double gap = std::hypot(dx, dy);
    if (gap >= margin) continue;
    const double ux = gap > 1e-9 ? dx / gap : std::cos(robot.yaw);
    const double uy = gap > 1e-9 ? dy / gap : std::sin(robot.yaw);
    self = {robot.x + ux * margin, std::clamp(robot.y + uy * margin, -half, half)};
  }
}

// The roles swap: the new holder stands a while, the giver picks something to do.
void HallwayPeople::pass_the_treat(double time_s, const go1::Pose& robot) {
  holder_ = 1 - holder_;
  ++hand_offs_done_;
  hand_off_began_s_ = -1.0;
  start_standing(time_s);
  pick_behaviour(time_s, robot);
}

// kMeet, one period of a hand-off under way: the receiver walks up at the other's top speed,
// the giver waits (then walks over too), and the treat passes once they are close enough.
void HallwayPeople::step_hand_off(double time_s, double dt_s, const go1::Pose& robot) {
  if (hand_off_began_s_ < 0.0) hand_off_began_s_ = time_s;
  const std::size_t giver = holder_, receiver = 1 - holder_;
  walk_toward(receiver, positions_[giver], scenario_.other.speed_max_m_s * dt_s, robot);
  if (time_s - hand_off_began_s_ >= kGiverWaitsS)
    walk_toward(giver, positions_[receiver], scenario_.holder.walk_speed_max_m_s * dt_s, robot);
  if (distance(positions_[giver], positions_[receiver]) <= scenario_.treat.pass_within_m)
    pass_the_treat(time_s, robot);
}

// Stands, walks on, stands...; walking, waits while farther than wait_beyond_m from the robot.
void HallwayPeople::step_holder(double time_s, double dt_s, const go1::Pose& robot,
                                std::size_t holder) {
  HolderMind& mind = holder_mind_;
  if (time_s >= mind.until_s) {
    mind.walking = !mind.walking;
    const HolderSettings& settings = scenario_.holder;
    mind.until_s =
        time_s + random_.exponential(mind.walking ? settings.mean_walk_s : settings.mean_stand_s);
    mind.speed_m_s = random_.uniform(settings.walk_speed_min_m_s, settings.walk_speed_max_m_s);
    mind.target_y = random_.uniform(-half_width(), half_width());
  }
  const go1::PlanarPoint& self = positions_[holder];
  const double away = distance(self, {robot.x, robot.y});
  if (should_return(time_s, robot, self)) {
    const go1::PlanarPoint spot = in_front_of(robot);
    walk_toward(holder, spot, scenario_.holder.return_speed_m_s * dt_s, robot);
    if (distance(self, spot) < kReachedM) mind.returning = false;
    return;
  }
  if (!mind.walking || away > scenario_.holder.wait_beyond_m) return;
  walk_toward(holder, {self.x + kWalkLookAheadM, mind.target_y}, mind.speed_m_s * dt_s, robot);
}

// start_min_m ahead along the robot's heading, or nearer if a wall comes first: where a person
// calling a dog stands.
go1::PlanarPoint HallwayPeople::in_front_of(const go1::Pose& robot) const {
  const double c = std::cos(robot.yaw), s = std::sin(robot.yaw);
  double ahead = scenario_.holder.start_min_m;
  const double half = half_width();
  if (std::fabs(s) > 1e-9) {  // the distance along the heading to the nearer wall line
    const double to_wall = ((s > 0 ? half : -half) - robot.y) / s;
    ahead = std::min(ahead, std::max(to_wall, scenario_.hallway.robot_margin_m + 0.1));
  }
  return {robot.x + ahead * c, robot.y + ahead * s};
}

// Far away, or unattended too long: come back until in front of the robot again.
bool HallwayPeople::should_return(double time_s, const go1::Pose& robot,
                                  const go1::PlanarPoint& self) {
  HolderMind& mind = holder_mind_;
  const HolderSettings& settings = scenario_.holder;
  const go1::PlanarPoint seen = go1::to_body_frame(robot, self);
  const double away = std::hypot(seen.x, seen.y);
  const bool unattended = away > settings.wait_beyond_m ||
                          std::fabs(std::atan2(seen.y, seen.x)) > settings.facing_half_angle_rad;
  if (!unattended)
    mind.unattended_since_s = -1.0;
  else if (mind.unattended_since_s < 0.0)
    mind.unattended_since_s = time_s;
  if (away > settings.return_beyond_m ||
      (unattended && time_s - mind.unattended_since_s >= settings.max_wait_s))
    mind.returning = true;
  return mind.returning;
}

void HallwayPeople::pick_behaviour(double time_s, const go1::Pose& robot) {
  const OtherSettings& s = scenario_.other;
  const double weights[] = {s.wander_weight, s.cross_weight, s.zigzag_weight, s.leave_weight};
  double pick = random_.uniform(0.0, weights[0] + weights[1] + weights[2] + weights[3]);
  int chosen = 0;
  while (chosen < 3 && pick >= weights[chosen])
    pick -= weights[chosen++];

  OtherMind mind;
  mind.behaviour = static_cast<Behaviour>(chosen);
  mind.until_s = time_s + random_.exponential(s.mean_behaviour_s);
  if (mind.behaviour == Behaviour::kLeave) mind.until_s = time_s + kLeaveAtMostS;
  mind.speed_m_s = random_.uniform(s.speed_min_m_s, s.speed_max_m_s);
  const go1::PlanarPoint& self = positions_[1 - holder_];
  mind.side = self.y >= robot.y ? -1.0 : 1.0;  // crossings go to the far side
  mind.ahead_m = mind.behaviour == Behaviour::kCross ? random_.uniform(s.cross_min_m, s.cross_max_m)
                                                     : random_.uniform(0.6, 1.5);
  mind.next_turn_s = time_s + s.zigzag_period_s;
  mind.leave_ahead = random_.chance(0.5);
  mind.target = {robot.x + random_.uniform(1.0, scenario_.camera.max_range_m - 1.0),
                 random_.uniform(-half_width(), half_width())};
  other_mind_ = mind;
}

go1::PlanarPoint HallwayPeople::other_target(double time_s, const go1::Pose& robot,
                                             const go1::PlanarPoint& holder,
                                             const go1::PlanarPoint& self) {
  OtherMind& mind = other_mind_;
  const double half = half_width();
  switch (mind.behaviour) {
    case Behaviour::kWander:
      if (distance(self, mind.target) < kReachedM)  // reached: wander on
        mind.target = {robot.x + random_.uniform(1.0, scenario_.camera.max_range_m - 1.0),
                       random_.uniform(-half, half)};
      return mind.target;
    case Behaviour::kCross:
      if (std::fabs(self.y - mind.side * half) < kReachedM) mind.until_s = time_s;  // crossed
      return {robot.x + mind.ahead_m, mind.side * half};
    case Behaviour::kZigzag:
      if (time_s >= mind.next_turn_s) {
        mind.side = -mind.side;
        mind.next_turn_s = time_s + scenario_.other.zigzag_period_s;
      }
      return {holder.x + mind.ahead_m, mind.side * kZigzagSide * half};
    case Behaviour::kLeave: {
      const go1::PlanarPoint out =
          mind.leave_ahead
              ? go1::PlanarPoint{robot.x + scenario_.camera.max_range_m + kBeyondRangeM, self.y}
              : go1::PlanarPoint{robot.x - kBehindRobotM, mind.side * half};
      if (!mind.away && distance(self, out) < kReachedM) {  // out of view: stay a while
        mind.away = true;
        mind.until_s =
            time_s + random_.uniform(scenario_.other.away_min_s, scenario_.other.away_max_s);
      }
      return out;
    }
  }
  return self;
}

// At most `distance_m` straight toward `target`, kept between the walls. A step that would
// bring the person nearer the robot than robot_margin_m goes around the robot instead.
void HallwayPeople::walk_toward(std::size_t person, const go1::PlanarPoint& target,
                                double distance_m, const go1::Pose& robot) {
  go1::PlanarPoint& self = positions_[person];
  const double gap = distance(self, target);
  if (gap < 1e-9) return;
  const double step = std::min(distance_m, gap);
  double dx = (target.x - self.x) / gap, dy = (target.y - self.y) / gap;
  const go1::PlanarPoint at_robot{robot.x, robot.y};
  const double margin = scenario_.hallway.robot_margin_m;
  auto blocked = [&](double ux, double uy) {
    const go1::PlanarPoint next{self.x + ux * step, self.y + uy * step};
    return distance(next, at_robot) < margin && distance(next, at_robot) < distance(self, at_robot);
  };
  if (blocked(dx, dy)) {  // sidestep on the side of the target
    const double cross = (robot.x - self.x) * dy - (robot.y - self.y) * dx;
    const double side = cross >= 0.0 ? 1.0 : -1.0;
    const double tx = -dy * side, ty = dx * side;
    if (blocked(tx, ty)) return;
    dx = tx, dy = ty;
  }
  const double half = half_width();
  self = {self.x + dx * step, std::clamp(self.y + dy * step, -half, half)};
}

}  // namespace oasis::hw::sim
