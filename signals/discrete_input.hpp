#pragma once
// Discrete inputs: a line's level over time as an initial level and a list of edges, built
// from level changes, pulses, pulse trains and contact bounce.

#include <cstddef>
#include <vector>

#include "core/line.hpp"
#include "core/time.hpp"
#include "signals/discrete_bounce.hpp"

namespace hilrig::signals {

class DiscreteSignal {
public:
  explicit DiscreteSignal(Level initial = Level::Low) : initial_(initial) {}

  // Changes the level at t (t must not precede the last edge); no edge if it is already
  // at that level.
  DiscreteSignal& set(Nanos t, Level level);
  // A pulse to `active` at t for `width`, back to the other level.
  DiscreteSignal& pulse(Nanos t, Nanos width, Level active = Level::High);
  // `count` pulses of `width` every `period`, the first at `start`.
  DiscreteSignal& pulse_train(Nanos start, Nanos period, Nanos width, std::size_t count,
                              Level active = Level::High);
  // A contact closing (or opening) to `target` at t with bounce (see ContactBounce); the
  // line must be at the other level before t.
  DiscreteSignal& bounce_to(Nanos t, Level target, const ContactBounce& bounce);

  [[nodiscard]] Level initial() const { return initial_; }
  [[nodiscard]] const std::vector<Edge>& edges() const { return edges_; }
  [[nodiscard]] Level level() const { return edges_.empty() ? initial_ : edges_.back().level; } // at the end
  // The level after every edge at or before t.
  [[nodiscard]] Level level_at(Nanos t) const;

private:
  Level initial_;
  std::vector<Edge> edges_;
};

} // namespace hilrig::signals
