#pragma once
// A measurement, as in OpenHTF: a named value with a unit, optional limits, a
// three-valued outcome, and the window of the trace that proves it.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/time.hpp"

namespace hilrig::rig {

enum class Outcome { Pass, Fail, Error }; // Error: could not be measured (no data, rig fault)

[[nodiscard]] constexpr const char* to_string(Outcome o) {
  return o == Outcome::Pass ? "pass" : o == Outcome::Fail ? "fail" : "error";
}

struct TraceWindow {
  Nanos begin;
  Nanos end;
};

struct Measurement {
  std::string name; // e.g. "throughput.ls1.p99"
  double value = 0.0;
  std::string unit;            // "us", "counts", "ms", "rpm", "" ...
  std::optional<double> lower; // inclusive
  std::optional<double> upper; // inclusive
  Outcome outcome = Outcome::Error;
  std::string detail; // one human sentence: what was compared, why it failed
  std::optional<TraceWindow> window;
  // The instant the measured event happened (the captured edge), when there is one; with
  // window it draws the report's timing diagram: expected window against captured edge.
  std::optional<Nanos> at;
};

// A sample series behind a distribution (e.g. every latency of a throughput check), kept so
// reports can draw histograms and merged shards keep the raw figures.
struct Series {
  std::string name; // e.g. "latency"
  std::string unit; // e.g. "us"
  std::vector<double> values;
};

// One probe of a bisection (a debounce check's pulse): its width, whether the board took it,
// and when it started (set when the check probed several start phases).
struct Probe {
  Nanos width;
  bool accepted = false;
  std::optional<Nanos> start{};
};

// What the trace held around one judged window, cut from the run's recording for the report's
// timing diagram: the stimulus (the encoder's A/B, or the line a check drives), the shaft's
// count and the output, each as its value at span.begin followed by its changes in the span.
// A Rate lane is derived, not recorded: a step line's steps per second, each step's rate
// (1 / the time since the step before) from that step on, 0 once the next step is overdue.
enum class LaneRole { Stimulus, Count, Output, Rate };

[[nodiscard]] constexpr const char* to_string(LaneRole r) {
  switch (r) {
  case LaneRole::Stimulus:
    return "stimulus";
  case LaneRole::Count:
    return "count";
  case LaneRole::Output:
    return "output";
  case LaneRole::Rate:
    return "rate";
  }
  return "output";
}

struct LaneChange {
  Nanos time;
  std::int64_t value = 0; // a line: 0 or 1; the count: counts
  double real = 0.0;      // a real lane's value (a resolver stator: volts); value is then 0
};

struct TraceLane {
  std::string name; // the trace's name: "enc.A", "shaft.count", "ls1"
  LaneRole role = LaneRole::Output;
  // The first: the value at span.begin; a real lane's: its samples in the span (the one
  // before it, at its own time, when none is inside), volts to 1 uV.
  std::vector<LaneChange> changes;
  // Changes left out to fit the figure (more than one per pixel column of it; the first and
  // last of each column are kept, so every level the lane held there is still drawn).
  std::size_t thinned = 0;
  // An analog lane (a trace signal of kind Real, e.g. resolver.sin): its values are the
  // changes' `real`, drawn as a line through the samples rather than as steps.
  bool real = false;
};

struct WindowTrace {
  TraceWindow around; // the measurement window it was cut for (Measurement::window)
  TraceWindow span;   // what the excerpt covers
  std::vector<TraceLane> lanes;
};

// A knot of an expected step rate (a programmed move's profile), steps/s, joined to the next
// by a straight line.
struct RatePoint {
  Nanos time;
  double rate = 0.0;
};

// An observation: a value read from the DUT (a status or data word) recorded by name.
struct Observation {
  std::string name;
  double value = 0.0;
  std::string unit;
  Nanos time; // when the rig made the read
  // When the campaign asked for it: its [[host]] `at` (a read inside a handshake: its write's).
  // A host action waits for the handshake before it (docs/campaigns.md, [[host]]), so `time`
  // may be later. None where not known (an observation loaded from results.json).
  std::optional<Nanos> due{};
};

// The one comparison rule (docs/campaigns.md, "How limits are compared"): every limit is
// inclusive, so a value exactly at a limit passes and one a hair beyond fails.
//  - Times are judged in integer nanoseconds, exactly (judge(Nanos, ...)).
//  - Every other value (counts, words, rates) is judged with one epsilon: a value within
//    kCompareEpsilon * max(1, |limit|) of a limit is at the limit. It absorbs the rounding of
//    double arithmetic (101.00000000000003 against 101: a double holds 2^-52 = 2.2e-16 of its
//    value, so 1e-12 is ~4,500 roundings) and nothing a board could show, at any magnitude a
//    campaign can reach: at 4 * 10^10 counts (10,000 turns of a 10^6-line encoder) it is
//    0.04 counts, where 1e-9 was 40 (a board 31 counts off passed).
//  - A value or a limit that is not a finite number is an Error: nothing was judged (every
//    comparison with NaN is false, so a NaN limit would otherwise pass any value).
inline constexpr double kCompareEpsilon = 1e-12;

[[nodiscard]] inline Outcome judge(double value, std::optional<double> lower, std::optional<double> upper) {
  if (!std::isfinite(value)) return Outcome::Error;
  if ((lower && !std::isfinite(*lower)) || (upper && !std::isfinite(*upper))) return Outcome::Error;
  const auto slack = [](double limit) { return kCompareEpsilon * std::max(1.0, std::abs(limit)); };
  if (lower && value < *lower - slack(*lower)) return Outcome::Fail;
  if (upper && value > *upper + slack(*upper)) return Outcome::Fail;
  return Outcome::Pass;
}

[[nodiscard]] inline Outcome judge(Nanos value, std::optional<Nanos> lower, std::optional<Nanos> upper) {
  if (lower && value < *lower) return Outcome::Fail;
  if (upper && value > *upper) return Outcome::Fail;
  return Outcome::Pass;
}

// A check's outcome in its run: the words every output uses (results.json, junit.xml,
// report.html; docs/campaigns.md "Outcome words"). A nominal run's check passes, fails or
// errs. In a fault run a named (caught_by) check that failed "caught" the fault; once the
// fault is caught every other check is "not judged"; when no named check caught it, the
// named checks that passed read "fail" (the fault went unnoticed) and the others "not judged".
enum class Judgement { Pass, Fail, Caught, NotJudged, Error };

[[nodiscard]] constexpr const char* to_string(Judgement j) {
  switch (j) {
  case Judgement::Pass:
    return "pass";
  case Judgement::Fail:
    return "fail";
  case Judgement::Caught:
    return "caught";
  case Judgement::NotJudged:
    return "not judged";
  case Judgement::Error:
    return "error";
  }
  return "error";
}

// The rig's own entries among a run's checks: the host's handshakes (kind "handshake") and a
// hardware run's timing (kind "rt_timing"; junit.xml's testcase for a rig fault has the name
// too). A campaign's check may take neither (the campaign reader refuses them), so no output
// holds two entries of one name.
inline constexpr std::string_view kHostCheckName = "host";
inline constexpr std::string_view kRigCheckName = "rig";

// One check's result: its measurements, all of which must pass for the check to pass.
struct CheckResult {
  std::string check; // the check's name in the campaign
  std::string kind;  // "throughput", "debounce", ...
  std::vector<Measurement> measurements;
  std::vector<Series> series;
  Judgement judgement = Judgement::Error; // in its run; derived by finalize()
  std::vector<Probe> probes;              // a debounce check's probes, in the order they ran
  // The trace around each window the report draws a timing diagram for (timing_figures()).
  std::vector<WindowTrace> traces;
  // A shaft_move check that names its move (profile_of): the step rate the move's profile
  // expects (rig/checks/move_profile.hpp), drawn over the measured rate; evidence, not judged.
  std::vector<RatePoint> expected_rate;
  // The measurements' outcome: Error when there is none (a check that judged nothing).
  [[nodiscard]] Outcome outcome() const {
    Outcome o = Outcome::Pass;
    for (const auto& m : measurements) {
      if (m.outcome == Outcome::Error) return Outcome::Error;
      if (m.outcome == Outcome::Fail) o = Outcome::Fail;
    }
    return measurements.empty() ? Outcome::Error : o;
  }
};

// The word one measurement reads, in its check's word (docs/campaigns.md, "each check's word"): in a
// fault run a failing measurement of the check that caught the fault is "caught", any failing
// one of a check not judged "not judged", never "fail". Every output that shows a measurement
// (report.html, trend.html, compare) reads it from here, so none paints a caught fault red.
[[nodiscard]] constexpr Judgement measurement_judgement(const CheckResult& check, const Measurement& m) {
  if (check.judgement == Judgement::Caught || check.judgement == Judgement::NotJudged)
    return m.outcome == Outcome::Pass ? Judgement::Pass : check.judgement;
  return m.outcome == Outcome::Pass   ? Judgement::Pass
         : m.outcome == Outcome::Fail ? Judgement::Fail
                                      : Judgement::Error;
}

} // namespace hilrig::rig
