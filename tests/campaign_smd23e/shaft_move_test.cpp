// The SMD23E check kinds on hand-made traces: shaft_move (net steps, duration, peak speed,
// reversals from a step line and a direction line) and word_bits, and their registry
// entries' parameter rules.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "rig/checks/registry.hpp"
#include "rig/checks/shaft_move.hpp"
#include "rig/checks/word_bits.hpp"

namespace hilrig::checks {
namespace {

using namespace hilrig::literals;
using nlohmann::json;
using rig::Outcome;

// Steps toggle the step line; `dir` edges set the direction before the step at that time.
std::vector<Edge> toggles(const std::vector<Nanos>& times) {
  std::vector<Edge> out;
  Level l = Level::Low;
  for (Nanos t : times) {
    l = !l;
    out.push_back({t, l});
  }
  return out;
}

const Measurement* find(const CheckResult& r, const std::string& name) {
  for (const auto& m : r.measurements)
    if (m.name == name) return &m;
  return nullptr;
}

TEST(ShaftMove, CountsNetStepsDurationPeakAndReversals) {
  // 5 CW steps 1 ms apart (1..5 ms), then 2 CCW steps at 5.5 and 6.0 ms. Net 5 - 2 = 3; one
  // reversal; the shortest same-direction interval is 0.5 ms -> 2000 steps/s (the 0.5 ms
  // across the reversal is not a speed); last step 6 ms after from = 0.
  const std::vector<Edge> step = toggles({1_ms, 2_ms, 3_ms, 4_ms, 5_ms, 5500_us, 6_ms});
  const std::vector<Edge> dir = {{1_ms, Level::High}, {5500_us, Level::Low}};
  ShaftMoveSpec s;
  s.name = "m";
  s.steps = 3;
  s.duration_min = 5900_us;
  s.duration_max = 6100_us;
  s.peak_min = 1999;
  s.peak_max = 2001;
  s.reversals = 1;
  const CheckResult r = check_shaft_move(step, dir, s);
  EXPECT_EQ(r.outcome(), Outcome::Pass);
  EXPECT_EQ(find(r, "m.steps")->value, 3.0);
  EXPECT_DOUBLE_EQ(find(r, "m.duration")->value, 6.0);
  EXPECT_DOUBLE_EQ(find(r, "m.peak_speed")->value, 2000.0);
  EXPECT_EQ(find(r, "m.reversals")->value, 1.0);
}

TEST(ShaftMove, WindowCountsStepsStrictlyAfterFromAndUpToTo) {
  // Steps at 1..4 ms, all CW. Window (2 ms, 3 ms]: only the step at 3 ms.
  const std::vector<Edge> step = toggles({1_ms, 2_ms, 3_ms, 4_ms});
  const std::vector<Edge> dir = {{1_ms, Level::High}};
  ShaftMoveSpec s;
  s.from = 2_ms;
  s.to = 3_ms;
  s.to_given = true; // the campaign closed the window: its steps are counted, the move runs on
  s.steps = 1;
  EXPECT_EQ(check_shaft_move(step, dir, s).outcome(), Outcome::Pass);
}

TEST(ShaftMove, NoStepMeansZeroDurationAndNoSpeed) {
  ShaftMoveSpec s;
  s.name = "stop";
  s.from = 10_ms;
  s.steps = 0;
  s.duration_max = 1_ms;
  s.peak_max = 10.0;
  const CheckResult r = check_shaft_move({}, {}, s);
  EXPECT_EQ(find(r, "stop.steps")->outcome, Outcome::Pass);
  EXPECT_EQ(find(r, "stop.duration")->value, 0.0);
  EXPECT_EQ(find(r, "stop.duration")->outcome, Outcome::Pass);
  // Only a ceiling on the speed of a shaft that made no two steps: nothing to hold against it.
  EXPECT_EQ(find(r, "stop.peak_speed")->outcome, Outcome::Error);
  // A floor is a move expected at least that fast: no speed fails it.
  s.peak_min = 1.0;
  EXPECT_EQ(find(check_shaft_move({}, {}, s), "stop.peak_speed")->outcome, Outcome::Fail);
  // One step, no interval: the same.
  s.peak_min.reset();
  EXPECT_EQ(find(check_shaft_move(toggles({11_ms}), {}, s), "stop.peak_speed")->outcome, Outcome::Error);
  // Two steps 1 ms apart: 1,000 steps/s against a ceiling of 10.
  EXPECT_EQ(find(check_shaft_move(toggles({11_ms, 12_ms}), {}, s), "stop.peak_speed")->outcome,
            Outcome::Fail);
}

// Without `steps`, a window with no step judges nothing: a board that never moves must not
// pass a duration, speed or reversal limit. One step in the window is judged again.
TEST(ShaftMove, NoStepWithoutAStepsExpectationIsAnError) {
  ShaftMoveSpec s;
  s.name = "stop";
  s.from = 10_ms;
  s.to = 20_ms;
  s.duration_max = 100_ms;
  EXPECT_EQ(check_shaft_move({}, {}, s).outcome(), Outcome::Error);
  s.duration_max.reset();
  s.reversals = 0;
  EXPECT_EQ(check_shaft_move({}, {}, s).outcome(), Outcome::Error);
  s.reversals.reset();
  s.peak_max = 10.0;
  EXPECT_EQ(check_shaft_move({}, {}, s).outcome(), Outcome::Error);
  s.peak_max.reset();
  s.duration_max = 100_ms;
  s.reversals = 0;
  // A step just after `from` and one at `to`: in the window.
  EXPECT_EQ(check_shaft_move(toggles({10_ms + 1_ns}), {}, s).outcome(), Outcome::Pass);
  EXPECT_EQ(check_shaft_move(toggles({20_ms}), {}, s).outcome(), Outcome::Pass);
  // Steps only outside it: nothing judged.
  EXPECT_EQ(check_shaft_move(toggles({10_ms, 20_ms + 1_ns}), {}, s).outcome(), Outcome::Error);
}

TEST(ShaftMove, DirectionLowBeforeItsFirstEdgeIsCcw) {
  const std::vector<Edge> step = toggles({1_ms, 2_ms});
  ShaftMoveSpec s;
  s.steps = -2;
  EXPECT_EQ(check_shaft_move(step, {}, s).outcome(), Outcome::Pass);
  s.dir_initial = Level::High;
  s.steps = 2;
  EXPECT_EQ(check_shaft_move(step, {}, s).outcome(), Outcome::Pass);
}

TEST(ShaftMove, StepsOutsideTheToleranceFail) {
  const std::vector<Edge> step = toggles({1_ms, 2_ms, 3_ms});
  const std::vector<Edge> dir = {{1_ms, Level::High}};
  ShaftMoveSpec s;
  s.steps = 5;
  s.steps_tolerance = 1;
  EXPECT_EQ(check_shaft_move(step, dir, s).outcome(), Outcome::Fail);
  s.steps_tolerance = 2;
  EXPECT_EQ(check_shaft_move(step, dir, s).outcome(), Outcome::Pass);
}

TEST(WordBits, JudgesOnlyTheMaskedBits) {
  // 0x4488: Controller OK, Position Invalid, Move Complete, Stopped.
  const std::vector<rig::Observation> obs = {{"sw1", 0x4488, "", 5_ms}};
  WordSpec s;
  s.name = "mc";
  s.observation = "sw1";
  EXPECT_EQ(check_word_bits(obs, s, 0x1080, 0x0080).outcome(), Outcome::Pass);
  EXPECT_EQ(check_word_bits(obs, s, 0x1080, 0x1080).outcome(), Outcome::Fail);
  s.observation = "nothing";
  EXPECT_EQ(check_word_bits(obs, s, 0x1080, 0x0080).outcome(), Outcome::Fail);
}

// A word read only after at_ms is missing at at_ms, and the failure says by when (as
// word_equals and word_within say it): 1 ns later it is judged.
TEST(WordBits, AWordReadAfterAtIsMissingByThatTime) {
  const std::vector<rig::Observation> obs = {{"sw1", 0x0080, "", 5_ms}};
  WordSpec s;
  s.name = "mc";
  s.observation = "sw1";
  s.at = 5_ms - 1_ns;
  const auto missing = check_word_bits(obs, s, 0x0080, 0x0080);
  EXPECT_EQ(missing.outcome(), Outcome::Fail);
  EXPECT_EQ(missing.measurements.at(0).detail, "missing word: no observation named 'sw1' by 4999999 ns");
  EXPECT_EQ(check_word_within(obs, s).measurements.at(0).detail, missing.measurements.at(0).detail);
  s.at = 5_ms;
  EXPECT_EQ(check_word_bits(obs, s, 0x0080, 0x0080).outcome(), Outcome::Pass);
}

TEST(WordBits, ASignedReadKeepsItsSixteenBits) {
  // 0xC000 read as signed is -16384; bit 15 and bit 14 are still set.
  const std::vector<rig::Observation> obs = {{"w", -16384.0, "", 1_ms}};
  WordSpec s;
  s.observation = "w";
  EXPECT_EQ(check_word_bits(obs, s, 0xC000, 0xC000).outcome(), Outcome::Pass);
}

// The key a ParamError names, or "ok" when the table builds.
std::string problem(const char* kind, const json& table) {
  try {
    (void)build_check_params(*find_check_kind(kind), "c", table);
    return "ok";
  } catch (const ParamError& e) {
    return e.key().empty() ? "(check)" : e.key();
  }
}

TEST(Smd23eCheckKinds, RegistryValidatesTheirParameters) {
  EXPECT_EQ(problem("shaft_move", json{{"step_line", "s"}, {"dir_line", "d"}, {"from_ms", 0}, {"steps", 3}}),
            "ok");
  // Nothing to judge.
  EXPECT_EQ(problem("shaft_move", json{{"step_line", "s"}, {"dir_line", "d"}, {"from_ms", 0}}), "(check)");
  EXPECT_EQ(problem("word_bits", json{{"observation", "sw1"}, {"mask", 4224}, {"value", 128}}), "ok");
  // A value bit outside the mask, a mask wider than a word, and a mask that judges no bit.
  EXPECT_EQ(problem("word_bits", json{{"observation", "sw1"}, {"mask", 128}, {"value", 4096}}), "value");
  EXPECT_EQ(problem("word_bits", json{{"observation", "sw1"}, {"mask", 70000}, {"value", 0}}), "mask");
  EXPECT_EQ(problem("word_bits", json{{"observation", "sw1"}, {"mask", 0}, {"value", 0}}), "mask");
}

// Where the direction line starts is no edge (a board output's power-up level): the check takes
// it from the capture, over dir_initial, and dir_initial only where the capture did not read it.
TEST(ShaftMove, TheDirectionLineStartsWhereTheCaptureReadIt) {
  const CheckParams cw =
      build_check_params(*find_check_kind("shaft_move"), "m",
                         json{{"step_line", "s"}, {"dir_line", "d"}, {"from_ms", 0}, {"steps", 2}});
  Capture c;
  c.lines["s"] = toggles({1_ms, 2_ms});
  c.lines["d"] = {};
  c.end = 5_ms; // still 3 ms after the last step, more than twice its 1 ms interval: the move is over
  EXPECT_EQ(run_check("m", cw, c).outcome(), Outcome::Fail); // dir_initial low: -2 steps
  c.initial["d"] = Level::High;
  EXPECT_EQ(run_check("m", cw, c).outcome(), Outcome::Pass);
  const CheckParams told_high = build_check_params(
      *find_check_kind("shaft_move"), "m",
      json{{"step_line", "s"}, {"dir_line", "d"}, {"dir_initial", "high"}, {"from_ms", 0}, {"steps", 2}});
  c.initial["d"] = Level::Low; // read low: CCW whatever dir_initial says
  EXPECT_EQ(run_check("m", told_high, c).outcome(), Outcome::Fail);
  c.initial.clear();
  EXPECT_EQ(run_check("m", told_high, c).outcome(), Outcome::Pass);
}

} // namespace
} // namespace hilrig::checks
