#pragma once
// Speed-compensated advances (spec §4.6): an advance time becomes a count of positions the
// edge fires early, recomputed at every speed update (L884).
#include <cstdint>

#include "models/ans1/output_setup.hpp"

namespace hilrig::models::ans1 {

struct AdvanceTimes {
  double lead_ms = 0.0;  // the From edge
  double trail_ms = 0.0; // the To edge
  friend bool operator==(const AdvanceTimes&, const AdvanceTimes&) = default;
};

// fixed: lead = Lead, trail = Trail. variable: lead = Fixed + (|S| / 2) * VAT / 1000
// (taken literally from L917, A12), trail = Fixed.
[[nodiscard]] AdvanceTimes advance_times(const OutputSetup& setup, double speed_rpm);

struct AdvanceCounts {
  std::int32_t lead = 0;  // counts, always >= 0 (DA19 w9)
  std::int32_t trail = 0; // (DA19 w10)
  bool clamped = false;   // an advance is longer than one machine cycle (status bit 7)
  friend bool operator==(const AdvanceCounts&, const AdvanceCounts&) = default;
};

// a = t[ms] * |S| * FSC / 60000, rounded to the nearest count ([MODEL]), at most FSC (one
// cycle); an advance longer than one cycle (t * |S| > 60000) is clamped to FSC - 1 counts
// ([MODEL]). `scale` multiplies
// the result (1 for the correct model; the AdvanceWrongScale variant uses 2).
[[nodiscard]] AdvanceCounts advance_counts(const OutputSetup& setup, double speed_rpm, std::uint16_t fsc,
                                           double scale = 1.0);

// Conversion from "degrees per 100 RPM" (L900): t[ms] = deg / 600 * 1000.
[[nodiscard]] constexpr double advance_ms_from_degrees_per_100rpm(double degrees) {
  return degrees / 600.0 * 1000.0;
}

} // namespace hilrig::models::ans1
