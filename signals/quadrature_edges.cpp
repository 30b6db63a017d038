#include "signals/quadrature_edges.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace hilrig::signals {

namespace {
int sign_of(double x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); }
} // namespace

QuadratureEdgeSolver::QuadratureEdgeSolver(const MotionProfile& profile, const QuadratureEncoder& encoder,
                                           Nanos until)
    : profile_(&profile), segments_(&profile.segments()), encoder_(encoder),
      counts_per_unit_(encoder.counts_per_unit()), until_(until), edge_offset_(encoder.edge_offset()),
      counts_per_turn_(encoder.counts_per_turn()) {
  if (encoder.lines_per_turn == 0)
    throw std::invalid_argument("QuadratureEncoder: lines_per_turn must be > 0");
  restart();
}

void QuadratureEdgeSolver::restart() {
  growing_ = static_cast<bool>(more_);
  next_segment_ = 0;
  done_ = false;
  piece_active_ = false;
  pieces_ = 0;
  piece_ = 0;
  initial_count_ = encoder_.count_at(profile_->position(profile_->start_time()));
  last_end_ns_ = std::numeric_limits<std::int64_t>::min();
  last_cend_ = 0.0;
  count_ = initial_count_;
  index_phase_ = (count_ - encoder_.index_count) % counts_per_turn_;
  if (index_phase_ < 0) index_phase_ += counts_per_turn_;
}

bool QuadratureEdgeSolver::load_segment(std::size_t i) {
  const Segment& s = (*segments_)[i];
  if (s.start >= until_) {
    next_segment_ = segments_->size();
    growing_ = false; // nothing later is solved
    return false;
  }
  Nanos end = s.duration == Nanos::max() ? until_ : std::min(s.end(), until_);
  if (end == Nanos::max())
    throw std::invalid_argument("QuadratureEdgeSolver: an open-ended profile needs a finite 'until'");
  // Work in counts and nanoseconds: per-edge arithmetic then needs no unit conversion.
  seg_start_ns_ = s.start.count();
  seg_end_ = static_cast<double>((end - s.start).count());
  // A segment starts where the one before it ended (MotionProfile joins them exactly), so it
  // starts on the count position that one ended on: one value, snapped once.
  const bool joined = s.start.count() == last_end_ns_;
  seg_c0_ = joined ? last_cend_ : QuadratureEncoder::snap_to_count(counts_per_unit_ * s.position);
  seg_v_ = counts_per_unit_ * s.velocity * 1e-9;
  seg_a_ = counts_per_unit_ * s.acceleration * 1e-18;
  seg_cend_ = end_counts(s, end);
  last_end_ns_ = end.count();
  last_cend_ = seg_cend_;
  if (seg_v_ == 0.0 && seg_a_ == 0.0) return false;
  pieces_ = 1;
  // A settled segment does not reverse (MotionProfile::settle checks it in the profile's
  // units); a turning point that the conversion to counts and nanoseconds puts a hair
  // before its end is that rounding, not a reversal.
  if (seg_a_ != 0.0 && !s.settled_end) {
    const double tv = -seg_v_ / seg_a_;
    if (tv > 0.0 && tv < seg_end_) { // the velocity crosses zero: split at the turning point
      pieces_ = 2;
      vertex_t_ = tv;
      vertex_c_ = seg_c0_ + 0.5 * seg_v_ * tv; // c0 + v·tv + a·tv²/2 with a·tv = -v
    }
  }
  return true;
}

// The segment's position at `end` in counts, the snapping rule of QuadratureEncoder applied
// to the values it is computed from: a settled end is the move's start plus its distance,
// each converted to counts (0.3 - 0.1 turns at 40 counts/turn is 12 - 4 = 8, where
// (0.3 - 0.1)·40 is 7.999999999999999); any other end is the segment's start plus its travel
// in counts. Either way the edges take the count exactly to count_at() of that end.
double QuadratureEdgeSolver::end_counts(const Segment& s, Nanos end) const {
  const double dt = (end - s.start).seconds();
  const double travel = counts_per_unit_ * ((s.velocity + 0.5 * s.acceleration * dt) * dt);
  const double reached =
      QuadratureEncoder::snap_to_count(seg_c0_ + travel, std::max(std::abs(seg_c0_), std::abs(travel)));
  if (!s.settled_end) return reached;
  const double from = counts_per_unit_ * s.settled_from;
  const double distance = counts_per_unit_ * s.settled_distance;
  const double target =
      QuadratureEncoder::snap_to_count(from + distance, std::max(std::abs(from), std::abs(distance)));
  if (end == s.end()) return target;
  // Cut short by `until`: where the closed form is, but never past the target (Segment::position_at).
  return target >= seg_c0_ ? std::min(reached, target) : std::max(reached, target);
}

void QuadratureEdgeSolver::start_piece(int piece) {
  piece_ = piece;
  piece_active_ = true;
  p_linear_ = seg_a_ == 0.0;
  if (pieces_ == 1) {
    p_t0_ = 0.0;
    p_c0_ = seg_c0_;
    p_v0_ = seg_v_;
    p_end_ = seg_end_;
    p_dir_ = seg_v_ != 0.0 ? sign_of(seg_v_) : sign_of(seg_a_);
    p_cend_ = seg_cend_;
  } else if (piece == 0) {
    p_t0_ = 0.0;
    p_c0_ = seg_c0_;
    p_v0_ = seg_v_;
    p_end_ = vertex_t_;
    p_dir_ = sign_of(seg_v_);
    p_cend_ = vertex_c_;
  } else {
    p_t0_ = vertex_t_;
    p_c0_ = vertex_c_;
    p_v0_ = 0.0;
    p_end_ = seg_end_;
    p_dir_ = sign_of(seg_a_);
    p_cend_ = seg_cend_;
  }
  // The piece's ends decide its direction: when a settled end lies a few ulps past a
  // turning point the closed form puts just before it, the count still follows the ends.
  if (p_cend_ != p_c0_) p_dir_ = p_cend_ > p_c0_ ? 1 : -1;
  p_inv_v_ = p_linear_ ? 1.0 / p_v0_ : 0.0;
  // Slowing towards its end: its speed there, in its direction, is what the closed form
  // gives (0 at a turning point), never below 0 (a rounding of a stop).
  p_slowing_ = !p_linear_ && seg_a_ * p_dir_ < 0.0;
  const double v_end = pieces_ == 2 && piece == 0 ? 0.0 : seg_v_ + seg_a_ * seg_end_;
  p_uend_ = std::max(0.0, v_end * p_dir_);
}

bool QuadratureEdgeSolver::advance() {
  if (piece_active_) return true;
  if (piece_ + 1 < pieces_) {
    start_piece(piece_ + 1);
    return true;
  }
  for (;;) {
    while (next_segment_ < segments_->size()) {
      const std::size_t i = next_segment_++;
      if (load_segment(i)) {
        start_piece(0);
        return true;
      }
    }
    if (!growing_) break;
    const Growth grown = more_();
    if (grown == Growth::Later) return false; // not done: the next fill() asks again
    if (grown == Growth::Whole) {
      growing_ = false; // the profile is whole
      break;
    }
  }
  pieces_ = 0;
  done_ = true;
  return false;
}

std::size_t QuadratureEdgeSolver::fill(std::span<QuadEdge> out) {
  if (out.size() < 2) throw std::invalid_argument("QuadratureEdgeSolver::fill: buffer must hold 2 edges");
  std::size_t written = 0;
  const std::size_t limit = out.size() - 1; // room for an A/B edge and its Z edge
  const bool has_index = encoder_.index_width > 0;
  const std::int64_t index_width = encoder_.index_width;
  while (written < limit) {
    if (!piece_active_ && !advance()) return written;
    const int dir = p_dir_;
    const double step = dir;
    // The edge from n up to n+1 sits at n + edge_offset counts and is emitted once the
    // position reaches it; the edge from n down to n-1 sits at n - 1 + edge_offset and is
    // emitted once the position falls below it (count_at's floor, both ways). Integers plus
    // 0.5 or 1 are exact in a double, so the comparisons with the piece's end are exact.
    double h = static_cast<double>(count_) + edge_offset_ - (dir > 0 ? 0.0 : 1.0);
    while (written < limit && (dir > 0 ? h <= p_cend_ : h > p_cend_)) {
      const double d = h - p_c0_;
      double t;
      if (p_linear_) {
        t = p_t0_ + d * p_inv_v_;
      } else if (p_slowing_ && step * (p_cend_ - h) < step * (h - p_c0_)) {
        // Nearer the slow end of a decelerating piece: solved back from that end, where
        // v_end² + 2·|a|·D adds two positive terms. Solved forward, v0² + 2·a·d cancels to
        // a residue of the rounding (~1e-16·v0²) near the end, and its square root puts an
        // edge on the end position up to microseconds early; from the end it lands on the
        // end time itself (D = 0).
        const double rest = std::max(0.0, step * (p_cend_ - h)); // D, counts still to go
        const double root = std::sqrt(p_uend_ * p_uend_ - 2.0 * step * seg_a_ * rest);
        const double denom = p_uend_ + root;
        t = denom != 0.0 ? p_end_ - 2.0 * rest / denom : p_end_;
      } else {
        // Numerically stable root of c0 + v0·t + a·t²/2 = h (no cancellation near v0).
        const double root = std::sqrt(std::max(0.0, p_v0_ * p_v0_ + 2.0 * seg_a_ * d));
        const double denom = p_v0_ + step * root;
        t = denom != 0.0 ? p_t0_ + 2.0 * d / denom : p_t0_;
      }
      t = std::min(std::max(t, p_t0_), p_end_);
      const Nanos time{seg_start_ns_ + static_cast<std::int64_t>(t + 0.5)};
      const std::int64_t old = count_;
      count_ += dir;
      // A changes between states 0-1 and 2-3, B between 1-2 and 3-0: A iff the higher
      // of the two states is odd.
      const bool a_edge = (std::max(old, count_) & 1) != 0;
      QuadEdge& e = out[written++];
      e.time = time;
      e.count = count_;
      e.channel = a_edge ? QuadChannel::A : QuadChannel::B;
      e.level = level_of(a_edge ? channel_a(count_) : channel_b(count_));
      if (has_index) {
        const bool z_before = index_phase_ < index_width;
        index_phase_ += dir;
        if (index_phase_ == counts_per_turn_) index_phase_ = 0;
        if (index_phase_ < 0) index_phase_ = counts_per_turn_ - 1;
        const bool z_after = index_phase_ < index_width;
        if (z_before != z_after) out[written++] = QuadEdge{time, count_, QuadChannel::Z, level_of(z_after)};
      }
      h += step;
    }
    if (written >= limit) return written;
    piece_active_ = false;
  }
  return written;
}

bool QuadratureTrace::initial_level(QuadChannel ch) const {
  switch (ch) {
  case QuadChannel::A:
    return channel_a(initial_count);
  case QuadChannel::B:
    return channel_b(initial_count);
  case QuadChannel::Z:
    return initial_z;
  }
  return false;
}

QuadratureTrace solve_quadrature(const MotionProfile& profile, const QuadratureEncoder& encoder,
                                 Nanos until) {
  QuadratureEdgeSolver solver(profile, encoder, until);
  QuadratureTrace trace;
  trace.initial_count = solver.initial_count();
  trace.initial_z = encoder.index_high(trace.initial_count);
  std::array<QuadEdge, 1024> buffer;
  for (std::size_t n = solver.fill(buffer); n != 0; n = solver.fill(buffer))
    trace.edges.insert(trace.edges.end(), buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(n));
  return trace;
}

} // namespace hilrig::signals
