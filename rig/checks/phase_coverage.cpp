#include "rig/checks/phase_coverage.hpp"

#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include <fmt/format.h>

namespace hilrig::checks {

PhaseCoverage phase_coverage(std::span<const Nanos> crossings, Nanos period, std::size_t bins) {
  if (period <= Nanos::zero() || bins == 0)
    throw std::invalid_argument("phase_coverage: period and bins must be > 0");
  std::vector<bool> hit(bins, false);
  const std::int64_t p = period.count();
  for (const Nanos c : crossings) {
    std::int64_t phase = c.count() % p;
    if (phase < 0) phase += p;
    // Integer bin edges: bin k holds phases in [k·p/bins, (k+1)·p/bins). (phase·bins stays
    // far inside 64 bits for any scan period and bin count a campaign can name.)
    const auto bin = static_cast<std::size_t>(phase * static_cast<std::int64_t>(bins) / p);
    hit[bin] = true;
  }
  PhaseCoverage out;
  out.bins = bins;
  for (const bool h : hit) out.covered += h ? 1 : 0;
  return out;
}

std::string PhaseCoverage::describe(Nanos period) const {
  const std::string base = fmt::format("{}/{} bins of the {} us period covered", covered, bins,
                                       static_cast<double>(period.count()) / 1e3);
  if (complete()) return base;
  return base + ": coverage incomplete, the worst-case phase may not have been reached";
}

Measurement phase_coverage_measurement(std::string name, std::span<const Nanos> crossings, Nanos period,
                                       std::size_t bins) {
  if (period <= Nanos::zero() || bins == 0)
    return error(std::move(name), "phase coverage needs scan_us > 0 and phase_bins >= 1");
  const PhaseCoverage cov = phase_coverage(crossings, period, bins);
  return measure(std::move(name), static_cast<double>(cov.covered), "bins", std::nullopt, std::nullopt,
                 cov.describe(period));
}

} // namespace hilrig::checks
