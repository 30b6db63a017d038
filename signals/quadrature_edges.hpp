#pragma once
// Quadrature edge solver: the time of every A/B (and Z) edge, solved in closed form from
// each segment's quadratic and rounded to the nearest nanosecond (halves up, counted from
// the segment's start); no sampling. Each edge is solved from the nearer end of its
// monotonic piece where the piece slows down (from the end, the root adds two positive
// terms instead of cancelling to a rounding residue), so a move that stops on an edge's
// position has that edge at its end time exactly. The edges take the count from count_at(start
// position) to count_at(end position) exactly, one edge per count, wherever the profile
// starts and ends (fractional positions, a move settled on a count boundary). A segment whose
// velocity crosses zero is split at the turning point, so reversals inside a segment give
// the right edges in the right order; a settled segment (the last step of a move) does not
// reverse, so it is one monotonic piece to its target.
//
// Positions in counts follow QuadratureEncoder's whole-count rule (snapped_counts(): within 8
// ulps of an integer is that integer), applied to the values each is computed from: the
// profile's start; a segment's start is the count position the segment before it ended on; a
// settled end is the move's start plus its distance, each converted to counts; any other end
// is the segment's start plus its travel in counts. A move from 0.3 turn by -0.1 at 40
// counts/turn thus ends on count 8 (12 - 4), as written. Where a target is computed with
// cancellation from much larger values, the solver's end (the move's start and distance in
// counts) is the one to trust over count_at() of the rounded sum.
//
// The solver streams: fill() writes into a caller's buffer and resumes where it stopped,
// and for_each_quadrature_edge() hands edges to a callback through a stack buffer. Neither
// allocates per edge.

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "signals/motion_profile.hpp"
#include "signals/quadrature_encoder.hpp"

namespace hilrig::signals {

class QuadratureEdgeSolver {
public:
  // Solves edges of `profile` (which must outlive the solver) before `until`; an
  // open-ended last segment needs a finite `until`.
  QuadratureEdgeSolver(const MotionProfile& profile, const QuadratureEncoder& encoder,
                       Nanos until = Nanos::max());

  // Writes up to out.size() edges (out.size() >= 2: an A/B edge and its Z edge go
  // together) in time order; returns how many were written, 0 once every edge is out.
  std::size_t fill(std::span<QuadEdge> out);

  // A profile that its owner appends to as the edges are asked for: when the solver has used
  // every segment it calls `more`, which appends segments to the profile (Grown), says that
  // none will come (Whole), or that it appends no more for now (Later: fill() returns what it
  // has, and the next fill() asks again). The edges are those of the whole profile solved at once.
  enum class Growth : std::uint8_t { Grown, Whole, Later };
  void grow_with(std::function<Growth()> more) {
    more_ = std::move(more);
    growing_ = static_cast<bool>(more_);
  }

  // Starts over from the profile's start, as a new solver of the same profile, encoder,
  // `until` and growth would (the profile may have been restarted and appended to since).
  void restart();

  [[nodiscard]] std::int64_t initial_count() const { return initial_count_; }
  [[nodiscard]] std::int64_t count() const { return count_; } // after the last edge written
  [[nodiscard]] bool done() const { return done_; }

private:
  bool advance();                   // sets up the next monotonic piece; false when none is left (yet)
  bool load_segment(std::size_t i); // false when segment i does not move
  void start_piece(int piece);
  [[nodiscard]] double end_counts(const Segment& s, Nanos end) const; // needs seg_c0_

  const MotionProfile* profile_;
  const std::vector<Segment>* segments_;
  std::function<Growth()> more_;
  bool growing_ = false; // more_ may still be asked
  QuadratureEncoder encoder_;
  double counts_per_unit_ = 0;
  Nanos until_;
  double edge_offset_ = 0.5; // QuadratureEncoder::edge_offset()
  std::size_t next_segment_ = 0;
  bool done_ = false;
  bool piece_active_ = false;
  std::int64_t initial_count_ = 0;
  std::int64_t count_ = 0;
  // Index phase: (count - index_count) mod counts_per_turn, tracked incrementally.
  std::int64_t index_phase_ = 0;
  std::int64_t counts_per_turn_ = 0;

  // The current segment, in counts and nanoseconds relative to its start.
  std::int64_t seg_start_ns_ = 0;
  double seg_c0_ = 0, seg_v_ = 0, seg_a_ = 0, seg_end_ = 0, seg_cend_ = 0;
  double vertex_t_ = 0, vertex_c_ = 0; // turning point inside the segment
  // Where (ns) and on what count position the last segment loaded ended.
  std::int64_t last_end_ns_ = 0;
  double last_cend_ = 0;
  int pieces_ = 0, piece_ = 0;
  // The current monotonic piece: origin time/count/velocity, its end and direction.
  double p_t0_ = 0, p_c0_ = 0, p_v0_ = 0, p_end_ = 0, p_cend_ = 0, p_inv_v_ = 0;
  int p_dir_ = 0;
  bool p_linear_ = false;
  bool p_slowing_ = false; // decelerating: edges near its end are solved back from the end
  double p_uend_ = 0;      // |velocity| at the piece's end, counts/ns
};

// Calls f(const QuadEdge&) for every edge, in time order. Returns the final count.
template <class F>
std::int64_t for_each_quadrature_edge(const MotionProfile& profile, const QuadratureEncoder& encoder, F&& f,
                                      Nanos until = Nanos::max()) {
  QuadratureEdgeSolver solver(profile, encoder, until);
  std::array<QuadEdge, 512> buffer;
  for (std::size_t n = solver.fill(buffer); n != 0; n = solver.fill(buffer))
    for (std::size_t i = 0; i < n; ++i) f(buffer[i]);
  return solver.count();
}

// The whole edge list with the initial levels: what faults and recorders work on.
struct QuadratureTrace {
  std::int64_t initial_count = 0;
  bool initial_z = false;
  std::vector<QuadEdge> edges; // time order
  [[nodiscard]] bool initial_level(QuadChannel ch) const;
};

[[nodiscard]] QuadratureTrace solve_quadrature(const MotionProfile& profile, const QuadratureEncoder& encoder,
                                               Nanos until = Nanos::max());

} // namespace hilrig::signals
