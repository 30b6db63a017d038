#pragma once
// Quadrature edges solved from a motion profile in counts, as Klipper's itersolve does:
// the time of each count change comes from the segment's quadratic, never from sampling.
// The count is floor(position); each change of it is one edge on A or B (X4), in the
// order 00 -> 10 -> 11 -> 01 going forward (A leads B).

#include <cstddef>
#include <cstdint>
#include <optional>

#include "core/line.hpp"
#include "signals/motion_profile.hpp"

namespace hilrig::campaign {

struct CountEdge {
  Nanos time;
  std::int64_t count; // the count after the edge
  bool on_a;          // the edge is on A (else on B)
  Level level;        // the changed line's new level
};

// Channel levels for a count (X4 state count mod 4).
[[nodiscard]] Level a_level(std::int64_t count);
[[nodiscard]] Level b_level(std::int64_t count);

// Walks the profile's edges in time order, one at a time (no schedule held in memory).
class QuadratureEdges {
public:
  explicit QuadratureEdges(const signals::MotionProfile& profile);

  [[nodiscard]] std::int64_t start_count() const { return start_count_; }
  [[nodiscard]] std::optional<CountEdge> next();

private:
  // Opens the next monotonic piece; false when the profile is done.
  bool open_piece();

  const signals::MotionProfile& profile_;
  std::int64_t start_count_ = 0;
  std::int64_t count_ = 0;
  std::size_t segment_ = 0;
  const signals::Segment* current_ = nullptr;
  // The current monotonic piece of segment_, in seconds from the segment's start.
  double tau_ = 0.0;       // cursor: the last edge (or the piece start)
  double piece_end_ = 0.0; // end of the piece
  int direction_ = 0;      // +1, -1, 0 (not moving)
  bool piece_open_ = false;
  bool second_piece_ = false; // the piece after a turning point inside the segment
  Nanos last_{Nanos::min()};
};

} // namespace hilrig::campaign
