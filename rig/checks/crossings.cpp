#include "rig/checks/crossings.hpp"

#include <algorithm>
#include <cmath>
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

// The setpoint's levels in [lo, hi]: the setpoint itself, or with a modulus every
// setpoint + k * modulus.
std::vector<double> levels_between(double setpoint, double modulus, double lo, double hi) {
  std::vector<double> out;
  if (modulus <= 0.0) {
    if (setpoint >= lo && setpoint <= hi) out.push_back(setpoint);
    return out;
  }
  // The levels are the setpoint's class modulo the modulus: start from its representative in
  // [0, modulus) (fmod is exact), so k stays small where the position is and k += 1 always
  // moves (a setpoint of 1e16 with a modulus of 1 left k at -1e16, where adding 1 changes
  // nothing, and the list grew without end).
  double base = std::fmod(setpoint, modulus);
  if (base < 0.0) base += modulus;
  for (double k = std::ceil((lo - base) / modulus); base + k * modulus <= hi; k += 1.0)
    out.push_back(base + k * modulus);
  return out;
}

} // namespace

std::vector<Nanos> find_crossings(const PositionFn& position, double setpoint, Nanos from, Nanos to,
                                  Nanos step, Direction direction, double modulus, const HeldFn& held) {
  if (step <= Nanos{0}) throw std::invalid_argument("find_crossings: step must be positive");
  std::vector<Nanos> out;
  const bool want_rising = direction != Direction::Falling;
  const bool want_falling = direction != Direction::Rising;
  Nanos a = from;
  double pa = position(a);
  bool unchanged = false; // the last step's two samples were equal: a standstill may have begun
  while (a < to) {
    if (held && unchanged) {
      // The grid's samples up to the end of the standstill all equal pa: the scan goes on from
      // the last of them (on the grid, not past `to`).
      unchanged = false;
      const Nanos still = std::min(held(a), to);
      if (still - a >= step) {
        a += step * ((still - a) / step);
        continue;
      }
    }
    const Nanos b = std::min(a + step, to);
    const double pb = position(b);
    for (const double level : levels_between(setpoint, modulus, std::min(pa, pb), std::max(pa, pb))) {
      if (want_rising && pa < level && pb >= level)
        out.push_back(first_true(a, b, [&](Nanos t) { return position(t) >= level; }));
      if (want_falling && pa > level && pb <= level)
        out.push_back(first_true(a, b, [&](Nanos t) { return position(t) <= level; }));
    }
    unchanged = pb == pa;
    a = b;
    pa = pb;
  }
  std::sort(out.begin(), out.end());
  return out;
}

} // namespace hilrig::checks
