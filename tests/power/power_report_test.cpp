// The power table a person reads: a value that failed one ns beyond its limit must not print
// as the limit itself, nor its margin as 0. Values from the shipped ans1_timed campaign's
// to_timer row (a 21 ms pulse, limit 21000 us, docs/power.md): the output_off_skew threshold
// 1000.001 us makes the pulse 21000.001 us, 1 ns too long.

#include <gtest/gtest.h>

#include <string>

#include "rig/power/power.hpp"
#include "rig/power/power_report.hpp"

namespace hilrig::power {
namespace {

PowerResult one_row(double threshold, double last_pass, double measured, double limit) {
  PowerRow r;
  r.check = "to_timer";
  r.kind = "pulse_width";
  r.knob = "output_off_skew";
  r.knob_unit = "us";
  r.direction = "up";
  r.nominal = 0.0;
  r.threshold = threshold;
  r.last_pass = last_pass;
  r.measurement = "to_timer.longest";
  r.measured = measured;
  r.limit = limit;
  r.unit = "us";
  r.margin_pct = (measured - limit) / limit * 100.0;
  return PowerResult{"c", "ans1", 5, {r}};
}

TEST(PowerReport, AValueOneNanosecondBeyondItsLimitReadsBeyondIt) {
  const PowerResult r = one_row(1000.001, 1000.0, 21000.001, 21000.0);
  const std::string text = to_power_text(r);
  EXPECT_NE(text.find(" 21000.001 us"), std::string::npos) << text;
  EXPECT_NE(text.find(" 1000.001 us"), std::string::npos) << text;
  EXPECT_NE(text.find(" 4.762e-06 %"), std::string::npos) << text; // 0.001 / 21000 x 100
  EXPECT_EQ(text.find("0.0000 %"), std::string::npos) << text;
  const std::string html = to_power_html(r);
  for (const char* cell : {"<td>21000.001 us</td>", "<td>1000.001 us</td>", "<td>4.762e-06 %</td>"})
    EXPECT_NE(html.find(cell), std::string::npos) << cell << "\n" << html;
}

// Far from the limit the numbers keep 6 significant digits; the margin 4.
TEST(PowerReport, AValueFarFromItsLimitKeepsSixDigits) {
  const std::string text = to_power_text(one_row(1000.0009765625, 999.0, 21010.000123, 21000.0));
  EXPECT_NE(text.find(" 21010 us"), std::string::npos) << text;
  EXPECT_NE(text.find(" 1000 us"), std::string::npos) << text; // differs from 999 at 6 digits
  EXPECT_NE(text.find(" 0.04762 %"), std::string::npos) << text;
}

// Below a lower limit the same: 18999.999 against 19000 (the down row).
TEST(PowerReport, AValueJustUnderALowerLimitReadsUnderIt) {
  const std::string text = to_power_text(one_row(-1000.001, -1000.0, 18999.999, 19000.0));
  EXPECT_NE(text.find("18999.999 us"), std::string::npos) << text;
  EXPECT_NE(text.find("-1000.001 us"), std::string::npos) << text;
}

} // namespace
} // namespace hilrig::power
