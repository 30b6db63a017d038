#include "rig/campaign/quadrature_edges.hpp"

#include <cmath>
#include <limits>

namespace hilrig::campaign {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

std::int64_t mod4(std::int64_t c) { return ((c % 4) + 4) % 4; }

// Time from now for position to move by d (same sign as the motion), with velocity v and
// acceleration a now; NaN when it is never reached.
double solve(double d, double v, double a) {
  if (a == 0.0) return v == 0.0 ? kNaN : d / v;
  if (v == 0.0) {
    const double q = 2.0 * d / a;
    return q >= 0.0 ? std::sqrt(q) : kNaN;
  }
  double disc = v * v + 2.0 * a * d;
  if (disc < 0.0) {
    // Rounding at a turning point that lands exactly on the count.
    if (disc > -1e-9 * v * v)
      disc = 0.0;
    else
      return kNaN;
  }
  // The stable form of the first root ahead. The root's sign follows the direction of
  // travel (d), not v: just after a turning point v may be a rounding error of either sign.
  const double root = std::sqrt(disc);
  return 2.0 * d / (v + (d > 0.0 ? root : -root));
}

} // namespace

Level a_level(std::int64_t count) {
  const std::int64_t s = mod4(count);
  return level_of(s == 1 || s == 2);
}

Level b_level(std::int64_t count) {
  const std::int64_t s = mod4(count);
  return level_of(s == 2 || s == 3);
}

QuadratureEdges::QuadratureEdges(const signals::MotionProfile& profile) : profile_(profile) {
  start_count_ = static_cast<std::int64_t>(std::floor(profile.position(profile.start_time())));
  count_ = start_count_;
}

bool QuadratureEdges::open_piece() {
  const auto& segs = profile_.segments();
  while (segment_ < segs.size()) {
    const signals::Segment& s = segs[segment_];
    const bool open_ended = s.duration == Nanos::max();
    const double dur = open_ended ? kInf : s.duration.seconds();
    // A turning point inside the segment splits it into two monotonic pieces.
    const double turn = s.acceleration != 0.0 ? -s.velocity / s.acceleration : -1.0;
    const bool splits = turn > 0.0 && turn < dur;
    if (!second_piece_) {
      tau_ = 0.0;
      piece_end_ = splits ? turn : dur;
      const double vmid = s.velocity + s.acceleration * (piece_end_ == kInf ? 1.0 : piece_end_ / 2.0);
      direction_ = vmid > 0.0 ? 1 : vmid < 0.0 ? -1 : 0;
      second_piece_ = splits;
      if (!splits) ++segment_;
      piece_open_ = true;
      current_ = &s;
      return true;
    }
    // The piece after the turning point.
    tau_ = turn;
    piece_end_ = dur;
    direction_ = s.acceleration > 0.0 ? 1 : -1;
    second_piece_ = false;
    ++segment_;
    piece_open_ = true;
    current_ = &s;
    return true;
  }
  return false;
}

std::optional<CountEdge> QuadratureEdges::next() {
  for (;;) {
    if (!piece_open_ && !open_piece()) return std::nullopt;
    const signals::Segment& s = *current_;
    if (direction_ != 0) {
      const double p = s.position + s.velocity * tau_ + 0.5 * s.acceleration * tau_ * tau_;
      const double v = s.velocity + s.acceleration * tau_;
      // Up: the count becomes c+1 when position reaches c+1. Down: it becomes c-1 when
      // position falls below c.
      const double target = direction_ > 0 ? static_cast<double>(count_ + 1) : static_cast<double>(count_);
      const double dt = solve(target - p, v, s.acceleration);
      if (std::isfinite(dt) && dt >= 0.0 && tau_ + dt <= piece_end_) {
        tau_ += dt;
        count_ += direction_;
        Nanos t = s.start + Nanos::from_seconds(tau_);
        if (t < last_) t = last_; // rounding never reorders edges
        last_ = t;
        // Up to count_ the line that changed is A when the new state is 1 or 3 (from 0 or 2).
        const std::int64_t changed_state = direction_ > 0 ? mod4(count_) : mod4(count_ + 1);
        const bool on_a = changed_state == 1 || changed_state == 3;
        return CountEdge{t, count_, on_a, on_a ? a_level(count_) : b_level(count_)};
      }
    }
    piece_open_ = false;
  }
}

} // namespace hilrig::campaign
