#pragma once
// Move kinematics of the SMD23E indexer (spec §3.2–§3.3), in "progress" coordinates: steps
// travelled along the move's direction, from 0. A motion is a chain of pieces, each of
// constant jerk (jerk 0 for linear ramps and cruise), like Klipper's trapq moves. Times come
// from the closed-form profile formulas, never from sampling.

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/time.hpp"
#include "models/smd23e/bisection_path.hpp"

namespace hilrig::models::smd23e {

enum class Phase : std::uint8_t { Accelerate, Cruise, Decelerate };

// Whether a progress p has reached x. Floating-point progress lands a few ulps off a whole
// step where the exact profile meets it on a whole ns (a cruise step 1.4 ms into a cruise
// gives 126.99999999999999): within 8 ulps of x counts as reached, far below a ns of travel at
// any step rate of the board (1 ns at 1 step/s is 1e-9 step). Non-decreasing in p, so the first
// ns reaching x is well defined; step counts and step times both use it.
[[nodiscard]] inline bool reaches(double p, double x) {
  return x - p <= 8.0 * std::numeric_limits<double>::epsilon() * std::abs(x);
}

struct Piece {
  double duration = 0.0; // s; +inf for an open-ended cruise (jog)
  double v0 = 0.0;       // steps/s at start
  double a0 = 0.0;       // steps/s² at start
  double jerk = 0.0;     // steps/s³
  Phase phase = Phase::Cruise;

  [[nodiscard]] double distance_at(double tau) const {
    return tau * (v0 + tau * (a0 / 2.0 + tau * jerk / 6.0));
  }
  [[nodiscard]] double velocity_at(double tau) const { return v0 + tau * (a0 + tau * jerk / 2.0); }
  [[nodiscard]] double accel_at(double tau) const { return a0 + tau * jerk; }
};

// The ramp shape of a move: the fraction of the ramp time spent at constant acceleration.
// 1 = linear (J = 0); 0 = triangular S (J = 1); between = trapezoidal S (J = 2…5000).
struct RampShape {
  double linear_fraction = 1.0;
  // A ramp of this shape covers the same distance in the same time as a linear ramp at
  // rate·(1+f)/2 (spec §3.3: T_ramp = 2·t_lin/(1+f)).
  [[nodiscard]] double effective(double rate) const { return rate * (1.0 + linear_fraction) / 2.0; }
};

// Ramp time and steps from v1 to v2 at a (peak) rate, spec §3.2 and §3.3.
[[nodiscard]] double ramp_time(double v1, double v2, double rate, RampShape shape);
[[nodiscard]] double ramp_steps(double v1, double v2, double rate, RampShape shape);

// Appends a ramp v1 → v2 (either direction) to a chain of pieces.
void append_ramp(std::vector<Piece>& pieces, double v1, double v2, double rate, RampShape shape);
// Appends a cruise at v over `steps` (or forever when steps is +inf).
void append_cruise(std::vector<Piece>& pieces, double v, double steps);

struct ProfileFigures {
  bool triangle = false;
  double peak_speed = 0.0; // steps/s
  double accel_steps = 0.0;
  double decel_steps = 0.0;
  double duration = 0.0; // s, from the start (speed jumps to v_s) to the stop
};

// Trapezoid or triangle for a move of n steps (spec §3.2), accel a and decel d in steps/s².
[[nodiscard]] ProfileFigures profile_figures(double n, double vs, double vp, double a, double d,
                                             RampShape shape);
// The pieces of that move, from v_s up to the peak and back down to v_s.
[[nodiscard]] std::vector<Piece> plan_move(double n, double vs, double vp, double a, double d,
                                           RampShape shape);

// A planned run of the motor: pieces placed at an absolute start time.
class Motion {
public:
  Motion() = default;
  // time_scale > 0: the pieces are in the board's own time, which runs time_scale times as
  // long in real time (a time base off its rate; 1 = exact). Velocities stay in board units.
  Motion(Nanos start, std::vector<Piece> pieces, double time_scale = 1.0);

  [[nodiscard]] Nanos start() const { return start_; }
  // End of the last piece; Nanos::max() when open-ended.
  [[nodiscard]] Nanos end() const { return end_; }
  [[nodiscard]] double total_steps() const { return total_; } // +inf when open-ended
  [[nodiscard]] const std::vector<Piece>& pieces() const { return pieces_; }

  [[nodiscard]] double progress(Nanos t) const;
  [[nodiscard]] double velocity(Nanos t) const;
  [[nodiscard]] Phase phase(Nanos t) const;
  // First time base + progress reaches() x (exact to 1 ns); Nanos::max() if never. `base`:
  // a chain's progress before this motion, added in the same floating-point sum the caller
  // counts steps by, so the time found and the count agree to the ns.
  [[nodiscard]] Nanos time_at_progress(double x, double base = 0.0) const;

private:
  struct Placed {
    double t0; // s from start_
    double p0; // progress at t0
  };
  [[nodiscard]] std::size_t index_at(double tau) const;
  // Where whole nanoseconds lo < hi (both inside (start, end)) fall: in one piece whose speed,
  // acceleration and jerk are all >= 0 (progress() is then non-decreasing from lo to hi in
  // floating point too), in one other piece, or in more than one. `piece`: lo's piece.
  enum class Span : std::uint8_t { Rising, OnePiece, Pieces };
  [[nodiscard]] Span span_between(std::int64_t lo, std::int64_t hi, std::size_t& piece) const;
  // The first whole ns in (lo, hi] whose progress reaches x, where [lo, hi] lies in that rising
  // piece, base + progress(lo) does not reach x and base + progress(hi) does: searched from the
  // piece's closed-form time.
  [[nodiscard]] Nanos first_reaching(double x, double base, std::size_t piece, std::int64_t lo,
                                     std::int64_t hi) const;
  [[nodiscard]] double board_time(Nanos t) const { return (t - start_).seconds() / scale_; }
  Nanos start_{0};
  Nanos end_{0};
  double scale_ = 1.0;
  double total_ = 0.0;
  std::vector<Piece> pieces_;
  std::vector<Placed> placed_;
  // time_at_progress()'s last probes: the next whole step's time (a bisection from the
  // motion's start to its end) shares the first of them with the step before.
  mutable BisectionPath path_;
};

} // namespace hilrig::models::smd23e
