#pragma once
// Brake stop time: from brake applied to standstill, against the limit; and the board's
// reported stop time and stop-time fault output checked against the measured time.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/line.hpp"
#include "rig/checks/support.hpp"

namespace hilrig::checks {

// One point of the motion trace (e.g. every count change of the shaft, or a sampled profile).
struct PositionSample {
  Nanos time;
  double position;
};

// Appends `sample` (times ascending) keeping only what standstill_after() reads: the first
// sample, the last change of position (the sample before it and the one that made it) and the
// latest sample. standstill_after() of the kept samples equals that of every sample appended,
// for any `from`, and a long run holds at most four.
void append_motion(std::vector<PositionSample>& motion, PositionSample sample);

// Standstill after `from`: the first instant at which the position stops changing for good
// (the time of the last change, or `from` when nothing moves after it). nullopt when the
// trace has no sample after that instant, so it cannot prove the shaft stayed still.
[[nodiscard]] std::optional<Nanos> standstill_after(std::span<const PositionSample> motion, Nanos from,
                                                    Nanos trace_end);

// When the shaft stood still: exact (earliest == latest, the rig knew the trajectory) or an
// interval read from count changes (rig/checks/standstill.hpp builds both).
struct Standstill {
  Nanos earliest; // the shaft stopped no sooner
  Nanos latest;   // ... and no later
  // The encoder count's last change before the standstill, which a board timing the stop from
  // count changes sees as its end (nullopt: earliest, as read from count changes).
  std::optional<Nanos> last_count_change{};
  // How a board's own standstill rule placed it (empty: the shaft's standstill), for the details.
  std::string rule{};
  [[nodiscard]] bool exact() const { return earliest == latest; }
  [[nodiscard]] Nanos last_change() const { return last_count_change.value_or(earliest); }
};

struct BrakeSpec {
  std::string name = "brake";
  Nanos limit{0};                      // Stop Time Limit: measured stop time must be <= limit
  std::optional<double> reported_ms{}; // the board's reported Stop Time (e.g. ANS1 DA19 w6)
  double report_tolerance_ms = 2.0;    // |reported - measured| allowed (without report_tick)
  // The board's stop timer tick: it times the stop in whole ticks, from its tick that saw the
  // brake applied to its tick that saw the count's last change (ANS1: 1 ms, L640, L1042,
  // L1052). A correct report then lies in [last count change - applied - tick, standstill -
  // applied + tick]; the reported time is judged against that window, not a tolerance.
  std::optional<Nanos> report_tick{};
  bool check_fault = false;         // judge the stop-time fault output
  Level fault_level = Level::Low;   // [MODEL] ANS1 ch. 3: outputs normally on, off = fault
  bool fault_from_reported = false; // expect the fault from the reported time, not the measured one
  std::string application{};        // how the application was chosen among several, for the details
  // How much later than `applied` the board may have seen the application (a bounce its tick
  // saw through a later edge): its report may be that much shorter (report_window()).
  Nanos applied_spread{0};
};

// Measurements: "<name>.stop_time" (ms, upper limit, window applied..standstill),
// "<name>.reported" (when reported_ms: ms, within measured ± tolerance, or with report_tick
// within the window a correct board can report, report_window()),
// "<name>.fault_output" (when check_fault: 1 when an edge to fault_level happened after
// `applied`, expected 1 exactly when the stop time exceeds the limit; with report_tick, when
// a report in the window exceeds it, as the board decides from its report).
// trace_end: when the capture ended (standstill must be followed by trace to be proven).
// From count changes alone (standstill_interval): judged on the interval's upper end.
[[nodiscard]] CheckResult check_brake_stop(Nanos applied, std::span<const PositionSample> motion,
                                           Nanos trace_end, std::span<const Edge> fault_output,
                                           const BrakeSpec& spec);
// With the standstill already known (nullopt: no standstill proven by trace_end). The stop
// time is judged conservatively on `latest`: it fails when the interval's upper end is over
// the limit, and the detail says when it was an interval. Without a standstill the stop is
// longer than trace_end - applied: over the limit for certain once that reaches the limit (a
// fail), else not judged (an error: the capture ended before the stop could be timed).
[[nodiscard]] CheckResult check_brake_stop(Nanos applied, std::optional<Standstill> still, Nanos trace_end,
                                           std::span<const Edge> fault_output, const BrakeSpec& spec);

// What a board with a stop timer tick of `tick` may report (ms, inclusive), brake applied at
// `applied`: its tick at the application falls in [applied, applied + tick), its tick at the
// standstill it sees (the count's last change, L1042) in [last change, last change + tick),
// and it counts whole ticks between them, so the report lies strictly inside
// (last change - applied - tick, last change - applied + tick). Widened to the standstill's
// upper end (the rig's exact standstill, or on hardware the interval's upper end) so that no
// correct board fails; from the application on (a shaft already still reads 0).
struct ReportWindow {
  double low_ms = 0.0;
  double high_ms = 0.0;
};
[[nodiscard]] ReportWindow report_window(Nanos applied, const Standstill& still, Nanos tick,
                                         Nanos applied_spread = Nanos{0});

} // namespace hilrig::checks
