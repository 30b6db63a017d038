// The 2742-18 packaging option (pls2700.md §4.11, Appendix A; W17, W18): input-triggered
// cycles on an LS Position, edge and level modes, advances through zero, input bits.
// Shaft: 32 raw counts per 400 us update (9.765625 rev/s) from half a raw count, so with
// SF 4096 MP moves 16 counts per update and v = 40 counts/ms. CL 1000 on channel 1; output 1
// pair 160..320 (LS). A trigger processed at update k0 gives LS = 16 (k - k0).
#include <gtest/gtest.h>

#include <vector>

#include "models/pls2700/error_codes.hpp"
#include "pls2700_bench.hpp"

namespace hilrig::models::pls2700 {
namespace {

using namespace hilrig::literals;
using testing::Bench;

constexpr double kTurnsPerSecondAt400us = 32.0 / 8192.0 / 0.0004;

std::vector<Nanos> times(const std::vector<Edge>& edges) {
  std::vector<Nanos> t;
  for (const Edge& e : edges) {
    t.push_back(e.time);
  }
  return t;
}

class Cycle18 : public ::testing::Test {
protected:
  Cycle18() {
    b.shaft(1, signals::angle_at_constant_speed(0.5 / 8192.0, kTurnsPerSecondAt400us));
    b.hold(2, 0, 360);
  }
  void program(std::uint16_t tr_word, std::uint16_t advances, std::uint16_t on, std::uint16_t off) {
    ASSERT_EQ(b.btw({0x8801, 0x4096, 0x8808, 0x1000, 0x8804, tr_word, 0xC011, advances, on, off}),
              error::kNone);
  }
  Bench b{ModelVariant::M2742_18};
};

TEST(Pls2700Setup18, W17BothChannelSetup) {
  // W17 (L1678-L1696): A807h 3600h 0720h 0090h 0045h 0201h 0104h.
  Bench b(ModelVariant::M2742_18);
  ASSERT_EQ(b.btw({0xC011, 0x0000, 0x0010, 0x0020, 0xC051, 0x0000, 0x0010, 0x0020}), error::kNone);
  EXPECT_EQ(b.btw({0xA807, 0x3600, 0x0720, 0x0090, 0x0045, 0x0201, 0x0104}), error::kNone);
  const pls2700::Setup& s = b.device().setup();
  EXPECT_EQ(s.channels[0].scale_factor, 3600);
  EXPECT_EQ(s.channels[0].circular_offset, 90);
  EXPECT_EQ(s.channels[0].cycle_length, 3600); // SF programmed -> CL := SF (L1540)
  EXPECT_EQ(s.channels[0].trigger, Trigger::NegativeEdge);
  EXPECT_EQ(s.channels[0].tach_code, 1);
  EXPECT_EQ(s.channels[1].scale_factor, 720);
  EXPECT_EQ(s.channels[1].circular_offset, 45);
  EXPECT_EQ(s.channels[1].cycle_length, 720);
  EXPECT_EQ(s.channels[1].trigger, Trigger::PositiveLevel);
  EXPECT_EQ(s.channels[1].tach_code, 4);
  EXPECT_EQ(s.outputs[0].pair_count, 0); // outputs 1-4 erased (L1634)
  EXPECT_EQ(s.outputs[4].pair_count, 0); // 5-8 erased: SF2 re-sent (L1659) [X]
}

TEST(Pls2700Setup18, W18ThroughZeroAndCycleLengthLimits) {
  // W18 (L1546, L1554, L1702): ON 350 / OFF 10 -> Dnh. Setpoints must be < CL (R-18-2).
  Bench b(ModelVariant::M2742_18);
  EXPECT_EQ(b.btw({0xC021, 0x0000, 0x0350, 0x0010}), 0xD2);
  b.btw({0x8400});
  EXPECT_EQ(b.btw({0x8808, 0x0100}), error::kNone);
  EXPECT_EQ(b.btw({0xC021, 0x0000, 0x0100, 0x0100}), 0xC2);
  b.btw({0x8400});
  EXPECT_EQ(b.btw({0xC021, 0x0000, 0x0050, 0x0100}), 0xD2);
  b.btw({0x8400});
  EXPECT_EQ(b.btw({0xC021, 0x0000, 0x0050, 0x0099}), error::kNone);
  EXPECT_EQ(b.btw({0x8808, 0x0200}), error::kNone); // programming CL erases outputs 1-4
  EXPECT_EQ(b.device().setup().outputs[1].pair_count, 0);
}

TEST_F(Cycle18, EdgeModeRunsOneCyclePerEdgeAndIgnoresEdgesDuringIt) {
  // R-18-3. Rising edge at 10 ms -> processed at update k0 = 25: on at LS 160 (k 35, 14 ms),
  // off at LS 320 (k 45, 18 ms); the cycle ends when LS >= 1000 (k 88, 35.2 ms). The edge at
  // 20 ms falls inside it and is ignored; the edge at 40 ms (k0 = 100) starts a new cycle:
  // on at 44 ms, off at 48 ms.
  program(0x0003, 0x0000, 0x0160, 0x0320);
  b.input_at(10_ms, 1, true);
  b.input_at(15_ms, 1, false);
  b.input_at(20_ms, 1, true);
  b.input_at(30_ms, 1, false);
  b.input_at(40_ms, 1, true);
  b.run_until(50_ms);
  EXPECT_EQ(times(b.edges(1)), (std::vector<Nanos>{14_ms, 18_ms, 44_ms, 48_ms}));
  // R-18-1: the input never changes the reported position: MP = 16 k at k = 125 -> 2000.
  EXPECT_EQ(b.btr()[0], 2000);
  // L1607: IN1 = bit 14 of the tach word while the input is energized.
  EXPECT_EQ(b.btr()[1] & 0x4000, 0x4000);
}

TEST_F(Cycle18, NegativeEdgeTriggers) {
  // Trigger byte 2 = negative edge: the fall at 10 ms starts the cycle (14 / 18 ms).
  program(0x0203, 0x0000, 0x0160, 0x0320);
  b.input_at(5_ms, 1, true);
  b.input_at(10_ms, 1, false);
  b.run_until(30_ms);
  EXPECT_EQ(times(b.edges(1)), (std::vector<Nanos>{14_ms, 18_ms}));
  EXPECT_EQ(b.btr()[1] & 0x4000, 0);
}

TEST_F(Cycle18, LevelModeRepeatsWhileActiveAndCompletesTheLastCycle) {
  // R-18-4. Active at 10 ms (k0 = 25): cycle 1 on 14/18 ms; LS wraps at k 88 (LS 1008 -> 8);
  // cycle 2: 16(k - 25) - 1000 in [160, 320) -> k 98..107: on 39.2 ms, off 43.2 ms. Inactive
  // at 50 ms (LS 600): cycle 2 is the last; back to active at 55 ms inside it: ignored.
  // Cycle 2 ends at k 150 (60 ms). Active at 70 ms (k0 = 175): on 74 ms, off 78 ms.
  program(0x0103, 0x0000, 0x0160, 0x0320);
  b.input_at(10_ms, 1, true);
  b.input_at(50_ms, 1, false);
  b.input_at(55_ms, 1, true);
  b.input_at(65_ms, 1, false);
  b.input_at(70_ms, 1, true);
  b.run_until(80_ms);
  EXPECT_EQ(times(b.edges(1)), (std::vector<Nanos>{14_ms, 18_ms, 39'200_us, 43'200_us, 74_ms, 78_ms}));
}

TEST_F(Cycle18, AdvanceThroughZeroAnticipatesTheNextCycleInLevelMode) {
  // R-18-6: pair 40..320 with a_on 5 ms: s_on = 40 * 5 = 200 -> ON point -160: on at the
  // trigger (10 ms), off at LS 320 (18 ms); while the input stays active it turns on again at
  // LS >= 1000 - 160 = 840 -> 16(k - 25) >= 840 -> k 78 (31.2 ms) and stays on through the
  // wrap until LS 320 of cycle 2 (k 108, 43.2 ms).
  program(0x0103, 0x0500, 0x0040, 0x0320);
  b.input_at(10_ms, 1, true);
  b.run_until(44_ms);
  EXPECT_EQ(times(b.edges(1)), (std::vector<Nanos>{10_ms, 18_ms, 31'200_us, 43'200_us}));
}

TEST_F(Cycle18, EdgeModeDoesNotAnticipate) {
  // Same program in edge mode: one cycle, no early ON near its end.
  program(0x0003, 0x0500, 0x0040, 0x0320);
  b.input_at(10_ms, 1, true);
  b.run_until(44_ms);
  EXPECT_EQ(times(b.edges(1)), (std::vector<Nanos>{10_ms, 18_ms}));
}

} // namespace
} // namespace hilrig::models::pls2700
