// [motion] cycles: the move list played N times is the same motion as the moves spelled out
// N times, segment for segment, and its range is said before anything runs.

#include <gtest/gtest.h>

#include <string>

#include "campaign_text.hpp"
#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/motion.hpp"

namespace hilrig::campaign {
namespace {

using test::rejected_at;

std::string campaign_with(const std::string& motion) {
  return R"([campaign]
name = "t"
end = "2s"
[dut]
model = "reference_pls"
[dut.params]
on = 10
off = 20
[[wiring]]
rig = "enc.A"
board = "A"
[[wiring]]
rig = "enc.B"
board = "B"
[[wiring]]
rig = "ls1"
board = "OUT"
[[check]]
kind = "throughput"
name = "on"
output = "ls1"
setpoint = 10
limit_us = 250
[encoder]
lines = 100
)" + motion;
}

// A back-and-forth with a fractional distance, so a cycle does not end on a whole count.
const std::string kCycle = R"([[motion.move]]
kind = "trapezoid"
speed_rpm = 120
accel_rpm_s = 900
turns = 1.37
[[motion.move]]
kind = "dwell"
duration = "15ms"
[[motion.move]]
kind = "trapezoid"
speed_rpm = 60
accel_rpm_s = 600
turns = -0.5
)";

BuiltMotion motion_of(const std::string& text) {
  const Campaign c = parse_campaign(text, "t.toml");
  return build_motion("t.toml", c.points.at(0).motion, c.points.at(0).encoder);
}

TEST(MotionCycles, CyclesAreTheMovesSpelledOut) {
  for (int cycles : {1, 2, 5}) {
    std::string spelled = "[motion]\n";
    for (int i = 0; i < cycles; ++i) spelled += kCycle;
    const BuiltMotion a = motion_of(campaign_with(spelled));
    const BuiltMotion b =
        motion_of(campaign_with("[motion]\ncycles = " + std::to_string(cycles) + "\n" + kCycle));
    const auto& sa = a.profile.segments();
    const auto& sb = b.profile.segments();
    ASSERT_EQ(sa.size(), sb.size()) << cycles;
    for (std::size_t i = 0; i < sa.size(); ++i) {
      EXPECT_EQ(sa[i].start, sb[i].start) << cycles << " segment " << i;
      EXPECT_EQ(sa[i].duration, sb[i].duration) << cycles << " segment " << i;
      EXPECT_EQ(sa[i].position, sb[i].position) << cycles << " segment " << i;
      EXPECT_EQ(sa[i].velocity, sb[i].velocity) << cycles << " segment " << i;
      EXPECT_EQ(sa[i].acceleration, sb[i].acceleration) << cycles << " segment " << i;
    }
    // Each cycle moves 1.37 - 0.5 = 0.87 turns forward: 400 counts a turn (100 lines, X4).
    EXPECT_NEAR(b.profile.end_position(), cycles * 0.87 * 400.0, 1e-6) << cycles;
  }
}

TEST(MotionCycles, RangeIsSaidBeforeAnythingRuns) {
  EXPECT_TRUE(rejected_at(campaign_with("[motion]\ncycles = 0\n" + kCycle), "t.toml:27:10: motion.cycles: "));
  EXPECT_TRUE(
      rejected_at(campaign_with("[motion]\ncycles = 10001\n" + kCycle), "t.toml:27:10: motion.cycles: "));
  // Three moves a cycle: at most 100000 moves in all is 33333 cycles (but 10000 is the cap).
  EXPECT_EQ(test::error_of(campaign_with("[motion]\ncycles = -1\n" + kCycle)).find("1 .. 10000") !=
                std::string::npos,
            true);
  EXPECT_TRUE(rejected_at(campaign_with("[motion]\ncycles = 2\n"), "t.toml:27:10: motion.cycles: "));
  EXPECT_TRUE(
      rejected_at(campaign_with("[motion]\ncycles = 1.5\n" + kCycle), "t.toml:27:10: motion.cycles: "));
}

TEST(MotionCycles, TotalMovesAreBounded) {
  std::string many = "[motion]\ncycles = 10000\n";
  for (int i = 0; i < 11; ++i)
    many += "[[motion.move]]\nkind = \"constant\"\nspeed_rpm = 1\nduration = \"1ms\"\n";
  // 11 moves a cycle: 100000 / 11 = 9090 cycles at most.
  const std::string error = test::error_of(campaign_with(many));
  EXPECT_NE(error.find("motion.cycles: "), std::string::npos) << error;
  EXPECT_NE(error.find("cycles 1 .. 9090"), std::string::npos) << error;
}

} // namespace
} // namespace hilrig::campaign
