#include "models/plants/crank_slider.hpp"

#include <cmath>

namespace hilrig::plants {

namespace {
double root(const CrankSlider& k, double sn) {
  return std::sqrt(k.rod * k.rod - k.radius * k.radius * sn * sn);
}
} // namespace

double CrankSlider::height(double theta) const {
  return radius * std::cos(theta) + root(*this, std::sin(theta));
}

double CrankSlider::d_height(double theta) const {
  const double sn = std::sin(theta);
  const double cs = std::cos(theta);
  return -radius * sn - radius * radius * sn * cs / root(*this, sn);
}

double CrankSlider::d2_height(double theta) const {
  const double sn = std::sin(theta);
  const double cs = std::cos(theta);
  const double q = root(*this, sn);
  const double r2 = radius * radius;
  return -radius * cs - r2 * (cs * cs - sn * sn) / q - r2 * r2 * sn * sn * cs * cs / (q * q * q);
}

} // namespace hilrig::plants
