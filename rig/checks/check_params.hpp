#pragma once
// Every check kind's parameters, typed: built once by the campaign parser from the check's
// table (registry.hpp: build_check_params, ranges and finiteness validated there) and read
// by the executive and the checks as fields, never looked up by name.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/line.hpp"
#include "core/time.hpp"
#include "rig/checks/brake.hpp"
#include "rig/checks/brake_application.hpp"
#include "rig/checks/crossings.hpp"
#include "rig/checks/debounce.hpp"
#include "rig/checks/edge_position.hpp"
#include "rig/checks/frames.hpp"
#include "rig/checks/pulse_width.hpp"
#include "rig/checks/shaft_move.hpp"
#include "rig/checks/standstill.hpp"
#include "rig/checks/throughput.hpp"
#include "rig/checks/words.hpp"

namespace hilrig::checks {

// Where a throughput check's crossings come from: the setpoint on the position function.
struct CrossingScan {
  double setpoint = 0.0; // counts
  Direction direction = Direction::Both;
  std::optional<Nanos> from{}; // default: the capture's begin
  std::optional<Nanos> to{};   // default: the capture's end
  Nanos step{100'000};
  double modulus = 0.0;
};

// The board's scan period the crossings' phase coverage is reported against (scan_us,
// phase_bins): informational, rig/checks/phase_coverage.hpp.
struct PhaseScan {
  Nanos scan{0};         // > 0
  std::size_t bins = 10; // >= 1
};

struct ThroughputParams {
  std::string output;
  ThroughputSpec spec;
  std::variant<std::vector<Nanos>, CrossingScan> crossings; // crossings_us as written, or a scan
  std::optional<PhaseScan> phase{};                         // scan_us given
};

// Debounce: the probe plan from a check's parameters for the executive's bisect_boundary().
struct BisectionPlan {
  Nanos narrow{0};
  Nanos wide{0};
  Nanos resolution{1000};
  std::string input{};       // the line the pulse is driven on
  std::string output{};      // the line whose edge means "accepted"
  Level level = Level::High; // the pulse's active level on the input
};

struct DebounceParams {
  DebounceSpec spec;
  BisectionPlan plan;
  // scan_us given: the probes start at probe_phases phases spread over the scan (probe_at +
  // k·scan/probe_phases), one bisection each, and their starts' phase coverage is reported.
  std::optional<PhaseScan> phase{};
  std::size_t probe_phases = 1; // >= 1; default phase_bins when scan_us is given
  // When each phase's probe pulses start, from the check's probe_at.
  [[nodiscard]] std::vector<Nanos> probe_starts(Nanos probe_at) const;
};

struct AdvanceParams {
  std::string output;
  AdvanceSpec spec;
  std::optional<PhaseScan> phase{}; // scan_us given: the expected edges' phase coverage
};

struct EdgeAtPositionParams {
  std::string output;
  EdgeAtPositionSpec spec;
};

struct BrakeParams {
  BrakeSpec spec;                 // reported_ms is filled from the capture's observation
  std::optional<Nanos> applied{}; // applied_ms; or the application of brake_line the board times
  std::string brake_line{};
  Level applied_level = Level::Low;
  BrakeDebounce debounce = BrakeDebounce::None; // applied_debounce: which application that is
  std::optional<std::string> reported{};        // the observation holding the board's stop time, ms
  std::optional<std::string> fault_output{};
  // The board's own standstill rule (ANS1 L1042): stopped once the count changed by less than
  // complete_stop_count over stop_window; its stop time ends stop_window before that (L1052).
  std::optional<StopCountRule> stop_rule{};
};

struct PulseWidthParams {
  std::string line;
  PulseWidthSpec spec;
  std::optional<PhaseScan> phase{}; // scan_us given: the pulse starts' phase coverage
};

struct WordEqualsParams {
  WordSpec spec;
  double value = 0.0;
};

struct WordWithinParams {
  WordSpec spec;
};

struct WordBitsParams {
  WordSpec spec;
  std::uint16_t mask = 0xFFFF; // never 0: the parser refuses a mask that judges nothing
  std::uint16_t value = 0;
};

struct FrameDecodesParams {
  std::string source;
  std::string decoder;
  FrameSpec spec;
};

struct ShaftMoveParams {
  std::string step_line;
  std::string dir_line;
  ShaftMoveSpec spec; // spec.to is the capture's end when to_ms is not given
  bool to_given = false;
};

using CheckParams = std::variant<ThroughputParams, DebounceParams, AdvanceParams, EdgeAtPositionParams,
                                 BrakeParams, PulseWidthParams, WordEqualsParams, WordWithinParams,
                                 WordBitsParams, FrameDecodesParams, ShaftMoveParams>;

// The check kind's name ("throughput", ...).
[[nodiscard]] std::string_view kind_of(const CheckParams& params);
// Every rig line the check reads from the capture (so the executive copies only those).
[[nodiscard]] std::vector<std::string> lines_of(const CheckParams& params);

} // namespace hilrig::checks
