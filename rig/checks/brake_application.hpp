#pragma once
// Which application of a brake line starts the stop a board times. A board that debounces its
// brake input drops a noisy application and times the next one: the ANS1 samples the input
// after each transition to "applied" and aborts a brake cycle the samples call noise (manual
// L1038-L1040), so a glitch before the real application starts no stop timer.

#include <optional>
#include <span>
#include <vector>

#include "core/line.hpp"
#include "core/time.hpp"

namespace hilrig::checks {

enum class BrakeDebounce {
  None, // the first transition to the applied level is the application
  Ans1, // the first the ANS1 qualifies (L1038-L1040; digest A9: 8 released samples cumulative,
        // a restart re-times the cycle to the restart instant)
};

struct BrakeApplication {
  std::optional<Nanos> applied{}; // nullopt: no application qualified within [from, end]
  std::vector<Nanos> rejected{};  // the starts of the cycles dropped as noise, in order
};

// `line`'s edges (times ascending), its level before the first of them, the level that
// applies the brake; transitions at or after `from`, samples no later than `end` (a cycle
// whose decision falls after the capture's end qualified nothing: it cannot be seen).
// Ans1: a cycle starts at a transition to `applied_level` (t0); 16 samples 1 ms apart from
// t0 + 16 ms; the 8th sample at the released level aborts it (L1039); at t0 + 32 ms, fewer
// than 12 samples at the applied level abort it (L1040). After an abort the next cycle starts
// at once when the line is applied then, else at its next transition to applied.
[[nodiscard]] BrakeApplication brake_application(std::span<const Edge> line, Level before,
                                                 Level applied_level, Nanos from, Nanos end,
                                                 BrakeDebounce rule);

} // namespace hilrig::checks
