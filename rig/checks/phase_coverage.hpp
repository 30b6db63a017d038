#pragma once
// Phase coverage of a latency check: where the stimulus crossings fell within the board's
// scan (or clock) period, in bins. A board that scans every T sees a crossing up to T late,
// and its worst-case latency only shows when some crossing falls just after a scan: a check
// whose crossings leave bins empty may never have met the worst case.
//
// The phase of a crossing is its rig time modulo the period (the board's own phase is its
// unknown power-up offset, so a full coverage in rig time is a full coverage against the
// board, to one bin).

#include <cstddef>
#include <span>
#include <string>

#include "core/time.hpp"
#include "rig/checks/support.hpp"

namespace hilrig::checks {

struct PhaseCoverage {
  std::size_t covered = 0; // bins holding at least one crossing
  std::size_t bins = 0;
  [[nodiscard]] bool complete() const { return bins > 0 && covered == bins; }
  // "7/10 bins of the 10 us period covered" (with why it matters when incomplete).
  [[nodiscard]] std::string describe(Nanos period) const;
};

// bins >= 1 and period > 0 (throws std::invalid_argument otherwise).
[[nodiscard]] PhaseCoverage phase_coverage(std::span<const Nanos> crossings, Nanos period, std::size_t bins);

// The coverage as a measurement for results.json ("<check>.phase_coverage", unit "bins",
// value the bins covered, out of `bins`): informational, no limit; its detail says when the
// coverage is incomplete, and the report shows it.
[[nodiscard]] Measurement phase_coverage_measurement(std::string name, std::span<const Nanos> crossings,
                                                     Nanos period, std::size_t bins);

} // namespace hilrig::checks
