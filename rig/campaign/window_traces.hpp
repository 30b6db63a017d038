#pragma once
// The trace around each window the report draws (rig/results/timing_figures.hpp), cut from
// the run's recording after the check was judged: what a timing diagram shows is what the
// run captured, never recomputed.

#include <vector>

#include "core/trace.hpp"
#include "rig/checks/check_params.hpp"
#include "rig/results/measurement.hpp"

namespace hilrig::campaign {

// Pixel columns a lane is thinned to (two changes kept per column at most).
inline constexpr std::size_t kLaneColumns = 500;
// A rate lane's name: its step line's and this.
inline constexpr const char* kRateSuffix = " rate";

// An analog lane's resolution, volts. The stators come from the resolver emulator
// (models/resolver_emulator), which has no DAC of its own in the model: its angle is 1/2^24
// turn (signals/resolver_frames.hpp), a stator step of at most amplitude * ratio * 2 pi / 2^24
// = 0.37 uV per volt, and the boards resolve 4096 counts a turn (ans1 seeds/000 L768: 1.5 mV
// per volt of stator). 1 uV keeps the first and is a thousand times finer than the second;
// more digits are float noise (results.json grew 2.2x with them).
inline constexpr double kRealLaneResolution = 1e-6;
inline constexpr double kRealLaneStepsPerVolt = 1e6; // 1 / kRealLaneResolution, exactly
// `volts` to the nearest kRealLaneResolution: the double nearest that decimal (a whole number
// of steps divided by the steps a volt, so it prints in at most six decimals).
[[nodiscard]] double real_lane_value(double volts);

// The lanes for a check's diagrams, as trace names: for a check judged against the shaft
// (throughput, advance_counts, edge_at_position) the stimulus (the encoder's lines, the
// resolver's stators as real lanes, whichever the campaign wires) and shaft.count; then the
// lines the check reads (output; a pulse or step line). Only names the trace declares; a
// shaft_move check adds its step line's rate (LaneRole::Rate).
[[nodiscard]] std::vector<std::pair<std::string, rig::LaneRole>> lanes_of(const checks::CheckParams& params,
                                                                          const TraceRecorder& trace);

using Lanes = std::vector<std::pair<std::string, rig::LaneRole>>;

// One WindowTrace per timing_figures(check) measurement, over the figure_span() of the
// measurement as drawn (as_drawn()), in one pass over the trace's samples.
[[nodiscard]] std::vector<rig::WindowTrace> cut_window_traces(const rig::CheckResult& check,
                                                              const TraceRecorder& trace, const Lanes& lanes);

// The windows of several checks of one run, each with its own lanes.
struct WindowCut {
  const rig::CheckResult* check;
  Lanes lanes;
};
// What cut_window_traces gives for each (the same, cut for cut), all in one pass over the
// trace's samples: a spilled recording is read back once per run, not once per check.
[[nodiscard]] std::vector<std::vector<rig::WindowTrace>> cut_window_traces(const std::vector<WindowCut>& cuts,
                                                                           const TraceRecorder& trace);

} // namespace hilrig::campaign
