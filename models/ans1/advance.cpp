#include "models/ans1/advance.hpp"

#include <cmath>

namespace hilrig::models::ans1 {

AdvanceTimes advance_times(const OutputSetup& setup, double speed_rpm) {
  const double s = std::fabs(speed_rpm);
  switch (setup.advance_mode) {
  case AdvanceMode::Fixed:
    return {static_cast<double>(setup.lead_ms), static_cast<double>(setup.trail_ms)};
  case AdvanceMode::Variable: {
    const double fixed = setup.lead_ms;
    return {fixed + (s / 2.0) * (static_cast<double>(setup.variable_us_per_rpm) / 1000.0), fixed};
  }
  case AdvanceMode::None:
    break;
  }
  return {};
}

namespace {

std::int32_t to_counts(double t_ms, double abs_speed, std::uint16_t fsc, double scale, bool& clamped) {
  const double ms_times_rpm = t_ms * abs_speed;
  if (ms_times_rpm > 60000.0) { // longer than one cycle: 60000 / |S| ms
    clamped = true;
    return fsc - 1;
  }
  // Up to exactly one cycle (FSC counts) the advance is not clamped (L2313) and DA19 shows
  // it as it is (L2621, L2622); only the AdvanceWrongScale variant's scale can go beyond.
  const double counts = std::round(ms_times_rpm * fsc / 60000.0 * scale);
  if (counts > fsc) {
    return fsc;
  }
  return static_cast<std::int32_t>(counts);
}

} // namespace

AdvanceCounts advance_counts(const OutputSetup& setup, double speed_rpm, std::uint16_t fsc, double scale) {
  AdvanceCounts a;
  if (setup.advance_mode == AdvanceMode::None) {
    return a;
  }
  const AdvanceTimes t = advance_times(setup, speed_rpm);
  const double s = std::fabs(speed_rpm);
  a.lead = to_counts(t.lead_ms, s, fsc, scale, a.clamped);
  a.trail = to_counts(t.trail_ms, s, fsc, scale, a.clamped);
  return a;
}

} // namespace hilrig::models::ans1
