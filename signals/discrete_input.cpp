#include "signals/discrete_input.hpp"

#include <algorithm>
#include <iterator>
#include <stdexcept>

namespace hilrig::signals {

DiscreteSignal& DiscreteSignal::set(Nanos t, Level level) {
  if (!edges_.empty() && t < edges_.back().time)
    throw std::invalid_argument("DiscreteSignal::set: edges must be added in time order");
  if (level == this->level()) return *this;
  if (!edges_.empty() && edges_.back().time == t) { // two changes at one instant cancel
    edges_.pop_back();
    return *this;
  }
  edges_.push_back(Edge{t, level});
  return *this;
}

DiscreteSignal& DiscreteSignal::pulse(Nanos t, Nanos width, Level active) {
  if (width <= Nanos::zero()) throw std::invalid_argument("DiscreteSignal::pulse: width must be > 0");
  set(t, active);
  return set(t + width, !active);
}

DiscreteSignal& DiscreteSignal::pulse_train(Nanos start, Nanos period, Nanos width, std::size_t count,
                                            Level active) {
  if (width >= period) throw std::invalid_argument("DiscreteSignal::pulse_train: width must be < period");
  for (std::size_t i = 0; i < count; ++i) pulse(start + period * static_cast<std::int64_t>(i), width, active);
  return *this;
}

DiscreteSignal& DiscreteSignal::bounce_to(Nanos t, Level target, const ContactBounce& bounce) {
  if (level() == target)
    throw std::logic_error("DiscreteSignal::bounce_to: the line is already at the target");
  for (const Edge& e : bounce_edges(t, target, bounce)) set(e.time, e.level);
  return *this;
}

Level DiscreteSignal::level_at(Nanos t) const {
  const auto it = std::upper_bound(edges_.begin(), edges_.end(), t,
                                   [](Nanos time, const Edge& e) { return time < e.time; });
  return it == edges_.begin() ? initial_ : std::prev(it)->level;
}

} // namespace hilrig::signals
