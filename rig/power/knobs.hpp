#pragma once
// Which deviation of a virtual board each check kind judges: the model parameter (a named
// row of the model's parameter table, `hilrig list`) that `hilrig power` sweeps away from its
// nominal value until the check fails, and in which direction. A check kind a model has no
// such parameter for has a named reason instead (docs/power.md).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hilrig::power {

// Which way from the nominal value the board gets worse. Both: a two-sided limit (a pulse too
// short or too long, a step clock too fast or too slow): `hilrig power` bisects each way and
// reports a row for each.
enum class KnobDirection { Up, Down, Both };

// What the model says the board's own worst case of the judged time is, from the knob: the knob
// itself (a response delay), or the knob plus another parameter (a scan period: an event waits
// up to one scan, then the output delay). The rig reads only the worst case its stimulus met;
// this is what the board would show at the worst phase.
enum class WorstCase { Unknown, Knob, KnobPlusParam };

// Where the knob lives: a parameter of the board's model, or (brake stop time, where the time
// judged is the machine's, not the board's) the brake deceleration of the scenario's
// press_stroke moves.
enum class KnobTarget { DutParam, MotionBrakeDecel };

struct Knob {
  KnobTarget target = KnobTarget::DutParam;
  std::string param; // the model's parameter; "" when there is none (see no_knob)
  KnobDirection direction = KnobDirection::Up;
  std::string no_knob; // why there is none: "no knob: ..."
  WorstCase worst_case = WorstCase::Unknown;
  std::string plus_param; // KnobPlusParam: the parameter added (a duration)
};

// The (first) knob for a check of `kind` on the model `model`.
[[nodiscard]] Knob knob_for(std::string_view model, std::string_view kind);
// Every board timing that moves such a check (an ANS1 pulse: its timer and its output driver),
// each bisected on its own; one entry (perhaps a no-knob reason) when there is one or none.
[[nodiscard]] std::vector<Knob> knobs_for(std::string_view model, std::string_view kind);

} // namespace hilrig::power
