// The first tach value after the Tachometer Response Time is set (pls2700.md §4.3). The
// parameter sets "the time between tachometer updates" (seeds/002_46e90574ec92805f.txt:374):
// every value, the first included, is the motion of one response time T. The module samples
// the position once per update (L377), so the first interval starts at the last update sample
// before the setting and ends T later; counting also the update in progress when the setting
// arrives measures over T + T_upd (999.9 rpm at 0.1 rpm then reads 10007, above the 999.9 rpm
// maximum of Table 1.3, L386).
//
// Expected values: the model [I] (R-T-7) value = count * 60 / (8192 T) / res rounded to the
// nearest unit, with count = the 8192-count motion between the two samples, and the manual's
// bound: the reading is the shaft speed in units of the resolution (L374, L1613), to the
// nearest unit, from whole 8192-count steps, never above the table's maximum (L382-L386).
#include <gtest/gtest.h>

#include <cmath>

#include "models/pls2700/error_codes.hpp"
#include "pls2700_bench.hpp"
#include "signals/resolver.hpp"

namespace hilrig::models::pls2700 {
namespace {

using namespace hilrig::literals;
using testing::Bench;

struct Code {
  int code;
  Nanos interval; // L374, R-T-1 (27x2 figures; code 0 is 30 ms by default, README)
  double resolution;
  double max_rpm; // Table 1.3 (L382-L386) and the range of L479-L480
};

const Code kCodes[] = {
    {0, 30_ms, 1.0, 2000.0},  {1, 60_ms, 1.0, 2000.0}, {2, 120_ms, 1.0, 2000.0},
    {3, 240_ms, 1.0, 1000.0}, {4, 240_ms, 0.1, 999.9},
};

void expect_first_value(ModelVariant model, const Code& c, double rpm, Nanos set_at) {
  const ModelTraits& m = traits(model);
  Bench b(model);
  const auto angle = signals::angle_at_constant_speed(0.5 / 8192.0, rpm / 60.0);
  b.shaft(1, angle);
  if (m.channels == 2) b.shaft(2, angle);
  b.run_until(set_at);
  // Channel 1's TR word: code in the low byte; on a 2-channel module the high byte is the
  // Output Allocation (8 = the default, L1384).
  const auto tr = static_cast<std::uint16_t>((m.channels == 2 ? 0x0800 : 0) | c.code);
  ASSERT_EQ(b.btw({0x8804, tr}), error::kNone);
  const Nanos period = m.update_period;
  const Nanos first_sample{set_at.count() / period.count() * period.count()};
  b.run_until(set_at + c.interval); // the first interval has closed, the second not yet
  const auto raw = [&angle](Nanos t) { return static_cast<std::int64_t>(std::floor(angle(t) * 8192.0)); };
  const std::int64_t count = raw(first_sample + c.interval) - raw(first_sample);
  // rpm = count * 60 / (8192 T), in units of the resolution, to the nearest (T in ns).
  const std::int64_t per_unit = c.resolution < 1.0 ? 10 : 1;
  const auto expected = static_cast<int>(std::llround(
      static_cast<double>(count) * 60.0 * static_cast<double>(per_unit) / (8192.0 * c.interval.seconds())));
  const int value = b.device().tach(1);
  const std::string where = std::string(m.name) + " code " + std::to_string(c.code) + " at " +
                            std::to_string(rpm) + " rpm, set at " + std::to_string(set_at.count()) + " ns";
  EXPECT_EQ(value, expected) << where;
  // The speed in units of the resolution, to the nearest (half an LSB), from a whole number of
  // 8192-count steps (one step more or less: 60 / (8192 T) rpm, digest §4.3 "Model [I]").
  const double step = 60.0 / (8192.0 * c.interval.seconds()) / c.resolution;
  EXPECT_GE(value, rpm / c.resolution - 0.5 - step) << where;
  EXPECT_LE(value, rpm / c.resolution + 0.5 + step) << where;
  EXPECT_LE(value, std::lround(c.max_rpm / c.resolution)) << where;
}

TEST(Pls2700TachFirstValue, EveryCodeNearItsMaximumAndLow) {
  for (ModelVariant model : {ModelVariant::M2741, ModelVariant::M2742, ModelVariant::M2731}) {
    for (const Code& c : kCodes) {
      for (double rpm : {c.max_rpm, c.max_rpm - 0.3, c.max_rpm * 0.5 + 0.17, 3.3}) {
        for (Nanos at : {500'030_us, 500'170_us, 731'111_us}) {
          expect_first_value(model, c, rpm, at);
        }
      }
    }
  }
}

TEST(Pls2700TachFirstValue, W19At999Point9RpmFirstReads9999Or9998) {
  // W19 (L1613): 999.9 rpm at 0.1 rpm = 9999 tenths; 240 ms of it is 32764.7 counts, so the
  // first reading is 9999 or 9998 (never 10007 from 240.2 ms of motion).
  Bench b(ModelVariant::M2741);
  b.shaft(1, signals::angle_at_constant_speed(0.5 / 8192.0, 999.9 / 60.0));
  b.run_until(500'070_us);
  ASSERT_EQ(b.btw({0x8804, 0x0004}), error::kNone);
  b.run_until(740'070_us);
  EXPECT_GE(b.device().tach(1), 9998);
  EXPECT_LE(b.device().tach(1), 9999);
}

TEST(Pls2700TachFirstValue, LongFirstIntervalVariantReadsAboveTheMaximum) {
  // tach_first_interval_long: 240.2 ms of 999.9 rpm = 32,791.9 counts -> 10007 or 10008
  // tenths, above the 9999 of L386 (the figure).
  Bench b(ModelVariant::M2741, Params{}, Fault::TachFirstIntervalLong);
  b.shaft(1, signals::angle_at_constant_speed(0.5 / 8192.0, 999.9 / 60.0));
  b.run_until(500'070_us);
  ASSERT_EQ(b.btw({0x8804, 0x0004}), error::kNone);
  b.run_until(740'300_us); // its first interval closes at the update at 740.2 ms
  EXPECT_GE(b.device().tach(1), 10007);
}

} // namespace
} // namespace hilrig::models::pls2700
