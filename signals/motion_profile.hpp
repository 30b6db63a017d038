#pragma once
// A motion profile is a queue of constant-acceleration segments, as in Klipper's trapq:
// each move is a start time, a duration, a start position and velocity, and an
// acceleration. Position, velocity and acceleration at any time come in closed form.
// Units: position in "counts" of the caller's choosing (usually turns or encoder counts
// — the profile does not care), time in Nanos, velocity per second, acceleration per s².

#include <cstddef>
#include <optional>
#include <vector>

#include "core/time.hpp"

namespace hilrig::signals {

struct Segment {
  Nanos start;         // absolute start time
  Nanos duration;      // > 0, or Nanos::max() for "forever" (last segment only)
  double position;     // at start
  double velocity;     // at start, units/s
  double acceleration; // units/s², constant through the segment
  // The end position a move builder aimed at, when it settled the segment there (see
  // MotionProfile::settle): the closed form lands within a few ulps of it, and a count
  // boundary must not fall into that gap. settled_from + settled_distance is the move's
  // start and signed distance as the builder was given them, so that an edge solver can add
  // them in its own unit (counts) instead of converting their rounded sum.
  std::optional<double> settled_end = std::nullopt;
  double settled_from = 0.0;
  double settled_distance = 0.0;

  [[nodiscard]] Nanos end() const;
  // t measured absolutely. A settled segment never passes its settled end: the closed form
  // of a chain of steps may land a few ulps beyond it, and a move never overshoots.
  [[nodiscard]] double position_at(Nanos t) const;
  [[nodiscard]] double velocity_at(Nanos t) const;
  [[nodiscard]] double end_position() const;
  [[nodiscard]] double end_velocity() const;
};

class MotionProfile {
public:
  MotionProfile() = default;
  explicit MotionProfile(double start_position, Nanos start_time = Nanos{0});
  // Becomes MotionProfile(start_position, start_time), keeping the segments' storage (a plan
  // redone at every input appends without reallocating).
  void restart(double start_position, Nanos start_time);
  // Room for n segments in all, so that appending up to them does not reallocate.
  void reserve(std::size_t n) { segments_.reserve(n); }

  // Appends a segment that starts where and when the last one ended (continuous position
  // and velocity).
  MotionProfile& accelerate(double acceleration, Nanos duration);
  MotionProfile& cruise(Nanos duration); // constant velocity (acceleration 0)
  MotionProfile& dwell(Nanos duration);  // velocity must be 0 (throws otherwise)
  // Appends an arbitrary segment; its start must equal the current end time.
  MotionProfile& append(const Segment& s);
  // MotionProfile(start_position, start_time) with each of `segments` appended in order (the
  // same checks, positions and peak speed), in the vector's own storage: a long trajectory
  // is not copied to a second block of memory.
  [[nodiscard]] static MotionProfile chained(double start_position, Nanos start_time,
                                             std::vector<Segment>&& segments);
  // Declares that the last segment ends exactly at from + distance, the target of a move
  // that started at `from` (within the closed form's rounding, a relative 1e-9; throws
  // otherwise): a move to count 2000 then ends on 2000, not on 1999.9999999999998, and the
  // next segment starts there. The segment must not reverse (its velocity keeps one sign or
  // reaches 0; throws otherwise): a settled segment is one monotonic approach to its end.
  MotionProfile& settle(double from, double distance);

  [[nodiscard]] const std::vector<Segment>& segments() const { return segments_; }
  [[nodiscard]] Nanos start_time() const;
  [[nodiscard]] Nanos end_time() const;
  [[nodiscard]] double end_position() const;
  [[nodiscard]] double end_velocity() const;

  // Closed form at any time; before the start: the start position held (velocity and
  // acceleration 0); after the end: the last segment's end position held (velocity 0)
  // unless the last segment is open-ended.
  [[nodiscard]] double position(Nanos t) const;
  [[nodiscard]] double velocity(Nanos t) const;
  [[nodiscard]] double acceleration(Nanos t) const;
  // The segment index containing t (binary search).
  [[nodiscard]] std::size_t segment_index(Nanos t) const;
  // The same values, the segment looked for first at `hint` and the one after it (then by
  // binary search), and `hint` set to the segment found: a reader asking at nearby times (a
  // check's scan and its bisections, over a plant's thousands of segments) finds it in a
  // comparison or two. Any hint gives the same result.
  [[nodiscard]] double position(Nanos t, std::size_t& hint) const;
  [[nodiscard]] double velocity(Nanos t, std::size_t& hint) const;
  [[nodiscard]] std::size_t segment_index(Nanos t, std::size_t& hint) const;
  // The last instant through which position() stays exactly position(t): the end of the
  // standstill t is in (dwells at one position, the start held before the first segment, the
  // end held after the last), Nanos::max() when it lasts for good, t itself when the shaft
  // moves. A reader sampling the position on a grid steps over a standstill in one go.
  [[nodiscard]] Nanos held_until(Nanos t, std::size_t& hint) const;

  // True when the profile ends at rest: |end velocity| within a relative 1e-9 of the
  // fastest speed seen (builders round durations to the nanosecond, so a stop leaves a
  // residue of a few ulps rather than an exact 0).
  [[nodiscard]] bool at_rest() const;
  // The largest |velocity| reached so far (velocity is linear in a segment, so at an end).
  [[nodiscard]] double peak_speed() const { return peak_speed_; }

private:
  // `s` as append() stores it after the segment `last` (null: the first), or throws.
  [[nodiscard]] Segment joined(const Segment* last, const Segment& s) const;
  void note_speed(const Segment& added);

  double start_position_ = 0.0;
  double peak_speed_ = 0.0;
  Nanos start_time_{0};
  std::vector<Segment> segments_;
};

} // namespace hilrig::signals
