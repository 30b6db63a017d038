#pragma once
// Shaft move checks for a stepper observed from the outside: a step line with one edge
// (either level) per step and a direction line (High = CW). Within a window the check
// measures the net distance (CW +), the time from the window's start to the last step (a
// move's duration from its command, a stop's duration from its trigger; 0 with no step),
// the peak speed (1 / the shortest interval between two steps in the same direction) and
// the direction reversals, each against limits worked out from the spec.

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
[[nodiscard]] CheckResult check_shaft_move(std::span<const Edge> step, std::span<const Edge> dir,
                                           const ShaftMoveSpec& spec);

} // namespace hilrig::checks
