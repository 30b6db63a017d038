#include "rig/checks/crossings.hpp"

#include <algorithm>
#include <stdexcept>

namespace hilrig::checks {
namespace {

// Smallest t in (a, b] with pred(t) true, given pred(a) false and pred(b) true.
template <class Pred> Nanos first_true(Nanos a, Nanos b, Pred pred) {
  while (b - a > Nanos{1}) {
    const Nanos mid = a + (b - a) / 2;
    if (pred(mid)) {
      b = mid;
    } else {
      a = mid;
    }
  }
  return b;
}

} // namespace

std::vector<Nanos> find_crossings(const PositionFn& position, double setpoint, Nanos from, Nanos to,
                                  Nanos step, Direction direction) {
  if (step <= Nanos{0}) throw std::invalid_argument("find_crossings: step must be positive");
  std::vector<Nanos> out;
  const auto at_or_above = [&](Nanos t) { return position(t) >= setpoint; };
  const auto at_or_below = [&](Nanos t) { return position(t) <= setpoint; };
  Nanos a = from;
  double pa = position(a);
  while (a < to) {
    const Nanos b = std::min(a + step, to);
    const double pb = position(b);
    const bool want_rising = direction != Direction::Falling;
    const bool want_falling = direction != Direction::Rising;
    if (want_rising && pa < setpoint && pb >= setpoint) out.push_back(first_true(a, b, at_or_above));
    if (want_falling && pa > setpoint && pb <= setpoint) out.push_back(first_true(a, b, at_or_below));
    a = b;
    pa = pb;
  }
  return out;
}

} // namespace hilrig::checks
