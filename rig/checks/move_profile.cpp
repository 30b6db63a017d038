#include "rig/checks/move_profile.hpp"

#include <cmath>

namespace hilrig::checks {

std::vector<rig::RatePoint> expected_step_rate(const MoveProfile& p) {
  const double vs = p.starting_speed, vp = p.speed, a = p.accel, d = p.decel, n = p.steps;
  const auto at = [&](double seconds) { return p.start + Nanos{std::llround(seconds * 1e9)}; };
  if (vp <= vs) return {{p.start, vs}, {at(n / vs), vs}}; // no ramps: N / v_s at v_s
  // Steps to ramp between v_s and v: (v² - v_s²) / 2a up, / 2d down (constant acceleration).
  const double n_acc = (vp * vp - vs * vs) / (2.0 * a);
  const double n_dec = (vp * vp - vs * vs) / (2.0 * d);
  if (n_acc + n_dec <= n) { // trapezoid: it reaches v_p
    const double t_acc = (vp - vs) / a;
    const double t_cru = (n - n_acc - n_dec) / vp;
    std::vector<rig::RatePoint> knots{{p.start, vs}, {at(t_acc), vp}};
    if (t_cru > 0.0) knots.push_back({at(t_acc + t_cru), vp});
    knots.push_back({at(t_acc + t_cru + (vp - vs) / d), vs});
    return knots;
  }
  // Triangle: the peak v where the ramps' steps add up to N, (v² - v_s²)(1/2a + 1/2d) = N.
  const double peak = std::sqrt(vs * vs + 2.0 * n * a * d / (a + d));
  const double t_acc = (peak - vs) / a;
  return {{p.start, vs}, {at(t_acc), peak}, {at(t_acc + (peak - vs) / d), vs}};
}

} // namespace hilrig::checks
