#pragma once
// Random shaft motion in encoder counts for property tests: rest-to-rest trapezoids either
// way, pauses, ramps to a new velocity (through zero: a reversal inside one segment), cruises
// and reversals, from standstill to about one count per 3 us, and cruises whose edges fall on
// the 10 us grid.
#include <cmath>
#include <cstdint>
#include <random>

#include "signals/motion_profile.hpp"
#include "signals/move_builders.hpp"

namespace hilrig::signals::testing {

inline MotionProfile random_motion(std::uint64_t seed, Nanos end) {
  std::mt19937_64 rng(seed);
  const auto uniform = [&rng](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
  };
  const auto pick = [&rng](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  const auto ms = [&](double lo, double hi) { return Nanos::from_seconds(uniform(lo, hi) * 1e-3); };
  MotionProfile p(0.5); // count 0: A and B low
  bool resting = true;  // exactly at rest (the start, or the end of a trapezoid)
  while (p.end_time() < end) {
    const double accel = uniform(2e6, 6e7); // counts/s²
    if (resting) {
      if (pick(0, 3) == 0) {
        // One count per 10 us with every edge on a 10 us grid point (a scan period): a pause
        // that brings the first edge there, then the cruise.
        const double v = pick(0, 1) == 0 ? 1e5 : -1e5;
        const double frac = p.end_position() - std::floor(p.end_position());
        const auto first = static_cast<std::int64_t>(std::llround((v > 0 ? 1.0 - frac : frac) * 1e4));
        const std::int64_t misalign = (p.end_time().count() + first) % 10'000;
        if (misalign != 0) {
          p.dwell(Nanos{10'000 - misalign});
        }
        constant_speed(p, v, ms(0.05, 10));
        resting = false;
      } else if (pick(0, 2) == 0) {
        p.dwell(ms(0.01, 15));
      } else if (pick(0, 2) == 0) {
        constant_speed(p, uniform(-3e5, 3e5), ms(0.01, 20));
        resting = false;
      } else {
        const double distance = (pick(0, 1) == 0 ? -1 : 1) * uniform(0.3, 6000);
        (void)trapezoid_move(p, distance, MoveLimits{uniform(5e3, 3e5), accel, uniform(2e6, 6e7)});
      }
      continue;
    }
    switch (pick(0, 3)) {
    case 0:
      ramp_to(p, uniform(-3e5, 3e5), accel);
      break;
    case 1:
      ramp_to(p, 0.0, accel); // then a pause at (about) zero velocity
      p.cruise(ms(0.01, 10));
      break;
    case 2:
      p.cruise(ms(0.01, 20));
      break;
    default:
      reversal(p, accel);
      break;
    }
  }
  return p;
}

} // namespace hilrig::signals::testing
