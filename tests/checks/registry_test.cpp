#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "check_test_support.hpp"
#include "rig/checks/registry.hpp"

namespace hilrig::checks {
namespace {

using namespace hilrig::literals;
using nlohmann::json;
using test::find;

CheckParams build(const char* kind, const json& table, std::string_view name = "c") {
  return build_check_params(*find_check_kind(kind), name, table);
}

// The first problem's valid range, or "ok".
std::string message(const char* kind, const json& table) {
  try {
    (void)build(kind, table);
    return "ok";
  } catch (const ParamError& e) {
    return e.what();
  }
}

// The key the first problem names ("(check)" for a rule across keys), or "ok".
std::string problem(const char* kind, const json& table) {
  try {
    (void)build(kind, table);
    return "ok";
  } catch (const ParamError& e) {
    return e.key().empty() ? "(check)" : e.key();
  }
}

TEST(Registry, NamesEveryCheckKindTheCampaignsUse) {
  std::set<std::string> names;
  for (const auto& k : check_kinds()) {
    names.insert(k.name);
    EXPECT_TRUE(k.build) << k.name;
    EXPECT_FALSE(k.summary.empty()) << k.name;
  }
  EXPECT_EQ(names, (std::set<std::string>{"throughput", "debounce", "advance_counts", "brake_stop_time",
                                          "edge_at_position", "pulse_width", "word_equals", "word_within",
                                          "frame_decodes", "shaft_move", "word_bits"}));
  ASSERT_NE(find_check_kind("debounce"), nullptr);
  EXPECT_TRUE(find_check_kind("debounce")->needs_bisection);
  EXPECT_EQ(find_check_kind("nonsense"), nullptr);
}

TEST(Registry, EveryKindBuildsItsOwnTypedParameters) {
  // kind_of() names the variant the builder returned: the typed spec and the kind agree.
  const std::vector<std::pair<const char*, json>> tables = {
      {"throughput", {{"output", "o"}, {"limit_us", 20}, {"setpoint", 1}}},
      {"debounce",
       {{"filter_us", 500},
        {"tolerance_us", 10},
        {"narrow_us", 1},
        {"wide_us", 2000},
        {"input", "i"},
        {"output", "o"}}},
      {"advance_counts", {{"output", "o"}, {"setpoint", 1}}},
      {"brake_stop_time", {{"limit_ms", 150}, {"applied_ms", 10}}},
      {"edge_at_position", {{"output", "o"}, {"position", 1}}},
      {"pulse_width", {{"line", "l"}, {"min_us", 1}}},
      {"word_equals", {{"observation", "w"}, {"value", 1}}},
      {"word_within", {{"observation", "w"}, {"lower", 1}}},
      {"word_bits", {{"observation", "w"}, {"mask", 1}, {"value", 1}}},
      {"shaft_move", {{"step_line", "s"}, {"dir_line", "d"}, {"from_ms", 0}, {"steps", 3}}}};
  // frame_decodes is refused: no backend captures frames (FrameDecodesIsRefusedAtParse).
  ASSERT_EQ(tables.size() + 1, check_kinds().size());
  for (const auto& [kind, table] : tables) EXPECT_EQ(kind_of(build(kind, table)), kind);
}

TEST(Registry, ValidationNamesTheKeyAndItsRange) {
  EXPECT_EQ(problem("throughput", json{{"output", "ls1"}, {"limit_us", 20}, {"setpoint", 100}}), "ok");
  EXPECT_EQ(problem("throughput", json{{"output", 3}, {"limit_us", 20}, {"setpoint", 1}}), "output");
  EXPECT_EQ(
      problem("throughput", json{{"output", "o"}, {"level", "middle"}, {"limit_us", 20}, {"setpoint", 1}}),
      "level");
  EXPECT_EQ(problem("throughput", json{{"output", "o"}, {"bogus", 1}, {"limit_us", 20}, {"setpoint", 1}}),
            "bogus");
  EXPECT_EQ(problem("throughput", json{{"output", "o"}, {"setpoint", 1}}), "limit_us");
  EXPECT_EQ(
      problem("throughput", json{{"output", "o"}, {"limit_us", 20}, {"setpoint", 1}, {"direction", "up"}}),
      "direction");
  // Cross rule: crossings or setpoint, not both or neither.
  EXPECT_EQ(problem("throughput", json{{"output", "ls1"}, {"limit_us", 20}}), "(check)");
  try {
    (void)build("throughput", json{{"output", "o"}, {"limit_us", -1}, {"setpoint", 1}});
    ADD_FAILURE() << "a negative limit built";
  } catch (const ParamError& e) {
    EXPECT_EQ(e.key(), "limit_us");
    EXPECT_STREQ(e.what(), "a finite number >= 0");
  }
}

// Issue 16 item 5: a NaN limit made every comparison false, so the check passed. NaN, inf
// and negatives where a limit, tolerance or duration is expected are bad input.
TEST(Registry, NotFiniteOrNegativeLimitsAreBadInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const double bad : {nan, inf, -inf, -0.001}) {
    SCOPED_TRACE(bad);
    EXPECT_EQ(problem("throughput", json{{"output", "o"}, {"limit_us", bad}, {"setpoint", 1}}), "limit_us");
    EXPECT_EQ(problem("throughput", json{{"output", "o"}, {"limit_us", 20}, {"crossings_us", {1.0, bad}}}),
              "crossings_us");
    EXPECT_EQ(problem("edge_at_position", json{{"output", "o"}, {"position", 1}, {"tolerance_counts", bad}}),
              "tolerance_counts");
    EXPECT_EQ(problem("brake_stop_time", json{{"limit_ms", bad}, {"applied_ms", 1}}), "limit_ms");
    EXPECT_EQ(problem("brake_stop_time", json{{"limit_ms", 1}, {"applied_ms", 1}, {"report_tick_ms", bad}}),
              "report_tick_ms");
    EXPECT_EQ(problem("pulse_width", json{{"line", "l"}, {"max_us", bad}}), "max_us");
    EXPECT_EQ(problem("debounce", json{{"filter_us", 500},
                                       {"tolerance_us", bad},
                                       {"narrow_us", 1},
                                       {"wide_us", 2000},
                                       {"input", "i"},
                                       {"output", "o"}}),
              "tolerance_us");
    EXPECT_EQ(problem("shaft_move",
                      json{{"step_line", "s"}, {"dir_line", "d"}, {"from_ms", 0}, {"duration_max_ms", bad}}),
              "duration_max_ms");
  }
  // A setpoint or an expected word may be negative, never NaN.
  EXPECT_EQ(problem("edge_at_position", json{{"output", "o"}, {"position", -5}}), "ok");
  EXPECT_EQ(problem("edge_at_position", json{{"output", "o"}, {"position", nan}}), "position");
  EXPECT_EQ(problem("word_within", json{{"observation", "w"}, {"lower", -inf}}), "lower");
  EXPECT_EQ(problem("word_within", json{{"observation", "w"}, {"lower", 3}, {"upper", 2}}), "upper");
}

// A modulus is 0 (none) or a full-scale count of at least one: below one count the levels
// setpoint + k * modulus are closer than any board resolves (1e-9 made a run eat memory without
// end). Both sides of 1, and 0, on every check that takes one.
TEST(Registry, AModulusIsNoneOrAtLeastOneCount) {
  const auto with = [](const std::string& kind, double modulus) {
    json p = kind == "throughput"       ? json{{"output", "o"}, {"limit_us", 20}, {"setpoint", 1}}
             : kind == "advance_counts" ? json{{"output", "o"}, {"setpoint", 1}, {"advance_ms", 1}}
                                        : json{{"output", "o"}, {"position", 1}};
    p["modulus"] = modulus;
    return problem(kind.c_str(), p);
  };
  for (const char* kind : {"throughput", "advance_counts", "edge_at_position"}) {
    SCOPED_TRACE(kind);
    for (const double ok : {0.0, 1.0, 4096.0}) EXPECT_EQ(with(kind, ok), "ok") << ok;
    for (const double bad : {1e-300, 1e-9, 0.5, std::nextafter(1.0, 0.0), -1.0})
      EXPECT_EQ(with(kind, bad), "modulus") << bad;
  }
}

// advance_ms scales with the speed at each edge, advance_counts is fixed: given both, one
// would silently win.
TEST(Registry, AnAdvanceIsATimeOrACountNotBoth) {
  const json base{{"output", "o"}, {"setpoint", 100}};
  json both = base;
  both["advance_ms"] = 1;
  both["advance_counts"] = 2;
  EXPECT_EQ(problem("advance_counts", both), "advance_counts");
  json ms = base;
  ms["advance_ms"] = 1;
  EXPECT_EQ(problem("advance_counts", ms), "ok");
  json counts = base;
  counts["advance_counts"] = 2;
  EXPECT_EQ(problem("advance_counts", counts), "ok");
}

// Issue 16 item 5: min_count, min_pulses, min_edges = 0 and a word_bits mask of 0 passed
// with nothing captured. Refused where the campaign is read.
TEST(Registry, ParametersThatJudgeNothingAreBadInput) {
  EXPECT_EQ(problem("throughput", json{{"output", "o"}, {"limit_us", 20}, {"setpoint", 1}, {"min_count", 0}}),
            "min_count");
  EXPECT_EQ(problem("pulse_width", json{{"line", "l"}, {"min_pulses", 0}}), "min_pulses");
  EXPECT_EQ(problem("edge_at_position", json{{"output", "o"}, {"position", 1}, {"min_edges", 0}}),
            "min_edges");
  EXPECT_EQ(problem("advance_counts", json{{"output", "o"}, {"setpoint", 1}, {"min_edges", 0}}), "min_edges");
  EXPECT_EQ(problem("frame_decodes", json{{"source", "s"}, {"decoder", "d"}, {"min_frames", 0}}),
            "min_frames"); // the key's range first, then the kind itself (FrameDecodesIsRefusedAtParse)
  EXPECT_EQ(problem("word_bits", json{{"observation", "w"}, {"mask", 0}, {"value", 0}}), "mask");
  EXPECT_EQ(problem("word_bits", json{{"observation", "w"}, {"mask", 1}, {"value", 0}}), "ok");
}

TEST(Registry, TimesAreWholeNanosecondsRoundedOnce) {
  // 20.3 us is not exact in binary; the limit is exactly 20'300 ns.
  const auto p = std::get<ThroughputParams>(
      build("throughput", json{{"output", "o"}, {"limit_us", 20.3}, {"setpoint", 1}}));
  EXPECT_EQ(p.spec.limit, 20'300_ns);
  const auto b =
      std::get<BrakeParams>(build("brake_stop_time", json{{"limit_ms", 150.0000001}, {"applied_ms", 0}}));
  EXPECT_EQ(b.spec.limit, 150'000'000_ns);
}

TEST(Registry, ThroughputFromThePositionFunctionAndASetpoint) {
  // Position 1 count/ms; setpoint 5 -> crossing at 5 ms; output high at 5.015 ms.
  Capture c;
  c.position = [](Nanos t) { return static_cast<double>(t.count()) / 1e6; };
  c.lines["dut.ls1"] = {{5_ms + 15_us, Level::High}};
  c.begin = 0_ms;
  c.end = 10_ms;
  const auto r =
      run_check("ls1-throughput",
                build("throughput",
                      json{{"output", "dut.ls1"}, {"limit_us", 20}, {"setpoint", 5}, {"direction", "rising"}},
                      "ls1-throughput"),
                c);
  EXPECT_EQ(r.check, "ls1-throughput");
  EXPECT_EQ(r.kind, "throughput");
  EXPECT_EQ(r.outcome(), rig::Outcome::Pass);
  EXPECT_EQ(find(r, "ls1-throughput.max").value, 15.0);
}

TEST(Registry, AMissingLineIsAnErrorNotAFailure) {
  Capture c;
  auto r = run_check(
      "x", build("throughput", json{{"output", "dut.ls1"}, {"limit_us", 20}, {"crossings_us", {1000}}}), c);
  EXPECT_EQ(r.outcome(), rig::Outcome::Error);
  EXPECT_NE(r.measurements[0].detail.find("no line named 'dut.ls1'"), std::string::npos);
  // Debounce without the executive's bisection cannot be judged.
  r = run_check("d",
                build("debounce", json{{"filter_us", 500},
                                       {"tolerance_us", 10},
                                       {"narrow_us", 1},
                                       {"wide_us", 2000},
                                       {"input", "in1"},
                                       {"output", "out1"}}),
                c);
  EXPECT_EQ(r.outcome(), rig::Outcome::Error);
}

TEST(Registry, DebouncePlanThenCheck) {
  const auto p = std::get<DebounceParams>(build("debounce",
                                                json{{"filter_us", 500},
                                                     {"tolerance_us", 10},
                                                     {"narrow_us", 1},
                                                     {"wide_us", 2000},
                                                     {"resolution_us", 1},
                                                     {"input", "rig.in1"},
                                                     {"output", "dut.out1"}},
                                                "in1-debounce"));
  EXPECT_EQ(p.plan.narrow, 1_us);
  EXPECT_EQ(p.plan.wide, 2_ms);
  EXPECT_EQ(p.plan.resolution, 1_us);
  EXPECT_EQ(p.plan.input, "rig.in1");
  Capture c;
  // A board with a 503 us filter: inside 500 ± 10.
  c.bisections = {{1_ms, bisect_boundary([](Nanos w) { return w >= 503_us; }, p.plan.narrow, p.plan.wide,
                                         p.plan.resolution)}};
  const auto r = run_check("in1-debounce", p, c);
  EXPECT_EQ(r.outcome(), rig::Outcome::Pass);
  EXPECT_NEAR(find(r, "in1-debounce.boundary").value, 503.0, 1.0);
  // narrow must be below wide.
  EXPECT_EQ(problem("debounce", json{{"filter_us", 500},
                                     {"tolerance_us", 10},
                                     {"narrow_us", 2000},
                                     {"wide_us", 2000},
                                     {"input", "i"},
                                     {"output", "o"}}),
            "wide_us");
}

// ans1_debounce's check (filter 27,500 us ± 500, probes 5 .. 60 ms) with `extra` keys.
json ans1_debounce_with(json extra) {
  json t{{"filter_us", 27500}, {"tolerance_us", 500}, {"narrow_us", 5000},
         {"wide_us", 60000},   {"input", "i"},        {"output", "o"}};
  if (!extra.is_null()) t.update(extra); // {} is null
  return t;
}

TEST(Registry, DebounceStartPhasesAreValidatedWithTheirKey) {
  // scan_us given: probe_phases defaults to phase_bins (10), each start's coverage reported.
  const auto p = std::get<DebounceParams>(build("debounce", ans1_debounce_with({{"scan_us", 1000}})));
  ASSERT_TRUE(p.phase);
  EXPECT_EQ(p.phase->scan, 1_ms);
  EXPECT_EQ(p.probe_phases, 10U);
  EXPECT_EQ(
      std::get<DebounceParams>(build("debounce", ans1_debounce_with({{"scan_us", 1000}, {"phase_bins", 4}})))
          .probe_phases,
      4U);
  EXPECT_EQ(std::get<DebounceParams>(build("debounce", ans1_debounce_with({}))).probe_phases, 1U);
  EXPECT_EQ(problem("debounce", ans1_debounce_with({{"probe_phases", 5}})),
            "probe_phases"); // only with scan_us
  EXPECT_EQ(problem("debounce", ans1_debounce_with({{"phase_bins", 5}})), "phase_bins");
  for (const double bad : {0.0, 1001.0, 2.5, -1.0})
    EXPECT_EQ(problem("debounce", ans1_debounce_with({{"scan_us", 1000}, {"probe_phases", bad}})),
              "probe_phases")
        << bad;
  EXPECT_EQ(problem("debounce", ans1_debounce_with({{"scan_us", 0.5}, {"probe_phases", 501}})),
            "probe_phases"); // > 1/ns
  EXPECT_EQ(problem("debounce", ans1_debounce_with({{"scan_us", 0}})), "scan_us");
  // The limit probe a hair short of filter - tolerance must be a pulse.
  EXPECT_EQ(problem("debounce", ans1_debounce_with({{"tolerance_us", 27500}})), "tolerance_us");
  EXPECT_EQ(problem("debounce", ans1_debounce_with({{"tolerance_us", 27499.999}})), "tolerance_us"); // 0 ns
  EXPECT_EQ(problem("debounce", ans1_debounce_with({{"tolerance_us", 27499.998}, {"narrow_us", 0.001}})),
            "ok"); // 1 ns
}

// narrow_us and wide_us bracket a board outside [filter - tolerance, filter + tolerance]: a
// narrowest probe that a board within the limits may accept, or a widest one it may reject,
// is refused. Limits 27,000 .. 28,000 us (filter 27,500, tolerance 500, as ans1_debounce).
TEST(Registry, DebounceProbeWidthsLieOutsideTheLimits) {
  EXPECT_EQ(problem("debounce", ans1_debounce_with({{"narrow_us", 26999.999}})), "ok"); // 1 ns short of 27 ms
  EXPECT_EQ(problem("debounce", ans1_debounce_with({{"narrow_us", 27000}})), "narrow_us"); // may be accepted
  EXPECT_EQ(problem("debounce", ans1_debounce_with({{"narrow_us", 27000.001}})), "narrow_us");
  EXPECT_EQ(problem("debounce", ans1_debounce_with({{"wide_us", 28000}})), "ok");          // must be accepted
  EXPECT_EQ(problem("debounce", ans1_debounce_with({{"wide_us", 27999.999}})), "wide_us"); // may be rejected
  // A pulse width is 1 ns .. 3600 s (docs/campaigns.md, "Times").
  EXPECT_EQ(problem("debounce", ans1_debounce_with({{"wide_us", 3.6e9}})), "ok");
  EXPECT_EQ(problem("debounce", ans1_debounce_with({{"wide_us", 3.6e9 + 0.001}})), "wide_us");
  EXPECT_EQ(message("debounce", ans1_debounce_with({{"wide_us", 3.6e9 + 0.001}})),
            "a finite number >= 0.0005 and <= 3600000000 (at least 1 ns once rounded to whole ns)");
  EXPECT_EQ(problem("debounce", ans1_debounce_with({{"narrow_us", 0.001}})), "ok");
  EXPECT_EQ(problem("debounce", ans1_debounce_with({{"narrow_us", 0.0004}})), "narrow_us"); // 0 ns
}

// A p99 limit above limit_us could never fail (every latency is judged against limit_us).
TEST(Registry, ThroughputP99LimitAtMostTheLimit) {
  const json base{{"output", "o"}, {"limit_us", 100}, {"crossings_us", json::array({1000})}};
  const auto with = [&](json extra) {
    json t = base;
    t.update(extra);
    return t;
  };
  EXPECT_EQ(problem("throughput", with({{"p99_limit_us", 100}})), "ok");
  EXPECT_EQ(problem("throughput", with({{"p99_limit_us", 99.999}})), "ok");
  EXPECT_EQ(problem("throughput", with({{"p99_limit_us", 100.001}})), "p99_limit_us");
}

TEST(Registry, BrakeFromTheBrakeLineAndTheReportedWord) {
  Capture c;
  c.lines["rig.brake"] = {{100_ms, Level::Low}};
  c.lines["dut.stop_fault"] = {};
  c.motion = {{0_ms, 0.0}, {200_ms, 10.0}, {250_ms, 12.0}};
  c.observations = {{"dut.stop_time", 151.0, "ms", 500_ms}};
  c.end = 600_ms;
  const auto p = build("brake_stop_time",
                       json{{"limit_ms", 200},
                            {"brake_line", "rig.brake"},
                            {"reported", "dut.stop_time"},
                            {"fault_output", "dut.stop_fault"}},
                       "brake");
  EXPECT_EQ(lines_of(p), (std::vector<std::string>{"rig.brake", "dut.stop_fault"}));
  // Virtual time: the executive hands the exact standstill (here 250 ms) in the capture.
  c.standstill = [](Nanos) { return std::optional<Nanos>{250_ms}; };
  auto r = run_check("brake", p, c);
  EXPECT_EQ(find(r, "brake.stop_time").value, 150.0);
  EXPECT_EQ(r.outcome(), rig::Outcome::Pass);
  // Hardware: only the count changes; the last count took 50 ms, so standstill lies in
  // [250, 300] ms and the stop time is judged on its upper end, 200 ms: exactly at the limit.
  c.standstill = nullptr;
  r = run_check("brake", p, c);
  EXPECT_EQ(find(r, "brake.stop_time").value, 200.0);
  EXPECT_EQ(find(r, "brake.stop_time").outcome, rig::Outcome::Pass);
  EXPECT_EQ(r.outcome(), rig::Outcome::Pass);
  // A hair beyond: the same interval against a limit 1 ns shorter fails.
  const auto tight = build(
      "brake_stop_time",
      json{{"limit_ms", 199.999999}, {"brake_line", "rig.brake"}, {"reported", "dut.stop_time"}}, "brake");
  EXPECT_EQ(find(run_check("brake", tight, c), "brake.stop_time").outcome, rig::Outcome::Fail);
}

// A brake check with nothing to time is an error, never a pass (docs/campaigns.md "Checks"):
// the rig's own brake line never applied, or a shaft already still when the brake came. A
// board's output that should drop the brake and never does is the board's fail.
TEST(Registry, BrakeWithNoStopToTimeIsAnError) {
  const auto p = build("brake_stop_time", json{{"limit_ms", 100}, {"brake_line", "brake"}}, "b");
  Capture c;
  c.lines["brake"] = {};
  c.motion = {{0_ms, 0.0}, {50_ms, 10.0}, {60_ms, 11.0}};
  c.end = 600_ms;
  c.rig_driven = {"brake"};
  EXPECT_EQ(find(run_check("b", p, c), "b.stop_time").outcome, rig::Outcome::Error);
  c.rig_driven.clear(); // the board drives it (a PLS output dropping a valve): the board's fail
  EXPECT_EQ(find(run_check("b", p, c), "b.stop_time").outcome, rig::Outcome::Fail);
  // Applied at 75 ms. Hardware: the last count change at 60 ms after one at 50 ms leaves the
  // standstill in [60, 70] ms, before the brake: nothing to time. Applied at 65 ms the
  // interval straddles it: judged on its upper end, 5 ms.
  c.lines["brake"] = {{75_ms, Level::Low}};
  EXPECT_EQ(find(run_check("b", p, c), "b.stop_time").outcome, rig::Outcome::Error);
  c.lines["brake"] = {{70_ms, Level::Low}};
  EXPECT_EQ(find(run_check("b", p, c), "b.stop_time").outcome, rig::Outcome::Error);
  c.lines["brake"] = {{69'999'999_ns, Level::Low}};
  EXPECT_EQ(find(run_check("b", p, c), "b.stop_time").value, 1e-6);
  EXPECT_EQ(find(run_check("b", p, c), "b.stop_time").outcome, rig::Outcome::Pass);
  // Virtual time: the exact standstill at or after the application. Still at it: an error;
  // 1 ns later: a stop of 1 ns, judged.
  c.standstill = [](Nanos from) { return std::optional<Nanos>{std::max(from, 60_ms)}; };
  c.lines["brake"] = {{60_ms, Level::Low}};
  EXPECT_EQ(find(run_check("b", p, c), "b.stop_time").outcome, rig::Outcome::Error);
  c.lines["brake"] = {{59'999'999_ns, Level::Low}};
  EXPECT_EQ(find(run_check("b", p, c), "b.stop_time").outcome, rig::Outcome::Pass);
}

// A brake line that applied more than once before the stop ended: without the board's
// debounce named, which application it times is unknown, so nothing is judged; with the
// ANS1's (L1038-L1040) a 2 ms glitch at 60 ms is noise and the stop is timed from 125 ms.
TEST(Registry, BrakeLineThatBouncedNeedsTheBoardsDebounce) {
  Capture c;
  c.lines["brake"] = {{60_ms, Level::Low}, {62_ms, Level::High}, {125_ms, Level::Low}};
  c.initial["brake"] = Level::High;
  c.rig_driven = {"brake"};
  c.motion = {{0_ms, 0.0}, {225_ms, 100.0}};
  c.standstill = [](Nanos) { return std::optional<Nanos>{225_ms}; };
  c.end = 600_ms;
  const json brake{{"limit_ms", 100}, {"brake_line", "brake"}};
  const auto r = run_check("b", build("brake_stop_time", brake, "b"), c);
  EXPECT_EQ(find(r, "b.stop_time").outcome, rig::Outcome::Error);
  EXPECT_NE(find(r, "b.stop_time").detail.find("applied_debounce"), std::string::npos);
  json debounced = brake;
  debounced["applied_debounce"] = "ans1";
  const auto d = run_check("b", build("brake_stop_time", debounced, "b"), c);
  EXPECT_EQ(find(d, "b.stop_time").value, 100.0); // 225 - 125 ms, exactly at the limit
  EXPECT_EQ(d.outcome(), rig::Outcome::Pass);
  debounced["limit_ms"] = 99.999999;
  EXPECT_EQ(run_check("b", build("brake_stop_time", debounced, "b"), c).outcome(), rig::Outcome::Fail);
  // The line returning to released only after the stop ended is no second application.
  c.lines["brake"] = {{125_ms, Level::Low}, {225_ms, Level::High}};
  EXPECT_EQ(find(run_check("b", build("brake_stop_time", brake, "b"), c), "b.stop_time").outcome,
            rig::Outcome::Pass);
  c.lines["brake"] = {{125_ms, Level::Low}, {224'999'999_ns, Level::High}};
  EXPECT_EQ(find(run_check("b", build("brake_stop_time", brake, "b"), c), "b.stop_time").outcome,
            rig::Outcome::Error);
  // Every application noise: the rig's stimulus never applied the brake for the board.
  c.lines["brake"] = {{60_ms, Level::Low}, {62_ms, Level::High}};
  debounced["limit_ms"] = 100;
  EXPECT_EQ(find(run_check("b", build("brake_stop_time", debounced, "b"), c), "b.stop_time").outcome,
            rig::Outcome::Error);
  EXPECT_EQ(
      problem("brake_stop_time", json{{"limit_ms", 1}, {"applied_ms", 1}, {"applied_debounce", "ans1"}}),
      "applied_debounce");
  EXPECT_EQ(
      problem("brake_stop_time", json{{"limit_ms", 1}, {"brake_line", "b"}, {"applied_debounce", "ANS1"}}),
      "applied_debounce");
  EXPECT_EQ(
      problem("brake_stop_time", json{{"limit_ms", 1}, {"brake_line", "b"}, {"applied_debounce", "none"}}),
      "ok");
}

// A key that only refines another does nothing alone: refused like a typo, not ignored.
TEST(Registry, RefiningKeysWithoutWhatTheyRefineAreBadInput) {
  const json brake{{"limit_ms", 100}, {"applied_ms", 1}};
  const auto with = [](json t, json extra) {
    t.update(extra);
    return t;
  };
  EXPECT_EQ(problem("brake_stop_time", with(brake, {{"report_tolerance_ms", 3}})), "report_tolerance_ms");
  EXPECT_EQ(problem("brake_stop_time", with(brake, {{"report_tolerance_ms", 3}, {"reported", "w"}})), "ok");
  EXPECT_EQ(problem("brake_stop_time", with(brake, {{"fault_level", "high"}})), "fault_level");
  EXPECT_EQ(problem("brake_stop_time", with(brake, {{"report_tick_ms", 1}})), "report_tick_ms");
  EXPECT_EQ(problem("brake_stop_time", with(brake, {{"report_tick_ms", 1}, {"reported", "w"}})), "ok");
  EXPECT_EQ(problem("brake_stop_time", with(brake, {{"report_tick_ms", 1}, {"fault_output", "f"}})), "ok");
  EXPECT_EQ(problem("brake_stop_time", with(brake, {{"applied_level", "high"}})), "applied_level");
  EXPECT_EQ(problem("brake_stop_time", with(brake, {{"fault_level", "high"}, {"fault_output", "f"}})), "ok");
  EXPECT_EQ(problem("brake_stop_time", with(brake, {{"fault_from_reported", true}, {"reported", "w"}})),
            "fault_from_reported");
  EXPECT_EQ(problem("brake_stop_time", with(brake, {{"fault_from_reported", true}, {"fault_output", "f"}})),
            "fault_from_reported");
  EXPECT_EQ(problem("brake_stop_time",
                    with(brake, {{"fault_from_reported", true}, {"fault_output", "f"}, {"reported", "w"}})),
            "ok");
  const json shaft{{"step_line", "s"}, {"dir_line", "d"}, {"from_ms", 0}, {"duration_max_ms", 5}};
  EXPECT_EQ(problem("shaft_move", with(shaft, {{"steps_tolerance", 2}})), "steps_tolerance");
  EXPECT_EQ(problem("shaft_move", with(shaft, {{"steps_tolerance", 2}, {"steps", 100}})), "ok");
}

// The board's stop timer tick replaces the fixed report tolerance: one or the other, and a
// tick of 0 would time nothing.
// The ANS1's own standstill (L1042): stopped once the count changed by less than the Complete
// Stop Count (CSC) in 125 ms, the stop time ending 125 ms before (L1052). The shaft brakes to a
// stop at 300 ms, 4,096 counts, as d(t) = (300 ms - t)^2 / K counts short of it (K exact in
// binary: 102,400 counts/s^2). The count is floor(position): its change over a window ending
// after the stop is the whole counts short of 4,096 at the window's start, under CSC once that
// is CSC - 1 or less. CSC 9: 8 counts short at 287.5 ms exactly, (12.5 ms)^2 / K = 8.
TEST(Registry, BrakeStandstillByTheBoardsCompleteStopCount) {
  constexpr double kK = 19'531'250'000'000.0; // 2e18 / 102,400: ns^2 per count
  Capture c;
  c.position = [&](Nanos t) {
    const double before = static_cast<double>(std::max(300_ms - t, Nanos{0}).count());
    return 4096.0 - before * before / kK;
  };
  c.lines["rig.brake"] = {};
  c.end = 600_ms;
  const auto brake = [&](json extra) {
    json t{{"applied_ms", 100}, {"limit_ms", 187.5}, {"complete_stop_count", 9}};
    if (!extra.is_null()) t.update(extra); // {} is null
    return run_check("brake", build("brake_stop_time", t, "brake"), c);
  };
  EXPECT_EQ(find(brake({}), "brake.stop_time").value, 187.5);
  EXPECT_EQ(brake({}).outcome(), rig::Outcome::Pass); // exactly at the limit
  EXPECT_EQ(brake({{"limit_ms", 187.499999}}).outcome(), rig::Outcome::Fail);
  // The board sees that standstill at 412.5 ms (287.5 + 125). A capture ending 1 ns sooner
  // cuts the stop: its time is over 187.499999 ms, within the 187.5 ms limit, not judged (an
  // error); against a limit 1 ns shorter it is over the limit for certain (a fail).
  c.end = 412'500'000_ns;
  EXPECT_EQ(brake({}).outcome(), rig::Outcome::Pass);
  c.end = 412'499'999_ns;
  EXPECT_EQ(brake({}).outcome(), rig::Outcome::Error);
  EXPECT_EQ(brake({{"limit_ms", 187.499999}}).outcome(), rig::Outcome::Fail);
  c.end = 600_ms;
  // CSC 1: the count's last change, at the stop itself (200 ms after 100 ms), as without it.
  // (4096 less a few 1e-14 counts rounds to 4096 a few ns before the stop.)
  EXPECT_NEAR(find(brake({{"complete_stop_count", 1}}), "brake.stop_time").value, 200.0, 1e-5);
  EXPECT_EQ(find(brake({{"complete_stop_count", 1}, {"limit_ms", 200}}), "brake.stop_time").outcome,
            rig::Outcome::Pass);
  // A 250 ms window: 8 counts short at 287.5 ms, seen 250 ms later (before the stop, every
  // 250 ms holds thousands of counts).
  EXPECT_EQ(find(brake({{"stop_window_ms", 250}}), "brake.stop_time").value, 187.5);
  // A shaft that runs 10,000 counts/s to 100 ms and then creeps at 9.98 counts per 125 ms
  // never stops, yet a CSC of 10 calls it still once a window holds only the creep (from
  // 100 ms: 10 ms after the brake at 90 ms); at 10 counts per 125 ms it is never still for
  // it: no standstill, the board's fail.
  for (const double per_window : {9.98, 10.0}) {
    c.position = [&](Nanos t) {
      return t < 100_ms ? t.seconds() * 1e4 : 1000.0 + (t - 100_ms).seconds() / 0.125 * per_window;
    };
    const auto r = brake({{"complete_stop_count", 10}, {"limit_ms", 10}, {"applied_ms", 90}});
    if (per_window < 10.0) {
      EXPECT_EQ(find(r, "brake.stop_time").value, 10.0);
      EXPECT_EQ(r.outcome(), rig::Outcome::Pass);
    } else {
      EXPECT_EQ(r.outcome(), rig::Outcome::Fail);
    }
  }
  // Already under CSC when the brake is applied: nothing to time, an error.
  c.position = [](Nanos) { return 5.0; };
  EXPECT_EQ(brake({}).outcome(), rig::Outcome::Error);
  // stop_window_ms refines complete_stop_count; CSC below 1 could never be met.
  EXPECT_EQ(problem("brake_stop_time", json{{"applied_ms", 1}, {"limit_ms", 1}, {"stop_window_ms", 125}}),
            "stop_window_ms");
  EXPECT_EQ(
      problem("brake_stop_time", json{{"applied_ms", 1}, {"limit_ms", 1}, {"complete_stop_count", 0.5}}),
      "complete_stop_count");
}

TEST(Registry, BrakeReportTickIsATickOrATolerance) {
  const json base{{"limit_ms", 150}, {"applied_ms", 1}, {"reported", "w"}};
  auto with = [&](json extra) {
    json t = base;
    t.update(extra);
    return t;
  };
  EXPECT_EQ(problem("brake_stop_time", with({{"report_tick_ms", 1}, {"report_tolerance_ms", 2}})),
            "report_tick_ms");
  EXPECT_EQ(problem("brake_stop_time", with({{"report_tick_ms", 0}})), "report_tick_ms");
  const auto p = std::get<BrakeParams>(build("brake_stop_time", with({{"report_tick_ms", 1}}), "b"));
  EXPECT_EQ(p.spec.report_tick, 1_ms);
}

TEST(Registry, ThroughputPhaseCoverageIsTypedAndInformational) {
  const json base{{"output", "o"}, {"limit_us", 20}, {"crossings_us", json::array({0, 3, 7, 11})}};
  auto with = [&](json extra) {
    json t = base;
    t.update(extra);
    return t;
  };
  const auto p = std::get<ThroughputParams>(build("throughput", with({{"scan_us", 10}}), "tp"));
  ASSERT_TRUE(p.phase.has_value());
  EXPECT_EQ(p.phase->scan, 10_us);
  EXPECT_EQ(p.phase->bins, 10U);
  EXPECT_FALSE(std::get<ThroughputParams>(build("throughput", base)).phase.has_value());
  // Ranges checked when the campaign is parsed.
  EXPECT_EQ(problem("throughput", with({{"scan_us", 0}})), "scan_us");
  EXPECT_EQ(problem("throughput", with({{"scan_us", -1}})), "scan_us");
  EXPECT_EQ(problem("throughput", with({{"scan_us", 10}, {"phase_bins", 0}})), "phase_bins");
  EXPECT_EQ(problem("throughput", with({{"scan_us", 10}, {"phase_bins", 1.5}})), "phase_bins");
  EXPECT_EQ(problem("throughput", with({{"phase_bins", 4}})), "phase_bins");
  EXPECT_EQ(problem("throughput", with({{"scan_us", 10}, {"phase_bins", 1000}})), "ok");
  // Crossings at 0, 3, 7, 11 us in a 10 us scan land in bins 0, 3, 7 and 1 of 10: 4 covered.
  // The coverage has no limit: it is reported, never a reason to fail.
  Capture c;
  c.lines["o"] = {{2_us, Level::High}, {5_us, Level::High}, {9_us, Level::High}, {13_us, Level::High}};
  c.end = 100_us;
  const auto r = run_check("tp", p, c);
  const auto& cov = find(r, "tp.phase_coverage");
  EXPECT_EQ(cov.value, 4.0);
  EXPECT_EQ(cov.unit, "bins");
  EXPECT_FALSE(cov.lower.has_value());
  EXPECT_FALSE(cov.upper.has_value());
  EXPECT_EQ(cov.outcome, rig::Outcome::Pass);
  EXPECT_NE(cov.detail.find("4/10 bins"), std::string::npos) << cov.detail;
  EXPECT_NE(cov.detail.find("incomplete"), std::string::npos) << cov.detail;
}

// The same coverage, one mechanism, for the pulse starts of a pulse_width check and for the
// expected edges of an advance_counts check (the instant the shaft stood at the expected
// position): the keys, their ranges and the bins are those of throughput.
TEST(Registry, PulseWidthAndAdvancePhaseCoverage) {
  EXPECT_EQ(problem("pulse_width", json{{"line", "o"}, {"phase_bins", 4}}), "phase_bins");
  EXPECT_EQ(problem("pulse_width", json{{"line", "o"}, {"scan_us", 0}}), "scan_us");
  EXPECT_EQ(problem("advance_counts", json{{"output", "o"}, {"setpoint", 10}, {"scan_us", -1}}), "scan_us");
  EXPECT_FALSE(std::get<PulseWidthParams>(build("pulse_width", json{{"line", "o"}})).phase.has_value());

  // High pulses starting at 1, 12.5, 24 and 1002 us: phases 1, 2.5, 4 and 2 us of a 10 us scan,
  // bins 1, 2, 4 and 2 of 10: 3 covered.
  const auto pw = build("pulse_width", json{{"line", "o"}, {"scan_us", 10}, {"min_pulses", 4}}, "pw");
  Capture c;
  c.lines["o"] = {{1_us, Level::High},  {2_us, Level::Low},  {12'500_ns, Level::High}, {14_us, Level::Low},
                  {24_us, Level::High}, {30_us, Level::Low}, {1002_us, Level::High},   {1003_us, Level::Low}};
  c.end = 2_ms;
  const auto r = run_check("pw", pw, c);
  EXPECT_EQ(find(r, "pw.phase_coverage").value, 3.0);
  EXPECT_EQ(find(r, "pw.phase_coverage").outcome, rig::Outcome::Pass);
  EXPECT_EQ(r.outcome(), rig::Outcome::Pass);

  // A shaft at 1000 counts/s (one count a ms) from 0 at t = 0: setpoint 10 with no advance is
  // expected at 10 ms; edges fired at 10.0003 and 20.0007 ms (positions 10.0003, 20.0007:
  // expected 10 and 20 +- 1, window middles at 10 and 20 ms exactly): phases 0 of a 1 ms tick in
  // 4 bins, 1 covered; with the 0.3 ms tick of scan_us = 300 they sit at 100 and 200 us: bins 1
  // and 2 of 3.
  Capture a;
  a.position = [](Nanos t) { return t.seconds() * 1000.0; };
  a.speed = [](Nanos) { return 1000.0; };
  a.lines["o"] = {
      {Nanos{10'000'300}, Level::High}, {Nanos{10'500'000}, Level::Low}, {Nanos{20'000'700}, Level::High}};
  a.end = 30_ms;
  const auto adv = build(
      "advance_counts",
      json{{"output", "o"}, {"setpoint", 10}, {"modulus", 10}, {"scan_us", 1000}, {"phase_bins", 4}}, "adv");
  const auto ra = run_check("adv", adv, a);
  EXPECT_EQ(find(ra, "adv.phase_coverage").value, 1.0);
  EXPECT_NE(find(ra, "adv.phase_coverage").detail.find("1/4 bins"), std::string::npos);
  const auto adv3 = build(
      "advance_counts",
      json{{"output", "o"}, {"setpoint", 10}, {"modulus", 10}, {"scan_us", 300}, {"phase_bins", 3}}, "adv");
  EXPECT_EQ(find(run_check("adv", adv3, a), "adv.phase_coverage").value, 2.0);
}

// The keys that refine a scanned setpoint do nothing with given crossings: refused, as a typo
// would be (docs/campaigns.md "Checks": "stimulus: crossings_us *or* setpoint with ...").
TEST(Registry, SetpointScanKeysAreRefusedWithGivenCrossings) {
  const json given{{"output", "o"}, {"limit_us", 300}, {"crossings_us", {42500}}};
  const json scanned{{"output", "o"}, {"limit_us", 300}, {"setpoint", 100}};
  const auto with = [](json t, json extra) {
    t.update(extra);
    return t;
  };
  for (const auto& [key, value] : std::vector<std::pair<const char*, json>>{
           {"direction", "rising"}, {"step_us", 10}, {"modulus", 400}, {"from_us", 1000}, {"to_us", 50000}}) {
    SCOPED_TRACE(key);
    EXPECT_EQ(problem("throughput", with(given, {{key, value}})), key);
    EXPECT_EQ(problem("throughput", with(scanned, {{key, value}})), "ok");
  }
  try {
    (void)build("throughput", with(given, {{"from_us", 1000}}));
    ADD_FAILURE() << "from_us with crossings_us built";
  } catch (const ParamError& e) {
    EXPECT_STREQ(e.what(), "only with setpoint (crossings_us are the stimulus as given)");
  }
}

// A debounce check every rule accepts: a 1 ms filter, ±100 us, probes from 10 us to 5 ms.
json debounce_base() {
  return {{"filter_us", 1000}, {"tolerance_us", 100}, {"narrow_us", 10},
          {"wide_us", 5000},   {"input", "i"},        {"output", "o"}};
}

// Every duration whose range is "> 0" (a timeout, a quiet gap, a scan step, a filter, a probe
// width, a bisection bracket, a stop timer tick) is at least 1 ns once rounded to whole ns as
// the check rounds it (std::round: 0.0005 us is 1 ns, 0.0004999 us is 0). Swept across that
// edge for each, found from the registry so a duration added later is swept too.
TEST(Registry, EveryDurationIsAtLeastOneNanosecondOnceRounded) {
  const std::map<std::string, json> base = {
      {"throughput", {{"output", "o"}, {"limit_us", 300}, {"setpoint", 100}}},
      {"debounce", debounce_base()},
      {"brake_stop_time",
       {{"limit_ms", 100}, {"applied_ms", 1}, {"reported", "w"}, {"complete_stop_count", 1}}}};
  std::set<std::string> swept;
  for (const CheckKind& k : check_kinds())
    for (const ParamSpec& p : k.params) {
      // A number whose range excludes 0 itself is a duration: the rule applies to each.
      if (p.type == ParamType::Number && p.range.min == 0.0 && p.range.min_open) {
        EXPECT_GT(p.duration_ns, 0.0) << k.name << "." << p.name;
      }
      if (p.duration_ns == 0.0) continue;
      SCOPED_TRACE(k.name + "." + p.name);
      ASSERT_TRUE(base.contains(k.name));
      swept.insert(k.name + "." + p.name);
      const double half_ns = 0.5 / p.duration_ns; // 0.0005 us, 0.0000005 ms
      const auto with = [&](double v) {
        json t = base.at(k.name);
        t[p.name] = v;
        return t;
      };
      // A probe width also has its ceiling, 3600 s (docs/campaigns.md, "Times"), named with it.
      const std::string most = p.range.max ? " and <= 3600000000" : "";
      const std::string rule =
          std::string(p.duration_ns == 1e3 ? "a finite number >= 0.0005" : "a finite number >= 0.0000005") +
          most + " (at least 1 ns once rounded to whole ns)";
      for (const double refused : {half_ns * 0.01, half_ns * 0.8, half_ns * 0.9999}) {
        EXPECT_EQ(problem(k.name.c_str(), with(refused)), p.name) << refused;
        EXPECT_EQ(message(k.name.c_str(), with(refused)), rule) << refused;
      }
      // Half a ns and more is 1 ns: accepted by this rule (another may still refuse it: a
      // debounce filter or wide probe of 1 ns leaves no room for its tolerance or narrow_us).
      for (const double ok : {half_ns, half_ns * 1.0001, 2 * half_ns})
        EXPECT_NE(message(k.name.c_str(), with(ok)), rule) << ok;
    }
  EXPECT_EQ(swept,
            (std::set<std::string>{"throughput.timeout_us", "throughput.quiet_us", "throughput.step_us",
                                   "debounce.filter_us", "debounce.narrow_us", "debounce.wide_us",
                                   "debounce.resolution_us", "brake_stop_time.report_tick_ms",
                                   "brake_stop_time.stop_window_ms"}));
  // The probe of the auditor's case: narrow_us = 0.0004 would have probed a 0 ns pulse.
  auto narrow = debounce_base();
  narrow["narrow_us"] = 0.0004;
  EXPECT_EQ(problem("debounce", narrow), "narrow_us");
  narrow["narrow_us"] = 0.0005;
  EXPECT_EQ(std::get<DebounceParams>(build("debounce", narrow)).plan.narrow, 1_ns);
}

// A phase bin is at least 1 ns of the scan: times are whole ns, so a finer bin could never be
// hit and "complete" coverage could never be reached. 1 .. the scan in ns (and 1000).
TEST(Registry, PhaseBinsAreAtMostOnePerNanosecondOfTheScan) {
  const std::vector<std::pair<const char*, json>> kinds = {
      {"throughput", {{"output", "o"}, {"limit_us", 300}, {"crossings_us", {1}}}},
      {"debounce", debounce_base()},
      {"advance_counts", {{"output", "o"}, {"setpoint", 100}}},
      {"pulse_width", {{"line", "o"}}}};
  for (const auto& [kind, base] : kinds) {
    SCOPED_TRACE(kind);
    const auto with = [&](json extra) {
      json t = base;
      t.update(extra);
      return t;
    };
    EXPECT_EQ(problem(kind, with({{"scan_us", 0.005}, {"phase_bins", 5}})), "ok");
    EXPECT_EQ(problem(kind, with({{"scan_us", 0.005}, {"phase_bins", 6}})), "phase_bins");
    EXPECT_EQ(problem(kind, with({{"scan_us", 0.001}, {"phase_bins", 1}})), "ok");
    EXPECT_EQ(problem(kind, with({{"scan_us", 0.001}, {"phase_bins", 2}})), "phase_bins");
    // 0.0055 us is 6 ns (rounded half away from zero): 6 bins, not 7.
    EXPECT_EQ(problem(kind, with({{"scan_us", 0.0055}, {"phase_bins", 6}})), "ok");
    EXPECT_EQ(problem(kind, with({{"scan_us", 0.0055}, {"phase_bins", 7}})), "phase_bins");
    EXPECT_EQ(problem(kind, with({{"scan_us", 1}, {"phase_bins", 1000}})), "ok");
    // The default 10 bins need a scan of 10 ns: the key the file holds is named.
    EXPECT_EQ(problem(kind, with({{"scan_us", 0.01}})), "ok");
    EXPECT_EQ(problem(kind, with({{"scan_us", 0.009}})), "scan_us");
  }
  try {
    (void)build("pulse_width", json{{"line", "o"}, {"scan_us", 0.005}, {"phase_bins", 10}});
    ADD_FAILURE() << "10 bins over 5 ns built";
  } catch (const ParamError& e) {
    EXPECT_STREQ(e.what(), "1 .. 5: at most one bin per ns of scan_us (5 ns)");
  }
}

// An edge after timeout_us is missing, one before min_limit_us fails: a timeout below the
// minimum passes no board. Compared in whole ns, inclusive like every limit.
TEST(Registry, AThroughputTimeoutBelowItsMinimumIsContradictory) {
  const json base{{"output", "o"}, {"limit_us", 300}, {"crossings_us", {1}}, {"min_limit_us", 20}};
  const auto with = [&](double timeout) {
    json t = base;
    t["timeout_us"] = timeout;
    return t;
  };
  EXPECT_EQ(problem("throughput", with(10)), "timeout_us");
  EXPECT_EQ(problem("throughput", with(19.999)), "timeout_us");
  EXPECT_EQ(problem("throughput", with(19.9994)), "timeout_us"); // 19'999 ns
  EXPECT_EQ(problem("throughput", with(19.9996)), "ok");         // 20'000 ns
  EXPECT_EQ(problem("throughput", with(20)), "ok");
  EXPECT_EQ(problem("throughput", with(25)), "ok");
}

// Given crossings are the whole stimulus: a min_count above their number passes no board.
TEST(Registry, AThroughputMinCountAboveTheGivenCrossingsIsRefused) {
  const json base{{"output", "o"}, {"limit_us", 300}, {"crossings_us", {10, 20}}};
  const auto with = [&](int n) {
    json t = base;
    t["min_count"] = n;
    return t;
  };
  EXPECT_EQ(problem("throughput", with(1)), "ok");
  EXPECT_EQ(problem("throughput", with(2)), "ok");
  EXPECT_EQ(problem("throughput", with(3)), "min_count");
  try {
    (void)build("throughput", with(3));
  } catch (const ParamError& e) {
    EXPECT_STREQ(e.what(), "1 .. 2 (the number of crossings_us)");
  }
}

// A scanned setpoint crossed fewer than min_count times: the stimulus fell short, an error
// (nothing judged against min_count), not the board's fail. Position 1 count/ms: setpoint 5
// crossed once, at 5 ms.
TEST(Registry, AScannedSetpointCrossedTooFewTimesIsAnError) {
  Capture c;
  c.position = [](Nanos t) { return static_cast<double>(t.count()) / 1e6; };
  c.lines["o"] = {{5_ms + 15_us, Level::High}};
  c.end = 10_ms;
  const auto scan = [](int min_count) {
    return build("throughput",
                 json{{"output", "o"}, {"limit_us", 20}, {"setpoint", 5}, {"min_count", min_count}}, "tp");
  };
  EXPECT_EQ(run_check("tp", scan(1), c).outcome(), rig::Outcome::Pass);
  const auto r = run_check("tp", scan(2), c);
  EXPECT_EQ(find(r, "tp.count").outcome, rig::Outcome::Error);
  EXPECT_EQ(find(r, "tp.count").value, 1.0);
  EXPECT_EQ(find(r, "tp.count").lower, 2.0);
  EXPECT_EQ(find(r, "tp.count").detail,
            "nothing judged against min_count: the stimulus crossed the setpoint 1 time(s), fewer than "
            "min_count (2); latencies measured: 1");
  EXPECT_EQ(find(r, "tp.max").value, 15.0); // what there was is still judged
  // Crossed twice (back down at 8 ms, the board answers only the first): the board's fail.
  c.position = [](Nanos t) { return t < 6_ms ? t.seconds() * 1e3 : 12.0 - t.seconds() * 1e3; };
  const auto twice = run_check("tp", scan(2), c);
  EXPECT_EQ(find(twice, "tp.count").outcome, rig::Outcome::Fail);
}

// edge_at_position and advance_counts with no edge: if the shaft never reached where the edge
// is due (in the span judged), the stimulus never came, an error; if it did, the missing edge
// is the board's fail. Position 1 count/ms from 0 to 10 ms, then still at 10.
TEST(Registry, AnEdgeDueWhereTheShaftNeverWentIsAnError) {
  Capture c;
  c.position = [](Nanos t) { return std::min(t, 10_ms).seconds() * 1e3; };
  c.speed = [](Nanos t) { return t < 10_ms ? 1e3 : 0.0; };
  c.lines["o"] = {};
  c.end = 20_ms;
  const auto eap = [&](json extra) {
    json t{{"output", "o"}, {"position", 5}};
    if (!extra.is_null()) t.update(extra); // {} is null
    return run_check("e", build("edge_at_position", t, "e"), c);
  };
  EXPECT_EQ(find(eap({}), "e.edges").outcome, rig::Outcome::Fail); // reached at 5 ms: the board's
  EXPECT_EQ(find(eap({}), "e.edges").detail, "missing edge: no high edge on the output");
  const auto never = eap({{"position", 10.5}});
  EXPECT_EQ(find(never, "e.edges").outcome, rig::Outcome::Error);
  EXPECT_EQ(find(never, "e.edges").detail,
            "nothing judged: the shaft never reached position 10.5 (the stimulus never came)");
  // Reached exactly (10 counts at 10 ms), then standing within the tolerance (1 count) of it to
  // the end: a board within the tolerance may still fire, so nothing is judged.
  EXPECT_EQ(find(eap({{"position", 10}}), "e.edges").outcome, rig::Outcome::Error);
  EXPECT_EQ(
      find(eap({{"position", 10}}), "e.edges").detail,
      "nothing judged against min_edges: the shaft reached position 10 1 time(s), the last with the shaft "
      "still within 1 counts of it when the span ended (a board within the tolerance may fire after "
      "that: not judged), fewer than min_edges (1); high edges: 0");
  // 9 is passed through its band [8, 10] by 10 ms: reached, the board's fail.
  EXPECT_EQ(find(eap({{"position", 9}}), "e.edges").outcome, rig::Outcome::Fail);
  EXPECT_EQ(find(eap({{"position", 9.000001}}), "e.edges").outcome, rig::Outcome::Error);
  // With a modulus of 8, position 10.5 is 2.5: reached at 2.5 ms.
  EXPECT_EQ(find(eap({{"position", 10.5}, {"modulus", 8}}), "e.edges").outcome, rig::Outcome::Fail);
  // The span judged: [from_us, to_us], inclusive. Position 5 is reached at 5 ms exactly.
  EXPECT_EQ(find(eap({{"from_us", 6000}}), "e.edges").outcome, rig::Outcome::Error);
  EXPECT_EQ(find(eap({{"from_us", 5000}}), "e.edges").outcome, rig::Outcome::Fail);
  EXPECT_EQ(find(eap({{"from_us", 5000.001}}), "e.edges").outcome, rig::Outcome::Error);
  // ... and the band's far edge (6 counts, at 6 ms) reached by to_us: a board within the
  // tolerance fires by then.
  EXPECT_EQ(find(eap({{"to_us", 6000}}), "e.edges").outcome, rig::Outcome::Fail);
  EXPECT_EQ(find(eap({{"to_us", 5999.999}}), "e.edges").outcome, rig::Outcome::Error);
  EXPECT_EQ(find(eap({{"to_us", 5000}}), "e.edges").outcome, rig::Outcome::Error);
  EXPECT_EQ(find(eap({{"to_us", 4999.999}}), "e.edges").outcome, rig::Outcome::Error);
  EXPECT_EQ(find(eap({{"to_us", 4999.999}}), "e.edges").detail,
            "nothing judged: the shaft never reached position 5 up to 4999999 ns (the stimulus never came)");
  // Reached once, two edges asked for: the shortfall is the stimulus's.
  const auto once = eap({{"min_edges", 2}});
  EXPECT_EQ(find(once, "e.edges").outcome, rig::Outcome::Error);
  EXPECT_EQ(find(once, "e.edges").detail,
            "nothing judged against min_edges: the shaft reached position 5 1 time(s), fewer than min_edges "
            "(2); high edges: 0");
  // An edge that did come is judged as ever.
  c.lines["o"] = {{Nanos{5'000'300}, Level::High}};
  EXPECT_EQ(eap({}).outcome(), rig::Outcome::Pass);
  c.lines["o"] = {};

  // advance_counts: the edge is due where the position plus its advance reaches the setpoint.
  const auto adv = [&](json extra) {
    json t{{"output", "o"}, {"setpoint", 12}};
    if (!extra.is_null()) t.update(extra); // {} is null
    return run_check("a", build("advance_counts", t, "a"), c);
  };
  // Setpoint 12 with advance_counts 3: due at 9 counts, reached at 9 ms: the board's fail.
  EXPECT_EQ(find(adv({{"advance_counts", 3}}), "a.edges").outcome, rig::Outcome::Fail);
  // ... advance_counts 1.5: due at 10.5, never reached.
  EXPECT_EQ(find(adv({{"advance_counts", 1.5}}), "a.edges").outcome, rig::Outcome::Error);
  EXPECT_EQ(find(adv({{"advance_counts", 1.5}}), "a.edges").detail,
            "nothing judged: the shaft never reached setpoint 12 less its advance (the stimulus never came)");
  // advance_ms 3 at 1000 counts/s: due where position + 3 reaches 12, at 9 ms: reached. With
  // 2 ms it would be at 10 ms, where the shaft stops and its advance with it (12 - 1 ns
  // before, 10 at it): never reached.
  EXPECT_EQ(find(adv({{"advance_ms", 3}}), "a.edges").outcome, rig::Outcome::Fail);
  EXPECT_EQ(find(adv({{"advance_ms", 2}}), "a.edges").outcome, rig::Outcome::Error);
  EXPECT_EQ(find(adv({}), "a.edges").outcome, rig::Outcome::Error); // 12 itself: never
}

// frame_decodes has no frame source: no backend fills Capture::frames or ::decoders (the
// run's CAN frames are the rig's own resolver stream; serial bytes are not split into
// messages), so every run could only err. Refused where the campaign is read, after its keys.
TEST(Registry, FrameDecodesIsRefusedAtParse) {
  EXPECT_EQ(problem("frame_decodes", json{{"source", "can0"}, {"decoder", "resolver_angle"}}), "(check)");
  EXPECT_EQ(problem("frame_decodes", json{{"source", "can0"}}), "decoder");
  EXPECT_EQ(problem("frame_decodes", json{{"source", "can0"}, {"decoder", "d"}, {"bogus", 1}}), "bogus");
  try {
    (void)build("frame_decodes", json{{"source", "can0"}, {"decoder", "resolver_angle"}});
  } catch (const ParamError& e) {
    EXPECT_STREQ(e.what(), "a check kind a backend can judge: frame_decodes has no frame source on any "
                           "backend yet (no CAN frame or serial message of the board is captured)");
  }
}

} // namespace
} // namespace hilrig::checks
