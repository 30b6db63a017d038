#pragma once
// Where a brake stop ends: the instant the shaft stands still, exact when the rig knows the
// trajectory (virtual time: the motion profile), otherwise an interval read from the count
// changes (a hardware run), which a stop-time check judges on its upper end.

#include <functional>
#include <optional>
#include <span>

#include "core/time.hpp"
#include "rig/checks/brake.hpp"

namespace hilrig::checks {

// A board that calls the shaft stopped from its counts: once the count changed by less than
// `counts` over the last `window` (ANS1 "Complete Stop Count" over 125 ms, L1042), and whose
// stop ends `window` before that instant (L1052: the 125 ms is subtracted).
struct StopCountRule {
  double counts = 1.0; // complete stop count: a change below it is standstill
  Nanos window{125'000'000};
};

// The standstill such a board sees, from the count (floor of `position`): the first instant t
// in [from, until] at which |count(t) - count(t - window)| < counts, less `window`; to 1 ns
// (scanned every 10 us, the change found there bisected). nullopt when none by `until`.
[[nodiscard]] std::optional<Nanos> stop_count_standstill(const std::function<double(Nanos)>& position,
                                                         const StopCountRule& rule, Nanos from, Nanos until);

// The rig's exact standstill (from the motion profile); nullopt when the shaft was still
// moving at trace_end (or never stops).
[[nodiscard]] std::optional<Standstill> exact_standstill(std::optional<Nanos> at, Nanos trace_end);

// From count changes only: [last change after `from`, last change + one count at the final
// speed bound]. A braking shaft only slows, so after its last change it is no faster than
// over its last count (one count in the time since the change before); at that speed it
// would change count again within that time, and after it (with no change) it has stopped.
// [from, from] when nothing changed after `from`. nullopt when the trace ends before the
// interval does, so it cannot prove the shaft stayed still.
[[nodiscard]] std::optional<Standstill> standstill_interval(std::span<const PositionSample> motion,
                                                            Nanos from, Nanos trace_end);

} // namespace hilrig::checks
