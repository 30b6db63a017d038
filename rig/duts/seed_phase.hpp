#pragma once
// A virtual board's power-up phase against rig time (where its free-running scan, update,
// frame or window clock starts): what a real board leaves to chance, drawn from the run's
// seed so that `--seed` and `repeat` meet the board at other phases.

#include <cstdint>

#include "core/time.hpp"

namespace hilrig::duts {

// In [0, period); 0 when period <= 0.
[[nodiscard]] inline Nanos phase_from_seed(std::uint64_t seed, Nanos period) {
  if (period <= Nanos::zero()) return Nanos::zero();
  return Nanos{static_cast<std::int64_t>(seed % static_cast<std::uint64_t>(period.count()))};
}

} // namespace hilrig::duts
