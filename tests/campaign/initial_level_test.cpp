// A board output's level from power-up is where its line starts, not an edge at time 0
// (virtual_run.cpp powers the bus up while it makes the board). The 4501's Cycle Output is off
// from power-up (models/amci4501/README.md); off is low with cycle_output_on = "high" and high
// with "low" (the sinking output of L277 read through a pull-up). A correct board passes the
// same checks in either polarity, and fails them beyond the same boundaries.

#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/executive.hpp"
#include "test_support.hpp"

namespace hilrig::campaign {
namespace {

using rig::Outcome;

// The 4501 with its Cycle Output on the rig line "co", in the polarity `on` ("high" / "low").
std::string board(const std::string& on) {
  return fmt::format(R"([dut]
model = "amci4501"
[dut.params]
cycle_output_on = "{}"
[[wiring]]
rig = "start"
board = "START"
[[wiring]]
rig = "latch"
board = "LATCH"
[[wiring]]
rig = "co"
board = "CYCLE_OUT"
)",
                     on);
}

// Mode 1, two cycles: Start 1 ms -> Latch 3 ms and Start 6 ms -> Latch 8 ms. The Cycle Output is
// active from the Start edge to the Latch edge (L7), each edge acted on one throughput (125 us,
// L281) later: active 1.125 .. 3.125 ms and 6.125 .. 8.125 ms, two pulses of 2000 us; off
// 3.125 .. 6.125 ms, one pulse of 3000 us. Off from power-up to 1.125 ms and from 8.125 ms to
// the end of the run are no pulses (no edge starts the one, none ends the other).
std::string mode1(const std::string& on, const std::string& check) {
  std::string text = R"([campaign]
name = "initial-level"
end = "10ms"
seed = 1
)" + board(on);
  for (const int at : {1, 3, 6, 8})
    text += fmt::format("[[stimulus]]\nkind = \"pulse\"\nline = \"{}\"\nat = \"{}ms\"\nwidth = \"100us\"\n",
                        at == 1 || at == 6 ? "start" : "latch", at);
  text += R"([[host]]
at = "0ms"
program = "mode"
mode = 1
timeout_ms = 0
name = "m1"
[[check]]
)" + check;
  return text;
}

std::string opposite(const std::string& level) { return level == "high" ? "low" : "high"; }

// The outcome of the campaign's one [[check]], named "co" (the host's handshake is judged too).
Outcome co_check(const std::string& text) {
  const Campaign c = parse_campaign(text, "initial_level.toml");
  const RunOutput out = Executive(c).run(c.runs.at(0));
  for (const rig::CheckResult& check : out.result.checks)
    if (check.check == "co") return check.outcome();
  ADD_FAILURE() << "no check co";
  return Outcome::Error;
}

Outcome pulse_check(const std::string& on, const std::string& level, const std::string& limits) {
  return co_check(mode1(on, fmt::format("kind = \"pulse_width\"\nname = \"co\"\nline = \"co\"\nlevel = "
                                        "\"{}\"\n{}\n",
                                        level, limits)));
}

class CycleOutputPolarity : public ::testing::TestWithParam<std::string> {};

// The line starts at the off level, with no edge: the trace holds it as the initial value
// (trace.vcd's $dumpvars), and the first edge is the first cycle's, to the on level.
TEST_P(CycleOutputPolarity, TheLineStartsOffWithNoEdge) {
  const std::string on = GetParam();
  const Campaign c = parse_campaign(
      mode1(on, "kind = \"pulse_width\"\nname = \"co\"\nline = \"co\"\nmin_pulses = 2\n"), "t.toml");
  const RunOutput out = Executive(c).run(c.runs.at(0));
  const std::int64_t co = out.trace->find("co");
  ASSERT_GE(co, 0);
  const SignalInfo& info = out.trace->signals().at(static_cast<std::size_t>(co));
  ASSERT_TRUE(info.has_initial);
  EXPECT_EQ(info.initial, on == "high" ? 0 : 1);
  const std::vector<Edge> edges = out.trace->edges_of("co");
  ASSERT_EQ(edges.size(), 4U);
  EXPECT_EQ(edges[0], (Edge{Nanos{1'125'000}, on == "high" ? Level::High : Level::Low}));
}

// The on pulses: 2000 us each (L7, L281), at the limit and a nanosecond either side.
TEST_P(CycleOutputPolarity, OnPulsesAreJudgedAtTheirWidth) {
  const std::string on = GetParam();
  EXPECT_EQ(pulse_check(on, on, "min_us = 2000\nmax_us = 2000\nmin_pulses = 2"), Outcome::Pass);
  EXPECT_EQ(pulse_check(on, on, "min_us = 1999.999\nmax_us = 2000.001\nmin_pulses = 2"), Outcome::Pass);
  EXPECT_EQ(pulse_check(on, on, "min_us = 2000.001"), Outcome::Fail);
  EXPECT_EQ(pulse_check(on, on, "max_us = 1999.999"), Outcome::Fail);
}

// The off pulses: only the one between the cycles, 3000 us. The off level from power-up is
// no pulse in either polarity (it was judged as one from an edge at 0 with "low").
TEST_P(CycleOutputPolarity, TheOffLevelFromPowerUpIsNoPulse) {
  const std::string on = GetParam();
  const std::string off = opposite(on);
  EXPECT_EQ(pulse_check(on, off, "min_us = 3000\nmax_us = 3000\nmin_pulses = 1"), Outcome::Pass);
  EXPECT_EQ(pulse_check(on, off, "min_us = 2999.999\nmax_us = 3000.001"), Outcome::Pass);
  EXPECT_EQ(pulse_check(on, off, "min_us = 3000.001"), Outcome::Fail);
  EXPECT_EQ(pulse_check(on, off, "max_us = 2999.999"), Outcome::Fail);
  // One complete off pulse, not two; the second is the off level after the last cycle, which
  // the run's end cuts: it may still close, so the count is not judged (an error, not a fail).
  EXPECT_EQ(pulse_check(on, off, "min_pulses = 2"), Outcome::Error);
  EXPECT_EQ(pulse_check(on, off, "min_pulses = 3"), Outcome::Fail); // short by more than the cut one
}

// Mode 2 (on 1000, off 3000 counts; Latch held 15 .. 35 ms): the Cycle Output copies the Latch in
// the window and is forced off at the window's end even with the Latch on (L12), one throughput
// later (L281). The shaft runs at 100,000 counts/s from 0.5 counts: count 3000 at 29.995 ms, the
// output off at 30.120 ms, at 0.5 + 3012 = 3012.5 counts. The only edge to the off level is that
// one: the off level from power-up is no edge "fired at 0.5 counts".
std::string mode2(const std::string& on, const std::string& check) {
  return R"([campaign]
name = "initial-level-mode2"
end = "40ms"
seed = 1
)" + board(on) +
         R"([[wiring]]
rig = "enc.A"
board = "A"
[[wiring]]
rig = "enc.B"
board = "B"
[encoder]
lines = 1024
[motion]
start_turns = 0.0001220703125
[[motion.move]]
kind = "constant"
speed_rpm = 1464.84375
duration = "40ms"
[[stimulus]]
kind = "pulse"
line = "latch"
at = "15ms"
width = "20ms"
[[host]]
at = "0ms"
program = "mode"
mode = 2
timeout_ms = 0
on = 1000
off = 3000
name = "m2"
[[check]]
)" + check;
}

Outcome off_edge_at(const std::string& on, double position) {
  return co_check(mode2(on, fmt::format("kind = \"edge_at_position\"\nname = \"co\"\noutput = "
                                        "\"co\"\nlevel = \"{}\"\nposition = {}\ntolerance_counts = 1\n",
                                        opposite(on), position)));
}

TEST_P(CycleOutputPolarity, TheOffEdgeIsTheWindowEndsOnly) {
  const std::string on = GetParam();
  EXPECT_EQ(off_edge_at(on, 3012.5), Outcome::Pass);
  EXPECT_EQ(off_edge_at(on, 3011.5), Outcome::Pass);   // the edge at the upper limit
  EXPECT_EQ(off_edge_at(on, 3011.501), Outcome::Pass); // the edge 0.999 counts above
  EXPECT_EQ(off_edge_at(on, 3011.499), Outcome::Fail); // 1.001 counts above
  EXPECT_EQ(off_edge_at(on, 3013.5), Outcome::Pass);   // at the lower limit
  EXPECT_EQ(off_edge_at(on, 3013.499), Outcome::Pass);
  EXPECT_EQ(off_edge_at(on, 3013.501), Outcome::Fail);
}

std::string polarity_name(const ::testing::TestParamInfo<std::string>& p) {
  return p.param == "high" ? "ActiveHigh" : "ActiveLow";
}

INSTANTIATE_TEST_SUITE_P(OnLevel, CycleOutputPolarity, ::testing::Values("high", "low"), polarity_name);

} // namespace
} // namespace hilrig::campaign
