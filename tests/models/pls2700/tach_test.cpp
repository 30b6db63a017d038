// Tachometer (pls2700.md §4.3, R-T-1..R-T-7; W19): transducer-shaft RPM over the response
// interval, counts * 60 / (8192 * T) rounded to the resolution [I], held between
// refreshes. Shafts start half a raw count past 0 so every expected count is unambiguous.
#include <gtest/gtest.h>

#include <algorithm>

#include "models/pls2700/error_codes.hpp"
#include "pls2700_bench.hpp"
#include "signals/resolver.hpp"

namespace hilrig::models::pls2700 {
namespace {

using namespace hilrig::literals;
using testing::Bench;

constexpr double kHalfCount = 0.5 / 8192.0;

signals::AngleFunction rpm(double value) {
  return signals::angle_at_constant_speed(kHalfCount, value / 60.0);
}

TEST(Pls2700Tach, Code0Is30msAt1Rpm) {
  // 1000 RPM for 30 ms = 0.5 turn = 4096 counts -> 4096 * 60 / (8192 * 0.030) = 1000.
  Bench b(ModelVariant::M2741);
  EXPECT_EQ(b.btw({0x8804, 0x0000}), error::kNone);
  b.shaft(1, rpm(1000.0));
  b.run_until(29'800_us);
  EXPECT_EQ(b.device().tach(1), 0); // not refreshed before the interval ends
  b.run_until(30_ms);
  EXPECT_EQ(b.device().tach(1), 1000);
  EXPECT_EQ(b.btr()[1], 1000);
}

TEST(Pls2700Tach, Codes1And2Are60And120ms) {
  // 500 RPM x 60 ms = 0.5 turn -> 500; 250 RPM x 120 ms = 0.5 turn -> 250.
  Bench b1(ModelVariant::M2741);
  EXPECT_EQ(b1.btw({0x8804, 0x0001}), error::kNone);
  b1.shaft(1, rpm(500.0));
  b1.run_until(59'800_us);
  EXPECT_EQ(b1.device().tach(1), 0);
  b1.run_until(60_ms);
  EXPECT_EQ(b1.device().tach(1), 500);
  Bench b2(ModelVariant::M2741);
  EXPECT_EQ(b2.btw({0x8804, 0x0002}), error::kNone);
  b2.shaft(1, rpm(250.0));
  b2.run_until(119'800_us);
  EXPECT_EQ(b2.device().tach(1), 0);
  b2.run_until(120_ms);
  EXPECT_EQ(b2.device().tach(1), 250);
}

TEST(Pls2700Tach, DefaultCode3Is240msAt1Rpm) {
  // Default code 3 (L376): 1000 RPM x 240 ms = 4 turns = 32768 counts -> 1000.
  Bench b(ModelVariant::M2741);
  b.shaft(1, rpm(1000.0));
  b.run_until(239'800_us);
  EXPECT_EQ(b.device().tach(1), 0);
  b.run_until(240_ms);
  EXPECT_EQ(b.device().tach(1), 1000);
}

TEST(Pls2700Tach, Code4ReportsTenths) {
  // R-T-4: 123.4 RPM x 240 ms = 0.4936 turn = 4043.57 counts; from half a count: raw 4044;
  // 4044 * 600 / (8192 * 0.24) = 1234.13 -> 1234 (= 123.4 RPM).
  Bench b(ModelVariant::M2742);
  EXPECT_EQ(b.btw({0x9804, 0x0004}), error::kNone); // channel 2, 0.1 RPM
  b.hold(1, 0, 360);
  b.shaft(2, rpm(123.4));
  b.run_until(240_ms);
  EXPECT_EQ(b.device().tach(2), 1234);
  EXPECT_EQ(b.btr()[3], 1234);
}

TEST(Pls2700Tach, W19MaximumTenthsValueIs9999) {
  // W19 (L1613): 999.9 RPM x 240 ms = 3.9996 turns = 32764.7 counts -> raw 32765;
  // 32765 * 600 / 1966.08 = 9999.08 -> 9999.
  Bench b(ModelVariant::M2741);
  EXPECT_EQ(b.btw({0x8804, 0x0004}), error::kNone);
  b.shaft(1, rpm(999.9));
  b.run_until(240_ms);
  EXPECT_EQ(b.device().tach(1), 9999);
}

TEST(Pls2700Tach, QuantisesTo1RpmFromThe8192CountValue) {
  // 7.3 RPM x 30 ms = 29.90 counts -> raw 30 -> 30 * 60 / 245.76 = 7.32 -> 7 (one raw count
  // per 30 ms is 0.2441 RPM, §4.3).
  Bench b(ModelVariant::M2741);
  EXPECT_EQ(b.btw({0x8804, 0x0000}), error::kNone);
  b.shaft(1, rpm(7.3));
  b.run_until(30_ms);
  EXPECT_EQ(b.device().tach(1), 7);
}

TEST(Pls2700Tach, ReverseMotionReportsTheMagnitude) {
  // R-T-7 [I]: no sign bit; -1000 RPM at 30 ms reads 1000.
  Bench b(ModelVariant::M2741);
  EXPECT_EQ(b.btw({0x8804, 0x0000}), error::kNone);
  b.shaft(1, signals::angle_at_constant_speed(0.7 + kHalfCount, -1000.0 / 60.0));
  b.run_until(30_ms);
  EXPECT_EQ(b.device().tach(1), 1000);
}

TEST(Pls2700Tach, ValueIsHeldUntilTheNextIntervalEnds) {
  // The shaft stops at 40 ms: the 30..60 ms interval still sees 10 ms of motion, the
  // 60..90 ms interval none. 1000 RPM x 10 ms = 1/6 turn = 1365.33 counts -> raw 1365 ->
  // 1365 * 60 / 245.76 = 333.25 -> 333.
  Bench b(ModelVariant::M2741);
  EXPECT_EQ(b.btw({0x8804, 0x0000}), error::kNone);
  b.shaft(1, [](Nanos t) {
    const double s = std::min(t.seconds(), 0.040);
    return kHalfCount + s * 1000.0 / 60.0;
  });
  b.run_until(59'800_us);
  EXPECT_EQ(b.device().tach(1), 1000);
  b.run_until(60_ms);
  EXPECT_EQ(b.device().tach(1), 333);
  b.run_until(89'800_us);
  EXPECT_EQ(b.device().tach(1), 333);
  b.run_until(90_ms);
  EXPECT_EQ(b.device().tach(1), 0);
}

TEST(Pls2700Tach, ThirtyTwoMillisecondOptionOnSingleChannel) {
  // §7.2 option: 32 ms on 27x1 (L469). 1000 RPM x 32 ms = 0.5333 turn = 4369.07 counts ->
  // raw 4369 -> 4369 * 60 / 262.144 = 999.98 -> 1000 (to the nearest RPM).
  Params p;
  p.tach_32ms_on_single_channel = true;
  Bench b(ModelVariant::M2731, p);
  EXPECT_EQ(b.btw({0x8804, 0x0000}), error::kNone);
  b.shaft(1, rpm(1000.0));
  b.run_until(31'800_us);
  EXPECT_EQ(b.device().tach(1), 0);
  b.run_until(32_ms);
  EXPECT_EQ(b.device().tach(1), 1000);
}

TEST(Pls2700Tach, TachSettingNeverChangesTheUpdatePeriod) {
  // R-T-3 (L377): 50 updates per 10 ms on a 1-channel module (200 us) for every code.
  for (std::uint16_t code = 0; code <= 4; ++code) {
    Bench b(ModelVariant::M2731);
    EXPECT_EQ(b.btw({0x8804, code}), error::kNone);
    b.hold(1, 0, 360);
    b.run_until(10_ms);
    const auto before = b.device().updates();
    b.run_until(20_ms);
    EXPECT_EQ(b.device().updates() - before, 50u) << "code " << code;
  }
}

TEST(Pls2700Tach, TransducerFaultGives8000h) {
  // R-T-6 (L1315).
  Bench b(ModelVariant::M2741);
  auto& r = b.shaft(1, rpm(100.0));
  signals::ResolverFaults f;
  f.excitation_lost = true;
  r.set_faults(f);
  b.run_until(1_ms);
  EXPECT_EQ(b.btr()[1], 0x8000);
}

// The spec page's ranges (L479-L480): 1..2000 RPM at codes 0-2 (30, 60, 120 ms), 1..1000 at
// code 3 (240 ms), 0.1..999.9 at code 4 (240 ms, tenths); resolution 1 or 0.1 RPM (L374,
// L473-L475). A steady shaft at the range's low end and at a round speed inside reads that
// speed in every interval, whichever phase the counts fall at: 1 RPM is 4.096 counts in 30 ms
// (4 or 5: 0.977 or 1.221 RPM), 8.19 / 16.38 / 32.77 in 60 / 120 / 240 ms; 0.1 RPM 3.28 counts
// in 240 ms (3 or 4: 0.92 or 1.22 tenths); 100 RPM 409.6 counts in 30 ms (99.85 or 100.10).
// Each rounds to the true value; floored, 1 RPM read 0 and 100 RPM 99 every other interval.
TEST(Pls2700Tach, SteadySpeedsAtTheRangesLowEndReadTheirValueInEveryInterval) {
  struct Case {
    int code;
    double rpm;
    std::uint16_t reads;
  };
  const Case cases[] = {{0, 1.0, 1},       {1, 1.0, 1},       {2, 1.0, 1},     {3, 1.0, 1},
                        {4, 0.1, 1},       {4, 1.0, 10},      {0, 100.0, 100}, {1, 100.0, 100},
                        {0, 2000.0, 2000}, {3, 1000.0, 1000}, {4, 999.9, 9999}};
  for (const Case& c : cases) {
    for (const double phase : {0.05, 0.35, 0.65, 0.95}) { // where in a count the shaft starts
      SCOPED_TRACE(::testing::Message() << "code " << c.code << ", " << c.rpm << " rpm, phase " << phase);
      Bench b(ModelVariant::M2741);
      EXPECT_EQ(b.btw({0x8804, static_cast<std::uint16_t>(c.code)}), error::kNone);
      b.shaft(1, signals::angle_at_constant_speed(phase / 8192.0, c.rpm / 60.0));
      const Nanos interval = tach_interval(c.code, false);
      for (int k = 1; k <= 6; ++k) {
        b.run_until(interval * k);
        EXPECT_EQ(b.device().tach(1), c.reads) << "interval " << k;
      }
    }
  }
}

} // namespace
} // namespace hilrig::models::pls2700
