#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "check_test_support.hpp"
#include "rig/checks/edge_position.hpp"

namespace hilrig::checks {
namespace {

using namespace hilrig::literals;
using test::find;

// v counts/s from 0 at t = 0.
PositionFn ramp(double v) {
  return [v](Nanos t) { return v * static_cast<double>(t.count()) / 1e9; };
}
PositionFn constant(double v) {
  return [v](Nanos) { return v; };
}

TEST(Advance, AnsOneLeadAdvanceWorkedExample) {
  // ANS1 W-13: lead advance 10 ms, FSC 360: 100 RPM = 600 counts/s -> 6 counts, 150 RPM =
  // 900 counts/s -> 9 counts. Setpoint 100: expected edges at 94 and 91 counts (± 1).
  const AdvanceSpec spec{.name = "ls1", .setpoint = 100.0, .advance = 10_ms, .modulus = 360.0};
  // At 600 counts/s position 94 is reached at 94/600 s = 156.666667 ms.
  const std::vector<Edge> at100{{Nanos{156'666'667}, Level::High}};
  auto r = check_advance(at100, ramp(600.0), constant(600.0), spec);
  EXPECT_EQ(r.outcome(), rig::Outcome::Pass);
  EXPECT_EQ(find(r, "ls1.edge0").lower, 93.0);
  EXPECT_EQ(find(r, "ls1.edge0").upper, 95.0);
  EXPECT_NEAR(find(r, "ls1.edge0").value, 94.0, 1e-6);
  const std::vector<Edge> at150{{Nanos{101'111'111}, Level::High}}; // 91/900 s
  r = check_advance(at150, ramp(900.0), constant(900.0), spec);
  EXPECT_EQ(r.outcome(), rig::Outcome::Pass);
  EXPECT_EQ(find(r, "ls1.edge0").lower, 90.0);
  EXPECT_EQ(find(r, "ls1.edge0").upper, 92.0);
}

TEST(Advance, PassesAtExactlyOneCountAndFailsAtTwo) {
  // 1000 counts/s (1 count per ms), advance 10 ms -> 10 counts; setpoint 100 -> expected 90.
  const AdvanceSpec spec{.name = "ls1", .setpoint = 100.0, .advance = 10_ms};
  const auto judge = [&](Nanos t) {
    const std::vector<Edge> e{{t, Level::High}};
    return check_advance(e, ramp(1000.0), constant(1000.0), spec).outcome();
  };
  EXPECT_EQ(judge(90_ms), rig::Outcome::Pass);
  EXPECT_EQ(judge(89_ms), rig::Outcome::Pass); // 89 counts: exactly -1
  EXPECT_EQ(judge(91_ms), rig::Outcome::Pass); // exactly +1
  EXPECT_EQ(judge(88_ms), rig::Outcome::Fail); // one count beyond
  EXPECT_EQ(judge(92_ms), rig::Outcome::Fail);
}

TEST(Advance, WindowIsTheTimeThePositionIsInsideTheToleranceAndAtIsTheEdge) {
  // Expected 90 ± 1 counts at 1 count/ms: inside from 89 ms to 91 ms.
  const std::vector<Edge> e{{90_ms + 300_us, Level::High}};
  const auto r =
      check_advance(e, ramp(1000.0), constant(1000.0), {.name = "a", .setpoint = 100.0, .advance = 10_ms});
  const auto& m = find(r, "a.edge0");
  ASSERT_TRUE(m.window);
  EXPECT_EQ(m.window->begin, 89_ms);
  EXPECT_EQ(m.window->end, 91_ms);
  EXPECT_EQ(m.at, 90_ms + 300_us);
}

TEST(Advance, ReverseMotionAdvancesTheOtherWay) {
  // -1000 counts/s from 200: expected 100 - (-1000 * 0.01) = 110; reached at 90 ms.
  const auto pos = [](Nanos t) { return 200.0 - static_cast<double>(t.count()) / 1e6; };
  const std::vector<Edge> e{{90_ms, Level::High}};
  const auto r = check_advance(e, pos, constant(-1000.0), {.name = "a", .setpoint = 100.0, .advance = 10_ms});
  EXPECT_EQ(r.outcome(), rig::Outcome::Pass);
  EXPECT_EQ(find(r, "a.edge0").lower, 109.0);
}

// A speed or position that is not a number (a division by a zero-length window upstream)
// judges nothing: every comparison with NaN is false, so a NaN expected position (from a NaN
// speed) would otherwise pass any edge. The measurement errs and says why; no window is made of
// it. The ANS1 worked example's figures (lead advance 10 ms, setpoint 100) otherwise.
TEST(Advance, ASpeedOrPositionThatIsNotANumberIsAnErrorNeverAPass) {
  const AdvanceSpec spec{.name = "ls1", .setpoint = 100.0, .advance = 10_ms}; // absolute positions
  const std::vector<Edge> e{{Nanos{156'666'667}, Level::High}};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Case {
    PositionFn position, speed;
    const char* reason;
  };
  for (const Case& c : {Case{ramp(600.0), constant(nan), "a limit is not a finite number: "},
                        Case{ramp(600.0), constant(inf), "a limit is not a finite number: "},
                        Case{constant(nan), constant(600.0), "not a number: "},
                        Case{constant(inf), constant(600.0), "not a finite number: "}}) {
    const auto r = check_advance(e, c.position, c.speed, spec);
    const auto& m = find(r, "ls1.edge0");
    EXPECT_EQ(m.outcome, rig::Outcome::Error);
    EXPECT_EQ(m.detail.rfind(c.reason, 0), 0U) << m.detail;
    EXPECT_FALSE(m.window);
    EXPECT_EQ(r.outcome(), rig::Outcome::Error);
  }
  // A speed so small the tolerance window outlasts 64-bit nanoseconds: judged, with no window.
  const auto slow = check_advance(e, constant(100.0), constant(1e-300), spec);
  EXPECT_EQ(slow.outcome(), rig::Outcome::Pass);
  EXPECT_FALSE(find(slow, "ls1.edge0").window);
}

TEST(Advance, WrapsModuloFullScale) {
  // FSC 360, setpoint 5, fixed advance 10 counts: expected -5 = 355. Fired at absolute 715.5
  // (= 355.5 on the second turn) compares as -4.5: inside [-6, -4].
  const std::vector<Edge> e{{1_ms, Level::High}};
  const auto r = check_advance(e, constant(715.5), constant(600.0),
                               {.name = "a", .setpoint = 5.0, .advance_counts = 10.0, .modulus = 360.0});
  EXPECT_EQ(r.outcome(), rig::Outcome::Pass);
  EXPECT_DOUBLE_EQ(find(r, "a.edge0").value, -4.5);
}

// 10,000 turns of a 10^6-line encoder: the shaft at 4e10 + 101.2412 counts, full scale 4096
// (4e10 is a multiple). Against 101 +- 0.2412 the board is exactly at the limit: it passes as it
// does without the modulus (expected 4e10 + 101), though the wrapped value keeps the position's
// rounding (101.24120330810547); a tenth of a count beyond fails, on both sides.
TEST(EdgeAtPosition, FarFromZeroWithAModulusTheLimitIsTheSameAsWithout) {
  const std::vector<Edge> e{{1_ms, Level::High}};
  const double turns = 4e10;
  for (const double beyond : {0.0, 0.1}) {
    SCOPED_TRACE(beyond);
    const Outcome want = beyond == 0.0 ? Outcome::Pass : Outcome::Fail;
    const EdgeAtPositionSpec wrapped{.name = "on", .position = 101.0, .tolerance = 0.2412, .modulus = 4096.0};
    const EdgeAtPositionSpec plain{.name = "on", .position = turns + 101.0, .tolerance = 0.2412};
    EXPECT_EQ(check_edge_at_position(e, constant(turns + 101.2412 + beyond), {}, wrapped).outcome(), want);
    EXPECT_EQ(check_edge_at_position(e, constant(turns + 101.2412 + beyond), {}, plain).outcome(), want);
    EXPECT_EQ(check_edge_at_position(e, constant(turns + 100.7588 - beyond), {}, wrapped).outcome(), want);
    EXPECT_EQ(check_edge_at_position(e, constant(turns + 100.7588 - beyond), {}, plain).outcome(), want);
  }
}

TEST(Advance, NoEdgeIsAMissingEdgeFailure) {
  const std::vector<Edge> e{{1_ms, Level::Low}};
  const auto r = check_advance(e, ramp(1000.0), constant(1000.0), {.name = "a", .setpoint = 100.0});
  EXPECT_EQ(r.outcome(), rig::Outcome::Fail);
  EXPECT_NE(find(r, "a.edges").detail.find("missing edge"), std::string::npos);
}

TEST(EdgeAtPosition, EveryEdgeOfTheLevelWithinTolerance) {
  // Low edges (output off) expected at 250 ± 1 counts: 250 and 251 pass, 252 and 301 fail.
  const EdgeAtPositionSpec spec{.name = "off", .level = Level::Low, .position = 250.0, .tolerance = 1.0};
  // At 1 count/ms the low edges at 250 ms and 301 ms fired at 250 and 301 counts.
  const std::vector<Edge> e{
      {100_ms, Level::High}, {250_ms, Level::Low}, {300_ms, Level::High}, {301_ms, Level::Low}};
  const auto r = check_edge_at_position(e, ramp(1000.0), {}, spec);
  EXPECT_EQ(find(r, "off.edges").value, 2.0);
  EXPECT_EQ(find(r, "off.edge0").outcome, rig::Outcome::Pass);
  EXPECT_EQ(find(r, "off.edge1").outcome, rig::Outcome::Fail);
  const std::vector<Edge> ok{{251_ms, Level::Low}};
  EXPECT_EQ(check_edge_at_position(ok, ramp(1000.0), {}, spec).outcome(), rig::Outcome::Pass);
  const std::vector<Edge> over{{252_ms, Level::Low}};
  EXPECT_EQ(check_edge_at_position(over, ramp(1000.0), {}, spec).outcome(), rig::Outcome::Fail);
}

// from_us / to_us: only the edges in [from, to] (both inclusive, as every limit) are judged; an
// edge 1 ns outside either end is not. A span with no edge judged nothing: a missing edge.
TEST(EdgeAtPosition, JudgesOnlyTheEdgesInItsTimeSpan) {
  EdgeAtPositionSpec spec{.name = "off", .level = Level::Low, .position = 250.0, .tolerance = 1.0};
  // At 1 count/ms: the low edge at 250 ms fired at 250 counts (inside), the one at 301 ms at 301.
  const std::vector<Edge> e{{250_ms, Level::Low}, {301_ms, Level::Low}};
  spec.to = 301_ms - Nanos{1};
  auto r = check_edge_at_position(e, ramp(1000.0), {}, spec);
  EXPECT_EQ(find(r, "off.edges").value, 1.0);
  EXPECT_EQ(r.outcome(), rig::Outcome::Pass);
  spec.to = 301_ms; // inclusive: the late edge is judged, and fails
  r = check_edge_at_position(e, ramp(1000.0), {}, spec);
  EXPECT_EQ(find(r, "off.edges").value, 2.0);
  EXPECT_EQ(r.outcome(), rig::Outcome::Fail);
  spec.to.reset();
  spec.from = 250_ms + Nanos{1}; // only the late edge
  r = check_edge_at_position(e, ramp(1000.0), {}, spec);
  EXPECT_EQ(find(r, "off.edges").value, 1.0);
  EXPECT_EQ(r.outcome(), rig::Outcome::Fail);
  spec.from = 250_ms; // inclusive
  EXPECT_EQ(find(check_edge_at_position(e, ramp(1000.0), {}, spec), "off.edges").value, 2.0);
  spec.from = 260_ms;
  spec.to = 300_ms; // no edge in the span
  r = check_edge_at_position(e, ramp(1000.0), {}, spec);
  EXPECT_EQ(r.outcome(), rig::Outcome::Fail);
  EXPECT_NE(find(r, "off.edges")
                .detail.find("missing edge: no low edge on the output from 260000000 ns to "
                             "300000000 ns"),
            std::string::npos)
      << find(r, "off.edges").detail;
}

// A detail sentence must not read a failing value as its limit, nor print "- -" or "-0".
// The 4501's Cycle Output answers its input one throughput time late (125 us, seeds/001
// L281); at 40,000 counts/s (600 rpm, 1000 lines x 4) a board 1 ns slower fires 0.00004
// counts beyond position 45: to 3 decimals "45.000", its limit.
TEST(EdgeAtPosition, DetailTellsAFailingValueFromItsLimit) {
  const EdgeAtPositionSpec spec{.name = "pos", .position = 45.0, .tolerance = 0.0};
  const std::vector<Edge> late{{1'125'001_ns, Level::High}}; // 45.00004 / 40,000 s
  const auto r = check_edge_at_position(late, ramp(40'000.0), constant(40'000.0), spec);
  EXPECT_EQ(r.outcome(), rig::Outcome::Fail);
  const std::string& d = find(r, "pos.edge0").detail;
  EXPECT_NE(d.find("fired at 45.00004"), std::string::npos) << d;
  // Reverse motion with no advance: the advance is -0 counts, read as 0, subtracted once.
  const AdvanceSpec adv{.name = "adv", .setpoint = -125.0, .advance = 0_ms, .tolerance = 0.0};
  const std::vector<Edge> at{{3'125'000_ns, Level::High}}; // -125 counts at -40,000 counts/s
  const auto a = check_advance(at, ramp(-40'000.0), constant(-40'000.0), adv);
  const std::string& ad = find(a, "adv.edge0").detail;
  EXPECT_EQ(a.outcome(), rig::Outcome::Pass) << ad;
  EXPECT_EQ(ad.find("- -"), std::string::npos) << ad;
  EXPECT_EQ(ad.find("-0 "), std::string::npos) << ad;
  EXPECT_NE(ad.find("-125 - 0 (speed -40000 counts/s) = -125"), std::string::npos) << ad;
}

} // namespace
} // namespace hilrig::checks
