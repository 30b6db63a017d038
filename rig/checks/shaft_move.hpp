#pragma once
// Shaft move checks for a stepper observed from the outside: a step line with one edge
// (either level) per step and a direction line (High = CW). Within a window the check
// measures the net distance (CW +), the time from the window's start to the last step (a
// move's duration from its command, a stop's duration from its trigger; 0 with no step),
// the peak speed (1 / the shortest interval between two steps in the same direction) and
// the direction reversals, each against limits worked out from the spec.
//
// A move the window's end or the run's end cuts is not judged (an error, "nothing judged"),
// unless what was seen is already beyond a limit. The shaft's step interval is its longest
// between two steps in one direction in the window (a turn is a stop; one step: from the
// step before it), and with a profile at least 1 / Starting Speed (the slowest a profile
// runs, seeds/003 L863, L1350). After its last step in the window, a next step within one
// interval is the same move still running when the window ended; the shaft still for more
// than twice the interval has ended its move;
// anything else (a ramp's last, longer intervals; the run ending first) leaves the end
// unknown. Then .duration fails if the move already lasted longer than duration_max (to its
// next step, or its last seen), .peak_speed if a step interval already beat peak_max,
// .reversals if there were already more; otherwise each is an error. .steps counts the window
// when to_ms closes it (a stretch of a jog: a count in a window is whole); when the run's end
// closes it, it is the move's distance: an error while the move may go on, unless the count
// is already past the band on the side the shaft was heading.

#include <optional>
#include <span>
#include <string>

#include "rig/checks/move_profile.hpp"
#include "rig/checks/support.hpp"

namespace hilrig::checks {

struct ShaftMoveSpec {
  std::string name = "shaft";
  Nanos from{0};           // steps strictly after this count
  Nanos to = Nanos::max(); // ... and at or before this
  bool to_given = false;   // the campaign closed the window (to_ms): .steps counts the window
  Level dir_initial = Level::Low;
  std::optional<double> steps{};       // expected net steps (CW +)
  double steps_tolerance = 0.0;        // either side
  std::optional<Nanos> duration_min{}; // from `from` to the last step, judged in ns
  std::optional<Nanos> duration_max{};
  std::optional<double> peak_min{}; // steps/s
  std::optional<double> peak_max{};
  std::optional<double> reversals{}; // exact count of direction changes
  // The move the steps are expected to follow (profile_of): its step rate goes into the
  // result as evidence (CheckResult::expected_rate). It judges nothing: the manual gives no
  // tolerance on the rate along a profile, only the profile (docs/spec/smd23e.md §3.2).
  std::optional<MoveProfile> profile{};
};

// Each expectation given in the spec becomes one measurement <name>.steps, .duration,
// .peak_speed, .reversals; with a profile, its expected step rate rides along.
// `end`: the capture's end (none: the capture holds everything after the window).
[[nodiscard]] CheckResult check_shaft_move(std::span<const Edge> step, std::span<const Edge> dir,
                                           const ShaftMoveSpec& spec,
                                           std::optional<Nanos> end = std::nullopt);

} // namespace hilrig::checks
