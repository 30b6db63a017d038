#pragma once
// Detection power: for each check of a campaign's nominal runs, the smallest deviation of the
// virtual board (the check kind's knob, knobs.hpp) at which the check fails, found by
// bisection (bisect.hpp) on the campaign's own runs through the executive, and what the check
// measured there against its spec limit. docs/power.md.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "rig/campaign/campaign.hpp"
#include "rig/duts/dut.hpp"
#include "rig/power/bisect.hpp"

namespace hilrig::power {

struct PowerRow {
  std::string check;
  std::string kind;
  std::string knob;                // the model parameter swept; "" with a no-knob reason
  std::string knob_unit;           // "us" for a duration knob, "" for a number
  std::string direction;           // "up" or "down"
  bool two_sided = false;          // one of the two rows of a two-sided knob (knobs.hpp, Both)
  std::optional<double> nominal;   // knob value, knob_unit
  std::optional<double> threshold; // the smallest failing knob value found, knob_unit
  std::optional<double> last_pass; // the largest passing knob value seen, knob_unit
  std::size_t probes = 0;
  // What the check measured at the threshold: its most failing measurement.
  std::string measurement;
  std::optional<double> measured;
  std::optional<double> limit;
  std::string unit;
  std::optional<double> margin_pct; // (measured - limit) / |limit| * 100, beyond the limit
  // The board's own worst case at the threshold, where the model states it (knobs.hpp), in
  // `unit`, and its distance beyond the limit: what the campaign lets through unseen.
  std::optional<double> board_worst;
  std::optional<double> board_margin_pct;
  // The phase coverage the check's stimulus met (its `<check>.phase_coverage` sentence, the
  // least covered run's) for a check whose reading depends on where the stimulus falls in the
  // board's scan; why it is unknown when the check reports none (no scan_us); "" otherwise.
  // A board worst case beyond the limit that the rig let pass is explained here.
  std::string phase_coverage;
  bool phase_coverage_complete = false;
  std::string detail; // the failing measurement's sentence
  std::string reason; // why there is no threshold ("" when there is one)
};

struct PowerResult {
  std::string campaign;
  std::string device;
  std::uint64_t seed = 0;
  std::vector<PowerRow> rows; // in check-name order
};

struct PowerOptions {
  std::optional<std::uint64_t> seed;                // default: the campaign's
  std::vector<std::string> checks;                  // only these (default: every check)
  std::function<void(const std::string&)> progress; // one line per probe
};

// Measures every (selected) check's detection power. The campaign must be for the virtual backend.
[[nodiscard]] PowerResult measure_power(const campaign::Campaign& c, const PowerOptions& options);

// One probe as the bisection runs it, at a value of the model parameter `param`: the campaign's
// nominal runs with only `check` kept and dut.params[param] = value at every point. For sweeps
// across a threshold (tests).
[[nodiscard]] Probe probe_param(const campaign::Campaign& c, const std::string& check,
                                const std::string& param, const duts::ParamValue& value, std::uint64_t seed);

// The same at a factor on every brake torque of a press [plant] (the nominal and each
// [[plant.change]]): the knob of brake_stop_time where a press plant brakes the shaft.
[[nodiscard]] Probe probe_plant_brake_factor(const campaign::Campaign& c, const std::string& check,
                                             double factor, std::uint64_t seed);

// Whether a row's margin (or the board's worst-case margin, where known) is over max_pct, or
// the row has no margin at all.
[[nodiscard]] bool over_margin(const PowerRow& row, double max_pct);

} // namespace hilrig::power
