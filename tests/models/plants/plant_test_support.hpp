#pragma once
// Drives a plant to an instant exactly (advance stops at steps, breakpoints and events).

#include "models/plants/plant.hpp"

namespace hilrig::plants::testing {

inline Knot run_to(Plant& p, Nanos t) {
  Knot k = p.state();
  while (k.time < t) k = p.advance(t);
  return k;
}

// Runs until the first standstill (or `limit`), returns the plant's time then.
inline Nanos run_to_standstill(Plant& p, Nanos limit) {
  while (p.standstills().empty() && p.now() < limit) (void)p.advance(limit);
  return p.standstills().empty() ? Nanos::max() : p.standstills().front();
}

} // namespace hilrig::plants::testing
