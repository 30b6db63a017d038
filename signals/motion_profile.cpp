#include "signals/motion_profile.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace hilrig::signals {

namespace {
constexpr double kRestTolerance = 1e-9; // relative to the peak speed; see at_rest()

bool open_ended(const Segment& s) { return s.duration == Nanos::max(); }
} // namespace

Nanos Segment::end() const { return duration == Nanos::max() ? Nanos::max() : start + duration; }

double Segment::position_at(Nanos t) const {
  const double dt = (t - start).seconds();
  const double closed = position + (velocity + 0.5 * acceleration * dt) * dt;
  if (!settled_end) return closed;
  // The closed form rounds a few ulps past the target near the end; the move does not.
  return *settled_end >= position ? std::min(closed, *settled_end) : std::max(closed, *settled_end);
}

double Segment::velocity_at(Nanos t) const { return velocity + acceleration * (t - start).seconds(); }

double Segment::end_position() const { return settled_end.value_or(position_at(end())); }
double Segment::end_velocity() const { return velocity_at(end()); }

MotionProfile::MotionProfile(double start_position, Nanos start_time)
    : start_position_(start_position), start_time_(start_time) {}

void MotionProfile::restart(double start_position, Nanos start_time) {
  start_position_ = start_position;
  peak_speed_ = 0.0;
  start_time_ = start_time;
  segments_.clear();
}

MotionProfile& MotionProfile::accelerate(double acceleration, Nanos duration) {
  return append(Segment{end_time(), duration, end_position(), end_velocity(), acceleration});
}

MotionProfile& MotionProfile::cruise(Nanos duration) { return accelerate(0.0, duration); }

MotionProfile& MotionProfile::dwell(Nanos duration) {
  if (!at_rest()) throw std::logic_error("MotionProfile::dwell: the profile is still moving");
  return append(Segment{end_time(), duration, end_position(), 0.0, 0.0});
}

MotionProfile& MotionProfile::append(const Segment& s) {
  const Segment added = joined(segments_.empty() ? nullptr : &segments_.back(), s);
  note_speed(segments_.emplace_back(added));
  return *this;
}

MotionProfile MotionProfile::chained(double start_position, Nanos start_time,
                                     std::vector<Segment>&& segments) {
  MotionProfile p(start_position, start_time);
  p.segments_ = std::move(segments);
  for (std::size_t i = 0; i < p.segments_.size(); ++i) {
    p.segments_[i] = p.joined(i == 0 ? nullptr : &p.segments_[i - 1], p.segments_[i]);
    p.note_speed(p.segments_[i]);
  }
  return p;
}

Segment MotionProfile::joined(const Segment* last, const Segment& s) const {
  // Where and when the profile ends so far: end_time() and end_position(), the last segment
  // read once.
  Nanos end = start_time_;
  double p0 = start_position_;
  if (last != nullptr) {
    if (open_ended(*last)) throw std::logic_error("MotionProfile::append: the last segment is open-ended");
    end = last->start + last->duration;
    p0 = last->settled_end ? *last->settled_end : last->position_at(end);
  }
  if (s.start != end)
    throw std::invalid_argument("MotionProfile::append: segment does not start at the end time");
  if (s.duration <= Nanos::zero()) throw std::invalid_argument("MotionProfile::append: duration must be > 0");
  // Position must be continuous (velocity may step: an ideal shaft "already spinning").
  if (std::abs(s.position - p0) > 1e-9 * (1.0 + std::abs(p0)))
    throw std::invalid_argument("MotionProfile::append: position is not continuous");
  // Exact continuity, so edge solvers see no jump at the boundary; only settle() declares an end.
  return Segment{s.start, s.duration, p0, s.velocity, s.acceleration};
}

void MotionProfile::note_speed(const Segment& added) {
  peak_speed_ = std::max(peak_speed_, std::abs(added.velocity));
  if (!open_ended(added)) peak_speed_ = std::max(peak_speed_, std::abs(added.end_velocity()));
}

MotionProfile& MotionProfile::settle(double from, double distance) {
  if (segments_.empty() || open_ended(segments_.back()))
    throw std::logic_error("MotionProfile::settle: no finite segment to settle");
  Segment& last = segments_.back();
  const double position = from + distance;
  const double reached = last.position_at(last.end());
  if (std::abs(position - reached) > 1e-9 * (1.0 + std::abs(position)))
    throw std::invalid_argument("MotionProfile::settle: the segment does not end there");
  // Velocity is linear in a segment: it keeps its sign when both ends share it (or one is 0).
  if (last.velocity * last.end_velocity() < 0.0)
    throw std::invalid_argument("MotionProfile::settle: the segment reverses before its end");
  last.settled_end = position;
  last.settled_from = from;
  last.settled_distance = distance;
  return *this;
}

Nanos MotionProfile::start_time() const { return segments_.empty() ? start_time_ : segments_.front().start; }

Nanos MotionProfile::end_time() const { return segments_.empty() ? start_time_ : segments_.back().end(); }

double MotionProfile::end_position() const {
  return segments_.empty() ? start_position_ : segments_.back().end_position();
}

double MotionProfile::end_velocity() const {
  return segments_.empty() ? 0.0 : segments_.back().end_velocity();
}

bool MotionProfile::at_rest() const {
  return std::abs(end_velocity()) <= kRestTolerance * std::max(1.0, peak_speed_);
}

std::size_t MotionProfile::segment_index(Nanos t) const {
  if (segments_.empty()) return 0;
  const auto it = std::upper_bound(segments_.begin(), segments_.end(), t,
                                   [](Nanos time, const Segment& s) { return time < s.start; });
  if (it == segments_.begin()) return 0;
  return static_cast<std::size_t>(it - segments_.begin()) - 1;
}

// The last segment starting at or before t, as the binary search finds it: starts never
// decrease, so segment i is it when it starts at or before t and the next starts after t.
std::size_t MotionProfile::segment_index(Nanos t, std::size_t& hint) const {
  const auto holds = [&](std::size_t i) {
    return i < segments_.size() && segments_[i].start <= t &&
           (i + 1 == segments_.size() || t < segments_[i + 1].start);
  };
  if (!holds(hint)) hint = holds(hint + 1) ? hint + 1 : segment_index(t);
  return hint;
}

// Outside the profile the shaft stands still: before the start at the start position,
// after the end at the end position (unless the last segment runs forever).
double MotionProfile::position(Nanos t, std::size_t& hint) const {
  if (segments_.empty() || t < start_time()) return start_position_;
  const Segment& s = segments_[segment_index(t, hint)];
  if (t >= s.end()) return s.end_position();
  return s.position_at(t);
}

double MotionProfile::velocity(Nanos t, std::size_t& hint) const {
  if (segments_.empty() || t < start_time()) return 0.0;
  const Segment& s = segments_[segment_index(t, hint)];
  if (t >= s.end()) return 0.0;
  return s.velocity_at(t);
}

// A dwell's closed form is its start position exactly (p + (0 + 0.5 * 0 * dt) * dt == p), so a
// run of dwells at one position, the start held and the end held are each one value.
Nanos MotionProfile::held_until(Nanos t, std::size_t& hint) const {
  if (segments_.empty()) return Nanos::max();
  const Segment& last = segments_.back();
  if (last.duration != Nanos::max() && t >= last.end()) return Nanos::max();
  Nanos held = t;
  double p = start_position_;
  std::size_t i = 0;
  if (t < start_time()) {
    held = start_time() - Nanos{1};
  } else {
    i = segment_index(t, hint);
    p = segments_[i].position;
  }
  for (; i < segments_.size(); ++i) {
    const Segment& s = segments_[i];
    if (s.velocity != 0.0 || s.acceleration != 0.0 || s.position != p) return held;
    if (s.duration == Nanos::max()) return Nanos::max();
    held = s.end() - Nanos{1};
  }
  return last.end_position() == p ? Nanos::max() : held;
}

double MotionProfile::position(Nanos t) const {
  std::size_t hint = 0;
  return position(t, hint);
}

double MotionProfile::velocity(Nanos t) const {
  std::size_t hint = 0;
  return velocity(t, hint);
}

double MotionProfile::acceleration(Nanos t) const {
  if (segments_.empty() || t < start_time()) return 0.0;
  const Segment& s = segments_[segment_index(t)];
  if (t >= s.end()) return 0.0;
  return s.acceleration;
}

} // namespace hilrig::signals
