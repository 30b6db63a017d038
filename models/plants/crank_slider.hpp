#pragma once
// Crank-slider kinematics of a press: crank radius r, connecting rod l, crank angle theta
// from top dead centre. The wrist pin (the ram) sits s(theta) = r cos(theta) +
// sqrt(l^2 - r^2 sin^2(theta)) above the crank centre: s = r + l at TDC, l - r at BDC.

namespace hilrig::plants {

struct CrankSlider {
  double radius = 0.0; // m
  double rod = 0.0;    // m, > radius

  [[nodiscard]] double height(double theta) const;    // s, m
  [[nodiscard]] double d_height(double theta) const;  // ds/dtheta, m/rad
  [[nodiscard]] double d2_height(double theta) const; // d2s/dtheta2, m/rad^2
};

} // namespace hilrig::plants
