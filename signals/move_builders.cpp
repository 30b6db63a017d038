#include "signals/move_builders.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace hilrig::signals {

namespace {

// One constant-acceleration piece of a move, before it is placed in the profile.
struct Step {
  double acceleration;
  Nanos duration;
};

Nanos round_duration(double seconds) {
  const Nanos d = Nanos::from_seconds(seconds);
  return d < Nanos{1} ? Nanos{1} : d;
}

void require_positive(double value, const char* what) {
  if (!(value > 0.0) || !std::isfinite(value)) throw std::invalid_argument(what);
}

// Distance covered from rest by the steps.
double distance_from_rest(const std::vector<Step>& steps) {
  double v = 0.0;
  double d = 0.0;
  for (const Step& s : steps) {
    const double dt = s.duration.seconds();
    d += (v + 0.5 * s.acceleration * dt) * dt;
    v += s.acceleration * dt;
  }
  return d;
}

// The acceleration that brings `velocity` to rest over `duration` without passing through
// zero: -velocity / duration, made smaller by an ulp at a time until velocity + a·duration (as
// Segment::end_velocity() evaluates it) keeps velocity's sign or is 0. Each step's velocity
// is the previous one's end, rounded once per step; a last step taken from the plan's
// acceleration would end on a residue of either sign (1.5e-13 counts/s after the 35 steps
// of an S-curve) and so turn round, a few ulps past the target, just before its end.
double stopping_acceleration(double velocity, Nanos duration) {
  const double dt = duration.seconds();
  double a = -velocity / dt;
  while (velocity * (velocity + a * dt) < 0.0) a = std::nextafter(a, 0.0);
  return a;
}

// Rescales the accelerations so the steps cover exactly `distance` (from rest, every
// velocity and distance is linear in the accelerations), appends them and settles the move
// on its target. The last step (it ends at rest in the plan) is the one that stops the
// velocity the chain reached, so the move never reverses. Returns the scale applied.
double append_exact(MotionProfile& profile, std::vector<Step>& steps, double distance) {
  const double from = profile.end_position();
  const double covered = distance_from_rest(steps);
  const double scale = distance / covered;
  std::size_t last = steps.size();
  for (std::size_t i = 0; i < steps.size(); ++i)
    if (steps[i].duration > Nanos::zero()) last = i;
  for (std::size_t i = 0; i < last; ++i) {
    if (steps[i].duration <= Nanos::zero()) continue;
    profile.accelerate(steps[i].acceleration * scale, steps[i].duration);
  }
  profile.accelerate(stopping_acceleration(profile.end_velocity(), steps[last].duration),
                     steps[last].duration);
  profile.settle(from, distance);
  return scale;
}

void require_rest(const MotionProfile& profile, const char* who) {
  if (!profile.at_rest()) throw std::logic_error(std::string(who) + ": the profile must be at rest");
}

} // namespace

namespace {

// A trapezoid's peak speed and cruise seconds over distance d (> 0), before rounding.
struct TrapezoidShape {
  double peak = 0.0;
  double cruise = 0.0;
  bool triangle = false;
};
TrapezoidShape trapezoid_shape(double d, const MoveLimits& limits) {
  const double a = limits.acceleration;
  const double b = limits.deceleration;
  const double v = limits.max_speed;
  // Distance to reach v and to stop from it: v²/2a + v²/2b.
  const double ramps = v * v / (2.0 * a) + v * v / (2.0 * b);
  if (ramps < d) return {v, (d - ramps) / v, false};
  // v²/2a + v²/2b = d. 1/(1/a + 1/b), not a·b/(a + b): a·b underflows to 0 for rates near 0.
  return {std::sqrt(2.0 * d / (1.0 / a + 1.0 / b)), 0.0, true};
}

// An S-curve's times over distance d (> 0), before the ramps are cut into steps.
struct SCurveShape {
  double acceleration = 0.0; // peak, as reached
  double jerk_time = 0.0;    // each of the four ramps
  double accel_time = 0.0;   // constant acceleration between ramps
  double cruise_time = 0.0;
};
SCurveShape s_curve_shape(double d, const SCurveLimits& limits) {
  const double j = limits.jerk;
  double v = limits.max_speed;
  double a = limits.acceleration;
  if (v * j < a * a) a = std::sqrt(v * j); // max_speed is reached before full acceleration
  double tj = a / j;
  double ta = v / a - tj;
  // Both acceleration phases together cover v·(v/a + tj).
  double tv = (d - v * (v / a + tj)) / v;
  if (tv < 0.0) {
    tv = 0.0;
    v = a * (-tj + std::sqrt(tj * tj + 4.0 * d / a)) / 2.0; // v²/a + v·tj = d
    ta = v / a - tj;
    if (ta < 0.0) { // too short to reach full acceleration: 2·j·tj³ = d
      ta = 0.0;
      tj = std::cbrt(d / (2.0 * j));
      a = j * tj;
    }
  }
  return {a, tj, ta, tv};
}

} // namespace

double trapezoid_seconds(double distance, const MoveLimits& limits) {
  const double d = std::abs(distance);
  if (d == 0.0) return 0.0;
  const TrapezoidShape shape = trapezoid_shape(d, limits);
  return shape.peak / limits.acceleration + shape.cruise + shape.peak / limits.deceleration;
}

double s_curve_seconds(double distance, const SCurveLimits& limits) {
  const double d = std::abs(distance);
  if (d == 0.0) return 0.0;
  const SCurveShape shape = s_curve_shape(d, limits);
  return 4.0 * shape.jerk_time + 2.0 * shape.accel_time + shape.cruise_time;
}

TrapezoidPlan plan_trapezoid(double distance, const MoveLimits& limits) {
  require_positive(limits.max_speed, "plan_trapezoid: max_speed must be > 0");
  require_positive(limits.acceleration, "plan_trapezoid: acceleration must be > 0");
  require_positive(limits.deceleration, "plan_trapezoid: deceleration must be > 0");
  TrapezoidPlan plan;
  const double d = std::abs(distance);
  if (d == 0.0) return plan;
  const TrapezoidShape shape = trapezoid_shape(d, limits);
  plan.triangle = shape.triangle;
  plan.accel_time = round_duration(shape.peak / limits.acceleration);
  plan.decel_time = round_duration(shape.peak / limits.deceleration);
  plan.cruise_time = plan.triangle ? Nanos::zero() : Nanos::from_seconds(shape.cruise);
  // Peak velocity that covers d exactly with the rounded times: d = v·(ta/2 + tc + td/2).
  const double peak =
      d / (0.5 * plan.accel_time.seconds() + plan.cruise_time.seconds() + 0.5 * plan.decel_time.seconds());
  plan.peak_velocity = distance < 0 ? -peak : peak;
  plan.acceleration = peak / plan.accel_time.seconds();
  plan.deceleration = peak / plan.decel_time.seconds();
  return plan;
}

MotionProfile& constant_speed(MotionProfile& profile, double velocity, Nanos duration) {
  return profile.append(Segment{profile.end_time(), duration, profile.end_position(), velocity, 0.0});
}

TrapezoidPlan trapezoid_move(MotionProfile& profile, double distance, const MoveLimits& limits) {
  require_rest(profile, "trapezoid_move");
  TrapezoidPlan plan = plan_trapezoid(distance, limits);
  if (distance == 0.0) return plan;
  const double sign = distance < 0 ? -1.0 : 1.0;
  std::vector<Step> steps{{sign * plan.acceleration, plan.accel_time},
                          {0.0, plan.cruise_time},
                          {-sign * plan.deceleration, plan.decel_time}};
  const double scale = append_exact(profile, steps, distance);
  plan.peak_velocity *= scale;
  plan.acceleration *= scale;
  plan.deceleration *= scale;
  return plan;
}

MotionProfile& ramp_to(MotionProfile& profile, double velocity, double acceleration) {
  require_positive(acceleration, "ramp_to: acceleration must be > 0");
  const double dv = velocity - profile.end_velocity();
  if (dv == 0.0) return profile;
  const Nanos dt = round_duration(std::abs(dv) / acceleration);
  return profile.accelerate(dv / dt.seconds(), dt);
}

MotionProfile& reversal(MotionProfile& profile, double acceleration) {
  return ramp_to(profile, -profile.end_velocity(), acceleration);
}

SCurvePlan s_curve_move(MotionProfile& profile, double distance, const SCurveLimits& limits) {
  require_positive(limits.max_speed, "s_curve_move: max_speed must be > 0");
  require_positive(limits.acceleration, "s_curve_move: acceleration must be > 0");
  require_positive(limits.jerk, "s_curve_move: jerk must be > 0");
  if (limits.steps_per_ramp < 1) throw std::invalid_argument("s_curve_move: steps_per_ramp must be >= 1");
  require_rest(profile, "s_curve_move");
  SCurvePlan plan;
  const double d = std::abs(distance);
  if (d == 0.0) return plan;
  const SCurveShape shape = s_curve_shape(d, limits);
  const double a = shape.acceleration;
  const double tj = shape.jerk_time;
  const double ta = shape.accel_time;
  const double tv = shape.cruise_time;
  const auto n = static_cast<std::int64_t>(limits.steps_per_ramp);
  const Nanos step = round_duration(tj / static_cast<double>(n));
  plan.jerk_time = step * n;
  plan.accel_time = Nanos::from_seconds(ta);
  plan.cruise_time = Nanos::from_seconds(tv);

  const double sign = distance < 0 ? -1.0 : 1.0;
  std::vector<Step> accel_phase;
  for (std::int64_t k = 0; k < n; ++k)
    accel_phase.push_back({sign * a * (static_cast<double>(k) + 0.5) / static_cast<double>(n), step});
  accel_phase.push_back({sign * a, plan.accel_time});
  for (std::int64_t k = n - 1; k >= 0; --k)
    accel_phase.push_back({sign * a * (static_cast<double>(k) + 0.5) / static_cast<double>(n), step});
  // The deceleration phase mirrors the acceleration phase, so the move ends at rest.
  std::vector<Step> steps = accel_phase;
  steps.push_back({0.0, plan.cruise_time});
  for (auto it = accel_phase.rbegin(); it != accel_phase.rend(); ++it)
    steps.push_back({-it->acceleration, it->duration});
  const double scale = append_exact(profile, steps, distance);
  double peak = 0.0;
  for (const Step& s : accel_phase) peak += s.acceleration * s.duration.seconds();
  plan.peak_velocity = peak * scale;
  plan.peak_acceleration = a * scale;
  return plan;
}

PressStroke press_stroke(MotionProfile& profile, double speed, Nanos run_time, double brake_deceleration) {
  require_positive(brake_deceleration, "press_stroke: brake_deceleration must be > 0");
  if (speed == 0.0) throw std::invalid_argument("press_stroke: speed must not be 0");
  constant_speed(profile, speed, run_time);
  PressStroke stroke{};
  stroke.brake_applied = profile.end_time();
  const Nanos stop = round_duration(std::abs(speed) / brake_deceleration);
  profile.accelerate(-speed / stop.seconds(), stop);
  stroke.standstill = profile.end_time();
  stroke.stop_distance = 0.5 * speed * stop.seconds();
  return stroke;
}

} // namespace hilrig::signals
