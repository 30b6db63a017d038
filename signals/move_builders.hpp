#pragma once
// Move builders: append the classic motion shapes to a MotionProfile. Every move starts
// where the profile ends; distances are signed (negative moves backwards).
//
// Durations are rounded to the nanosecond, and the accelerations are then rescaled (by a
// relative ~1e-9) so the move covers its distance exactly and ends at rest: a move to an
// integer count stops on that count, never a hair short of it. The last step stops the
// velocity the chain of steps actually reached, without letting it change sign, so a move is
// monotonic: it never passes its target and comes back (MotionProfile::settle checks it).

#include <cstdint>

#include "core/time.hpp"
#include "signals/motion_profile.hpp"

namespace hilrig::signals {

struct MoveLimits {
  double max_speed = 0.0;    // units/s, > 0
  double acceleration = 0.0; // units/s², > 0
  double deceleration = 0.0; // units/s², > 0
};

// A rest-to-rest trapezoid (or triangle when the distance is too short to reach
// max_speed), after rounding to the nanosecond.
struct TrapezoidPlan {
  Nanos accel_time;
  Nanos cruise_time; // 0 for a triangle
  Nanos decel_time;
  double peak_velocity = 0.0; // signed
  double acceleration = 0.0;  // magnitudes, as used
  double deceleration = 0.0;
  bool triangle = false;
  [[nodiscard]] Nanos duration() const { return accel_time + cruise_time + decel_time; }
};

[[nodiscard]] TrapezoidPlan plan_trapezoid(double distance, const MoveLimits& limits);
// The seconds that move takes, in closed form before any rounding to ns: what a caller holds
// against a limit first (a rate near 0 would overflow the plan's nanoseconds).
[[nodiscard]] double trapezoid_seconds(double distance, const MoveLimits& limits);

// Spins at `velocity` for `duration` from the current position (the velocity steps: an
// ideal shaft that is already turning).
MotionProfile& constant_speed(MotionProfile& profile, double velocity, Nanos duration);

// Rest-to-rest trapezoid or triangle; the profile must be at rest. Returns the plan used.
TrapezoidPlan trapezoid_move(MotionProfile& profile, double distance, const MoveLimits& limits);

// Changes velocity to `velocity` at constant |acceleration| (> 0). Through zero this is a
// reversal inside one segment.
MotionProfile& ramp_to(MotionProfile& profile, double velocity, double acceleration);
// Reverses the current motion: ramps from v to -v at |acceleration|.
MotionProfile& reversal(MotionProfile& profile, double acceleration);

// Jerk-limited (S-curve) rest-to-rest move with symmetric acceleration and deceleration.
// Each jerk ramp is approximated by `steps_per_ramp` constant-acceleration segments, each
// holding the ramp's acceleration at its midpoint: the velocity at the end of every ramp
// is exact, the position error of the staircase is O(jerk·Tj³/N²) and is absorbed by the
// final rescale, so the move still ends exactly at its distance. Edge times are then
// solved exactly from each step's quadratic.
struct SCurveLimits {
  double max_speed = 0.0;    // units/s
  double acceleration = 0.0; // units/s², peak
  double jerk = 0.0;         // units/s³
  int steps_per_ramp = 8;    // N >= 1
};
struct SCurvePlan {
  Nanos jerk_time;   // each of the four ramps
  Nanos accel_time;  // constant acceleration between ramps
  Nanos cruise_time; // at peak velocity
  double peak_velocity = 0.0;
  double peak_acceleration = 0.0;
  [[nodiscard]] Nanos duration() const { return 4 * jerk_time + 2 * accel_time + cruise_time; }
};
SCurvePlan s_curve_move(MotionProfile& profile, double distance, const SCurveLimits& limits);
// The seconds that move takes, in closed form before the ramps are cut into steps and rounded.
[[nodiscard]] double s_curve_seconds(double distance, const SCurveLimits& limits);

// A press stroke: steps to `speed`, runs for `run_time`, then the brake is applied and
// decelerates at `brake_deceleration` (> 0) to standstill.
struct PressStroke {
  Nanos brake_applied;  // absolute time the brake is applied
  Nanos standstill;     // absolute time the shaft stops
  double stop_distance; // travel from brake applied to standstill (signed)
};
PressStroke press_stroke(MotionProfile& profile, double speed, Nanos run_time, double brake_deceleration);

} // namespace hilrig::signals
