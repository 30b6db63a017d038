#pragma once
// Which application of a brake line starts the stop a board times. A board that debounces its
// brake input drops a noisy application and times the next one: the ANS1 samples the input
// after each transition to "applied" and aborts a brake cycle the samples call noise (manual
// L1038-L1040), so a glitch before the real application starts no stop timer.

#include <cstddef>
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
  // The qualified application: its earliest transition (nullopt: none), and the latest one
  // a phase of the board's tick may see instead (a contact bounce); the board's own cycle
  // starts on its tick, in [applied, latest + 1 ms).
  std::optional<Nanos> applied{};
  Nanos latest{0};
  std::vector<Nanos> rejected{}; // the cycles dropped as noise (their earliest starts), in order
  // The board's tick phase decides whether (or which) application qualifies: nothing can be
  // timed for certain (applied is nullopt).
  bool depends_on_phase = false;
};

// `line`'s edges (times ascending), its level before the first of them, the level that
// applies the brake; transitions at or after `from`, samples no later than `end` (a cycle
// whose decision falls after the capture's end qualified nothing: it cannot be seen).
// Ans1: the board reads the input on its 1 ms tick, of unknown phase: a cycle starts at the
// first tick that sees the line applied after one that saw it released (t0); 16 samples on
// the ticks from t0 + 16 ms; the 8th at the released level aborts it (L1039); at t0 + 32 ms,
// fewer than 12 applied abort it (L1040). After an abort the next cycle starts at once when the
// line is applied then, else at the next tick that sees a transition. Every phase of the tick
// is tried (the outcome changes only where a tick meets an edge): where they agree on the
// application, applied..latest spans its starts (a contact bounce: different edges of one
// application, under 16 ms apart); where they do not, depends_on_phase.
[[nodiscard]] BrakeApplication brake_application(std::span<const Edge> line, Level before,
                                                 Level applied_level, Nanos from, Nanos end,
                                                 BrakeDebounce rule);

} // namespace hilrig::checks
