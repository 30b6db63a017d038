#pragma once
// An incremental quadrature encoder: lines per turn, X4 counts (4 per line), A leading B
// for forward motion, and an index pulse Z once per turn.
//
// Count n is the encoder state: (A, B) = 00, 10, 11, 01 for n mod 4 = 0, 1, 2, 3. Where
// the edge from n to n+1 sits is the encoder's EdgePlacement:
//   HalfCount  at n + 0.5 counts: count = round(position) (halves up), so a shaft that
//              stops exactly on a count rests in the middle of a state, not on an edge;
//   WholeCount at n + 1 counts:   count = floor(position), the rig's convention (positions
//              in checks name the count they enter: going up, count n is entered when the
//              position reaches n; going down, count n-1 when it falls below n).
// Either way the count at a position is count_at(), and the edges the solver emits always
// take the count from count_at(start) to count_at(end).
//
// Whole counts survive floating point (snapped_counts()): a position in counts that lies
// within 8 ulps (2^-49, about 1.8e-15, relative) of an integer is that integer. A user writes
// decimals, and 0.3 - 0.1 turns is 0.19999999999999998, 7.999999999999999 counts at 40
// counts/turn: without the rule a move from 0.3 by -0.1 would end on count 7, not 8. The
// tolerance is relative to the larger of the values the position was computed from (a move's
// start and distance in counts, a segment's start and travel, or the position itself), at
// least 1 count. It cannot change a position a user can write: a count value that is a
// decimal of at most 14 digits in all (123456.12345678, 0.00000000000001) and not an integer
// is at least 1e-14 of its magnitude (and at least 1e-14 counts) from every integer, more than
// 5 times the tolerance; a position of up to 7 digits in turns is such a count value at any
// encoder up to 1,000,000 lines (4,000,000 counts/turn: 7 more digits).

#include <cstdint>

#include "core/line.hpp"
#include "core/time.hpp"

namespace hilrig::signals {

enum class QuadChannel : std::uint8_t { A, B, Z };
enum class EdgePlacement : std::uint8_t { HalfCount, WholeCount };

// Channel levels of encoder state n (n may be negative).
[[nodiscard]] constexpr bool channel_a(std::int64_t n) { return ((n & 3) == 1) || ((n & 3) == 2); }
[[nodiscard]] constexpr bool channel_b(std::int64_t n) { return (n & 3) >= 2; }

struct QuadratureEncoder {
  std::uint32_t lines_per_turn = 1024;
  // Profile position units per shaft turn: 1 when the profile is in turns, or
  // counts_per_turn() when the profile is already in counts.
  double units_per_turn = 1.0;
  // Direction: false = A leads B for increasing position; true = B leads A.
  bool reversed = false;
  EdgePlacement placement = EdgePlacement::HalfCount;
  // Index Z: high while (count - index_count) mod counts_per_turn < index_width.
  // index_width 0 means no index channel.
  std::int64_t index_count = 0;
  std::int64_t index_width = 0;

  [[nodiscard]] std::int64_t counts_per_turn() const { return 4 * static_cast<std::int64_t>(lines_per_turn); }
  // Signed (negative when reversed).
  [[nodiscard]] double counts_per_unit() const;
  // Continuous count at a profile position; the encoder state there is count_at().
  [[nodiscard]] double counts(double position) const { return position * counts_per_unit(); }
  [[nodiscard]] std::int64_t count_at(double position) const; // of snapped_counts(position)
  // counts(position), an integer when it is within the tolerance of one (see the top).
  [[nodiscard]] double snapped_counts(double position) const { return snap_to_count(counts(position)); }
  // `c`, or the integer within 8 ulps of max(|magnitude|, |c|, 1) of it.
  [[nodiscard]] static double snap_to_count(double c, double magnitude = 0.0);
  // Where, in continuous counts, the edge from state n to n+1 sits, relative to n (0.5 or 1).
  [[nodiscard]] double edge_offset() const { return placement == EdgePlacement::HalfCount ? 0.5 : 1.0; }
  [[nodiscard]] bool index_high(std::int64_t count) const;
  // Z gated to A·B high on line `line`: one count wide, on the state where A = B = 1.
  void gate_index_to_line(std::int64_t line) {
    index_count = 4 * line + 2;
    index_width = 1;
  }
};

// One edge of one channel. For A and B, `count` is the encoder state after the edge; for
// Z it is the state the Z edge coincides with.
struct QuadEdge {
  Nanos time;
  std::int64_t count = 0;
  QuadChannel channel = QuadChannel::A;
  Level level = Level::Low; // after the edge
  friend bool operator==(const QuadEdge&, const QuadEdge&) = default;
};

} // namespace hilrig::signals
