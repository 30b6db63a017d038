#include "rig/power/knobs.hpp"

#include <array>

namespace hilrig::power {
namespace {

struct Row {
  std::string_view model;
  std::string_view kind;
  std::string_view param;
  KnobDirection direction;
  WorstCase worst_case = WorstCase::Unknown;
  std::string_view plus_param = {};
};

// The detection-power knobs, each a parameter documented in its model's README. An output
// that reaches its pin later makes every timing an output edge carries worse: the crossing to
// output latency (throughput), the position at which the edge falls (edge_at_position) and the
// advance the board achieves (advance_counts).
constexpr std::array kKnobs{
    // models/ans1/params.hpp: latency in [output_delay, scan + output_delay].
    Row{"ans1", "throughput", "output_delay", KnobDirection::Up, WorstCase::KnobPlusParam, "scan"},
    Row{"ans1", "edge_at_position", "output_delay", KnobDirection::Up},
    Row{"ans1", "advance_counts", "output_delay", KnobDirection::Up},
    // Both: a debounce's limit is two-sided (filter +- tolerance, docs/campaigns.md "debounce"):
    // a filter that qualifies too early is as far out of spec as one too late.
    Row{"ans1", "debounce", "brake_sample_start", KnobDirection::Both},
    Row{"pls2700", "throughput", "output_delay", KnobDirection::Up},
    Row{"pls2700", "advance_counts", "output_delay", KnobDirection::Up},
    // models/amci4501/README.md: every response exactly one throughput after its input edge.
    Row{"amci4501", "throughput", "throughput", KnobDirection::Up, WorstCase::Knob},
    // rig/duts/reference_pls.cpp: the output is decided at a scan and set `delay` later.
    Row{"reference_pls", "throughput", "delay", KnobDirection::Up, WorstCase::KnobPlusParam, "scan"},
    // A timed output's on time is its timer (models/ans1/README.md): a timer running long or short.
    Row{"ans1", "pulse_width", "timer_error", KnobDirection::Both},
    // Every ON pulse at a pin, timed or not, is as long as the board commands it plus its
    // driver's turn-off delay minus its turn-on delay (models/*/README.md, output_off_skew).
    Row{"ans1", "pulse_width", "output_off_skew", KnobDirection::Both},
    Row{"pls2700", "pulse_width", "output_off_skew", KnobDirection::Both},
    Row{"amci4501", "pulse_width", "output_off_skew", KnobDirection::Both},
    // The 7361's clock pulses are halves of its clock period T, its frames start every TINT
    // (models/ssi7361/README.md).
    Row{"ssi7361", "pulse_width", "clock_period_error", KnobDirection::Both},
    // Up, and down too where the frame_start check has early_us (power.cpp, throughput_has_min):
    // with quiet_us it judges each frame's first falling edge, so an early frame reads early.
    Row{"ssi7361", "throughput", "frame_period_error", KnobDirection::Up},
    // The SMD23E's step timing is its profile in its own time base (models/smd23e/README.md).
    Row{"smd23e", "shaft_move", "step_clock_error", KnobDirection::Both},
};

bool value_check(std::string_view kind) {
  return kind == "word_equals" || kind == "word_within" || kind == "word_bits" || kind == "frame_decodes";
}

} // namespace

std::vector<Knob> knobs_for(std::string_view model, std::string_view kind) {
  std::vector<Knob> out;
  for (const Row& r : kKnobs)
    if (r.model == model && r.kind == kind)
      out.push_back(Knob{KnobTarget::DutParam,
                         std::string(r.param),
                         r.direction,
                         {},
                         r.worst_case,
                         std::string(r.plus_param)});
  if (out.empty()) out.push_back(knob_for(model, kind));
  return out;
}

Knob knob_for(std::string_view model, std::string_view kind) {
  for (const Row& r : kKnobs)
    if (r.model == model && r.kind == kind)
      return Knob{KnobTarget::DutParam, std::string(r.param),     r.direction, {},
                  r.worst_case,         std::string(r.plus_param)};
  // The stop time a brake_stop_time check judges is the shaft's: a weaker brake stops later.
  if (kind == "brake_stop_time")
    return Knob{
        KnobTarget::MotionBrakeDecel, "motion decel_rpm_s", KnobDirection::Down, {}, WorstCase::Unknown, {}};
  Knob k;
  if (value_check(kind))
    k.no_knob = "no knob: a value check (a word or a frame), not a timing with a deviation to sweep";
  else if (kind == "shaft_move")
    k.no_knob = "no knob: the " + std::string(model) + " model has no step-timing deviation parameter";
  else
    k.no_knob = "no knob: the " + std::string(model) + " model has no parameter that moves a " +
                std::string(kind) + " measurement";
  return k;
}

} // namespace hilrig::power
