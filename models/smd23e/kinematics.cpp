#include "models/smd23e/kinematics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace hilrig::models::smd23e {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
} // namespace

double ramp_time(double v1, double v2, double rate, RampShape shape) {
  return std::abs(v2 - v1) / shape.effective(rate);
}

double ramp_steps(double v1, double v2, double rate, RampShape shape) {
  return std::abs(v2 * v2 - v1 * v1) / (2.0 * shape.effective(rate));
}

void append_ramp(std::vector<Piece>& pieces, double v1, double v2, double rate, RampShape shape) {
  if (v1 == v2) {
    return;
  }
  const double sign = v2 > v1 ? 1.0 : -1.0;
  const Phase phase = v2 > v1 ? Phase::Accelerate : Phase::Decelerate;
  const double total = ramp_time(v1, v2, rate, shape);
  const double f = shape.linear_fraction;
  if (f >= 1.0) {
    pieces.push_back({total, v1, sign * rate, 0.0, phase});
    return;
  }
  // Jerk up to the peak rate, constant rate, jerk back down: point-symmetric (spec §3.3).
  const double tj = (1.0 - f) * total / 2.0;
  const double tl = f * total;
  const double jerk = sign * rate / tj;
  Piece up{tj, v1, 0.0, jerk, phase};
  pieces.push_back(up);
  double v = up.velocity_at(tj);
  if (tl > 0.0) {
    pieces.push_back({tl, v, sign * rate, 0.0, phase});
    v += sign * rate * tl;
  }
  pieces.push_back({tj, v, sign * rate, -jerk, phase});
}

void append_cruise(std::vector<Piece>& pieces, double v, double steps) {
  if (steps <= 0.0) {
    return;
  }
  pieces.push_back({steps == kInf ? kInf : steps / v, v, 0.0, 0.0, Phase::Cruise});
}

ProfileFigures profile_figures(double n, double vs, double vp, double a, double d, RampShape shape) {
  ProfileFigures f;
  const double ae = shape.effective(a);
  const double de = shape.effective(d);
  const double n_acc = (vp * vp - vs * vs) / (2.0 * ae);
  const double n_dec = (vp * vp - vs * vs) / (2.0 * de);
  if (n_acc + n_dec <= n) {
    f.peak_speed = vp;
    f.accel_steps = n_acc;
    f.decel_steps = n_dec;
    f.duration = (vp - vs) / ae + (n - n_acc - n_dec) / vp + (vp - vs) / de;
    return f;
  }
  f.triangle = true;
  f.peak_speed = std::sqrt(vs * vs + 2.0 * n * ae * de / (ae + de));
  f.accel_steps = (f.peak_speed * f.peak_speed - vs * vs) / (2.0 * ae);
  f.decel_steps = n - f.accel_steps;
  f.duration = (f.peak_speed - vs) * (1.0 / ae + 1.0 / de);
  return f;
}

std::vector<Piece> plan_move(double n, double vs, double vp, double a, double d, RampShape shape) {
  std::vector<Piece> pieces;
  if (n <= 0.0) {
    return pieces;
  }
  const ProfileFigures f = profile_figures(n, vs, vp, a, d, shape);
  append_ramp(pieces, vs, f.peak_speed, a, shape);
  if (!f.triangle) {
    append_cruise(pieces, vp, n - f.accel_steps - f.decel_steps);
  }
  append_ramp(pieces, f.peak_speed, vs, d, shape);
  return pieces;
}

Motion::Motion(Nanos start, std::vector<Piece> pieces, double time_scale)
    : start_(start), scale_(time_scale), pieces_(std::move(pieces)) {
  if (!(scale_ > 0.0)) throw std::invalid_argument("Motion: time_scale must be > 0");
  double t = 0.0;
  double p = 0.0;
  placed_.reserve(pieces_.size());
  for (const Piece& piece : pieces_) {
    placed_.push_back({t, p});
    t += piece.duration;
    p = piece.duration == kInf ? kInf : p + piece.distance_at(piece.duration);
  }
  total_ = p;
  end_ = t == kInf ? Nanos::max() : start_ + Nanos::from_seconds(t * scale_);
}

std::size_t Motion::index_at(double tau) const {
  std::size_t i = 0;
  while (i + 1 < placed_.size() && placed_[i + 1].t0 <= tau) {
    ++i;
  }
  return i;
}

double Motion::progress(Nanos t) const {
  if (pieces_.empty() || t <= start_) {
    return 0.0;
  }
  if (t >= end_) {
    return total_;
  }
  const double tau = board_time(t);
  const std::size_t i = index_at(tau);
  const double local = std::min(tau - placed_[i].t0, pieces_[i].duration);
  return placed_[i].p0 + pieces_[i].distance_at(local);
}

double Motion::velocity(Nanos t) const {
  if (pieces_.empty() || t < start_ || t >= end_) {
    return 0.0;
  }
  const double tau = board_time(t);
  const std::size_t i = index_at(tau);
  return pieces_[i].velocity_at(std::min(tau - placed_[i].t0, pieces_[i].duration));
}

Phase Motion::phase(Nanos t) const {
  if (pieces_.empty() || t < start_ || t >= end_) {
    return Phase::Cruise;
  }
  return pieces_[index_at(board_time(t))].phase;
}

// In a piece with v0, a0 and jerk >= 0 every floating-point step of progress() is
// non-decreasing in t, and rounding to nearest keeps it so: the board time (int64 to double,
// a product and a quotient by positive constants), the local time (a difference with and a min
// of constants, >= 0), distance_at's sums and products of terms >= 0 that do not decrease, and
// p0 plus that. So progress is non-decreasing over whole ns that map into such a piece.
Motion::Span Motion::span_between(std::int64_t lo, std::int64_t hi, std::size_t& piece) const {
  piece = index_at(board_time(Nanos{lo}));
  // index_at is non-decreasing in the board time, which is non-decreasing in t.
  if (piece + 1 < placed_.size() && placed_[piece + 1].t0 <= board_time(Nanos{hi})) return Span::Pieces;
  const Piece& p = pieces_[piece];
  return p.v0 >= 0.0 && p.a0 >= 0.0 && p.jerk >= 0.0 ? Span::Rising : Span::OnePiece;
}

// Progress is non-decreasing on [lo, hi], so every probe keeps lo short of x and hi reaching it
// and the first ns reaching x is the one the bisection would end on. The first probe is the
// closed-form time (within a ns or so of the answer); from there the bracket grows towards the
// answer in doubling strides, then is halved: a few probes, never many more than a bisection's.
Nanos Motion::first_reaching(double x, double base, std::size_t piece, std::int64_t lo,
                             std::int64_t hi) const {
  const Piece& p = pieces_[piece];
  const double rest = x - base - placed_[piece].p0;
  const auto reached = [this, x, base](std::int64_t t) { return reaches(base + progress(Nanos{t}), x); };
  // The local time where the piece covers `rest`: the quadratic's stable root, then Newton for
  // the jerk's term.
  const double root = std::sqrt(std::max(0.0, p.v0 * p.v0 + 2.0 * p.a0 * rest));
  double tau = p.v0 + root > 0.0 ? 2.0 * rest / (p.v0 + root) : 0.0;
  if (p.jerk != 0.0) {
    for (int i = 0; i < 4; ++i) {
      const double v = p.velocity_at(tau);
      if (!(v > 0.0)) break;
      tau -= (p.distance_at(tau) - rest) / v;
    }
  }
  const double guess =
      std::ceil(static_cast<double>(start_.count()) + (placed_[piece].t0 + tau) * scale_ * 1e9);
  std::int64_t g = lo + (hi - lo) / 2;
  if (guess > static_cast<double>(lo) && guess < static_cast<double>(hi))
    g = static_cast<std::int64_t>(guess);
  if (reached(g)) {
    hi = g;
    for (std::int64_t stride = 1; hi - lo > 1; stride *= 2) {
      const std::int64_t t = std::max(hi - stride, lo + 1);
      if (!reached(t)) {
        lo = t;
        break;
      }
      hi = t;
    }
  } else {
    lo = g;
    for (std::int64_t stride = 1; hi - lo > 1; stride *= 2) {
      const std::int64_t t = std::min(lo + stride, hi - 1);
      if (reached(t)) {
        hi = t;
        break;
      }
      lo = t;
    }
  }
  while (hi - lo > 1) {
    const std::int64_t mid = lo + (hi - lo) / 2;
    if (reached(mid))
      hi = mid;
    else
      lo = mid;
  }
  return Nanos{hi};
}

Nanos Motion::time_at_progress(double x, double base) const {
  if (reaches(base, x)) {
    return start_;
  }
  if (!reaches(base + total_, x)) {
    return Nanos::max();
  }
  // Progress is non-decreasing (speed never drops below v_s > 0): bisect on whole ns.
  std::int64_t lo = start_.count();
  std::int64_t hi = end_ == Nanos::max() ? lo : end_.count();
  if (end_ == Nanos::max()) {
    std::int64_t step = 1'000'000;
    while (!reaches(base + progress(Nanos{hi}), x)) {
      lo = hi;
      hi += step;
      step *= 2;
    }
  }
  // The progress at lo: the start's, or a probe's (the value progress(Nanos{lo}) gives).
  double at_lo = progress(Nanos{lo});
  const auto probe = [this](std::int64_t t) { return progress(Nanos{t}); };
  // Once lo and hi are probes (lo short of x, hi reaching it) within one rising piece, the
  // bisection can only end at the one ns where progress there first reaches x: that ns is
  // found from the piece's closed form rather than by the rest of the bisection's probes. Looked at only
  // before a probe the path does not remember (remembered ones cost nothing), and no more once
  // lo and hi share a piece that is not rising.
  bool look_for_rise = true;
  for (std::size_t depth = 0; hi - lo > 1; ++depth) {
    const std::int64_t mid = lo + (hi - lo) / 2;
    if (look_for_rise && lo > start_.count() && hi < end_.count() && !path_.knows(depth, mid)) {
      std::size_t piece = 0;
      const Span span = span_between(lo, hi, piece);
      if (span == Span::Rising) return first_reaching(x, base, piece, lo, hi);
      look_for_rise = span == Span::Pieces;
    }
    const double at_mid = path_.probe(depth, mid, probe);
    if (reaches(base + at_mid, x)) {
      hi = mid;
    } else {
      lo = mid;
      at_lo = at_mid;
    }
  }
  return reaches(base + at_lo, x) ? Nanos{lo} : Nanos{hi};
}

} // namespace hilrig::models::smd23e
