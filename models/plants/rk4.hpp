#pragma once
// Fixed-step classical Runge-Kutta (order 4) and event location on the nanosecond grid.
// RK4 is exact for motion whose state is a polynomial of degree <= 4 in time (a constant
// torque), and its local error is O(h^5) otherwise; steps never straddle a breakpoint, so
// the right-hand side is smooth inside each step.

#include <cstdint>
#include <optional>

namespace hilrig::plants {

// One RK4 step of dx/dt = f(t, x) from (t, x) over h seconds.
template <class Vec, class F> [[nodiscard]] Vec rk4_step(const F& f, double t, const Vec& x, double h) {
  const Vec k1 = f(t, x);
  const Vec k2 = f(t + h / 2.0, Vec(x + (h / 2.0) * k1));
  const Vec k3 = f(t + h / 2.0, Vec(x + (h / 2.0) * k2));
  const Vec k4 = f(t + h, Vec(x + h * k3));
  return x + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

// The first nanosecond of a step at which an event function has fallen to <= 0, by
// bisection on whole nanoseconds: g(0) > 0 is known, and g(step_ns) <= 0 has been seen.
// g_at(n) evaluates the event function on the state integrated n ns from the step's start
// (one sub-step from the same start, so the bracket is the integrator's own trajectory).
// The event lies in (result - 1 ns, result]: located to within one nanosecond.
template <class G> [[nodiscard]] std::int64_t locate_event(const G& g_at, std::int64_t step_ns) {
  std::int64_t lo = 0;
  std::int64_t hi = step_ns;
  while (hi - lo > 1) {
    const std::int64_t mid = lo + (hi - lo) / 2;
    if (g_at(mid) <= 0.0)
      hi = mid;
    else
      lo = mid;
  }
  return hi;
}

// The speed below which a decelerating shaft counts as stopped, for a motion whose fastest
// speed since it last stood was `scale` rad/s: within rounding of zero, so a stop that
// falls exactly on a nanosecond is located on it rather than one after.
[[nodiscard]] double speed_floor(double scale);

} // namespace hilrig::plants
