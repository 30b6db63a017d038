#pragma once
// Debounce: pulses shorter than the input filter are rejected and longer ones accepted. The
// boundary is found by bisection over repeated runs: the executive gives a callable that
// plays one pulse of a given width in a fresh virtual run and says whether the board took it.
//
// A scanning board sees a pulse's start up to one scan late, so its boundary depends on
// where in its scan the pulse starts: the executive bisects at several start phases spread
// over the scan, and the limit holds at every phase (docs/campaigns.md, "Debounce").

#include <functional>
#include <span>
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
  bool bracketed = false;              // a probe was rejected and a wider one accepted
  Nanos rejected{0};                   // the widest width seen rejected (below the boundary)
  Nanos accepted{0};                   // the narrowest width seen accepted (the boundary, to resolution)
  std::vector<DebounceProbe> probes{}; // in the order they were run
};

using PulseProbe = std::function<bool(Nanos width)>;

// Probes the `first` widths in order (the spec's limits: they decide the verdict exactly,
// whatever the resolution), then `narrow` unless a probe was rejected and `wide` unless one
// was accepted, then halves the bracket until accepted - rejected <= resolution. Each call of
// `accepted` is one run. With no `first`: narrow, wide, then about
// log2((wide-narrow)/resolution) halvings.
[[nodiscard]] Bisection bisect_boundary(const PulseProbe& accepted, Nanos narrow, Nanos wide,
                                        Nanos resolution, std::span<const Nanos> first = {});

// One bisection per pulse start: `start` is the rig time the probe pulses began.
struct PhaseBisection {
  Nanos start{0};
  Bisection bisection;
};

struct DebounceSpec {
  std::string name = "debounce";
  Nanos filter{0};    // the spec's filter time
  Nanos tolerance{0}; // the boundary must lie in [filter - tolerance, filter + tolerance]
  // The widths whose verdict decides the check exactly: filter - tolerance - 1 ns must be
  // rejected (a hair short of the narrowest allowed boundary) and filter + tolerance accepted.
  [[nodiscard]] Nanos shortest_rejected() const { return filter - tolerance - Nanos{1}; }
  [[nodiscard]] Nanos longest_accepted() const { return filter + tolerance; }
};

// Measurements, over every start phase (the limit holds at each):
// "<name>.boundary" (the phase boundary farthest from the filter, us, within filter ±
// tolerance; an unbracketed phase fails it with the reason), "<name>.misjudged" (probes at
// any phase narrower than filter - tolerance accepted, or of filter + tolerance or wider
// rejected; upper 0), "<name>.resolution" (the widest final bracket, us).
[[nodiscard]] CheckResult check_debounce(std::span<const PhaseBisection> phases, const DebounceSpec& spec);
// One start phase.
[[nodiscard]] CheckResult check_debounce(const Bisection& bisection, const DebounceSpec& spec);

} // namespace hilrig::checks
