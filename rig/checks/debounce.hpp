#pragma once
// Debounce: pulses shorter than the input filter are rejected and longer ones accepted. The
// boundary is found by bisection over repeated runs: the executive gives a callable that
// plays one pulse of a given width in a fresh virtual run and says whether the board took it.

#include <functional>
#include <string>
#include <vector>

#include "core/time.hpp"
#include "rig/checks/support.hpp"

namespace hilrig::checks {

struct DebounceProbe {
  Nanos width;
  bool accepted;
};

struct Bisection {
  bool bracketed = false;              // the narrowest probe was rejected and the widest accepted
  Nanos rejected{0};                   // the widest width seen rejected (below the boundary)
  Nanos accepted{0};                   // the narrowest width seen accepted (the boundary, to resolution)
  std::vector<DebounceProbe> probes{}; // in the order they were run
};

using PulseProbe = std::function<bool(Nanos width)>;

// Probes `narrow` and `wide` first, then halves the bracket until accepted - rejected <=
// resolution. Each call of `accepted` is one run. About log2((wide-narrow)/resolution) + 2 runs.
[[nodiscard]] Bisection bisect_boundary(const PulseProbe& accepted, Nanos narrow, Nanos wide,
                                        Nanos resolution);

struct DebounceSpec {
  std::string name = "debounce";
  Nanos filter{0};    // the spec's filter time
  Nanos tolerance{0}; // the boundary must lie in [filter - tolerance, filter + tolerance]
};

// Measurements: "<name>.boundary" (narrowest accepted width, us, within filter ± tolerance),
// "<name>.misjudged" (probes narrower than filter - tolerance accepted, or wider than
// filter + tolerance rejected; upper 0), "<name>.resolution" (accepted - rejected, us).
// An unbracketed bisection fails "<name>.boundary" with the reason.
[[nodiscard]] CheckResult check_debounce(const Bisection& bisection, const DebounceSpec& spec);

} // namespace hilrig::checks
