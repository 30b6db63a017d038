#pragma once
// Where a brake stop ends: the instant the shaft stands still, exact when the rig knows the
// trajectory (virtual time: the motion profile), otherwise an interval read from the count
// changes (a hardware run), which a stop-time check judges on its upper end.

#include <optional>
#include <span>

#include "core/time.hpp"
#include "rig/checks/brake.hpp"

namespace hilrig::checks {

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
