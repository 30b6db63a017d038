// A fault that sets scenario keys (`set = { "key" = value }`): its run is the scenario with
// those keys replaced, so a campaign can expect a fault that lies outside the board (a
// brake too slow for its limit) and name the check that must see it.

#include <gtest/gtest.h>

#include <string>

#include "campaign_text.hpp"
#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/executive.hpp"
#include "test_support.hpp"

namespace hilrig::campaign {
namespace {

using test::error_of;

using namespace hilrig::literals;
using rig::Outcome;
using test::find;

// The press stroke of executive_devices_test (600 rpm, 1.25 turns to the brake at 125 ms):
// braking at 6000 rpm/s stops in 10/100 s = 100 ms; at 2000 rpm/s in 10/(100/3) s = 300 ms.
// With a 120 ms limit the nominal stroke passes and the slow brake must fail it.
const std::string kPress = R"([campaign]
name = "press"
end = "800ms"
[dut]
model = "reference_pls"
[[wiring]]
rig = "enc.A"
board = "A"
[[wiring]]
rig = "enc.B"
board = "B"
[[wiring]]
rig = "brake"
board = "EN"
[encoder]
lines = 100
[motion]
[[motion.move]]
kind = "press_stroke"
speed_rpm = 600
decel_rpm_s = 6000
strokes = 1
brake_at_deg = 90
brake_line = "brake"
[[check]]
kind = "brake_stop_time"
name = "stop"
brake_line = "brake"
limit_ms = 120
)";

TEST(FaultSet, TheFaultRunRunsTheScenarioWithItsKeysReplaced) {
  const std::string text =
      kPress + "[[fault]]\nname = \"slow_brake\"\nset = { \"motion.move[0].decel_rpm_s\" = 2000 }\n"
               "caught_by = \"stop\"\n";
  const Campaign c = parse_campaign(text, "t.toml");
  ASSERT_EQ(c.runs.size(), 2U);
  EXPECT_EQ(c.scenario_of(c.runs[0]).motion.moves.at(0).decel_rpm_s, 6000.0);
  EXPECT_EQ(c.scenario_of(c.runs[1]).motion.moves.at(0).decel_rpm_s, 2000.0);
  const rig::CampaignResult r = test::run_everything(c);
  // Nominal: stop within [100 - 7.1, 100] ms (the last count change comes up to
  // sqrt(2 / 40000) s = 7.1 ms before the exact standstill), under the 120 ms limit.
  const auto* nominal = find(r.runs[0], "stop.stop_time");
  ASSERT_NE(nominal, nullptr);
  EXPECT_LE(nominal->value, 100.0);
  EXPECT_EQ(nominal->outcome, Outcome::Pass);
  // Slow brake: 300 ms less at most sqrt(2 / (400 * 33.3)) s = 12.2 ms: beyond 120 ms, caught.
  const auto* slow = find(r.runs[1], "stop.stop_time");
  ASSERT_NE(slow, nullptr);
  EXPECT_GE(slow->value, 287.0);
  EXPECT_LE(slow->value, 300.0);
  EXPECT_EQ(slow->outcome, Outcome::Fail);
  EXPECT_EQ(r.totals.faults_caught, 1U);
  EXPECT_EQ(r.verdict, Outcome::Pass);
}

TEST(FaultSet, AFaultWithOnlySetKeysNeedsNoVariantOrSignal) {
  // kPress has 29 lines: the [[fault]] header is line 30.
  EXPECT_EQ(
      error_of(kPress + "[[fault]]\nname = \"f\"\ncaught_by = \"stop\"\n"),
      "t.toml:30:1: fault[0].variant: a device variant, a signal = { kind = ... } fault or set = { key = "
      "value }");
}

TEST(FaultSet, AKeyThatIsNotInTheFileIsRejectedAtItsValue) {
  // Line 32 is the set line (kPress has 29): the value 1 is at column 30.
  const std::string text = kPress + "[[fault]]\nname = \"f\"\nset = { \"motion.nothing.x\" = 1 }\n"
                                    "caught_by = \"stop\"\n";
  const std::string got = error_of(text);
  EXPECT_EQ(got.rfind("t.toml:32:30: fault[0].set: ", 0), 0U) << got;
  EXPECT_NE(got.find("fault[0].set"), std::string::npos) << got;
}

TEST(FaultSet, ASetValueOfTheWrongTypeIsRejectedBeforeAnyRun) {
  const std::string text = kPress +
                           "[[fault]]\nname = \"f\"\nset = { \"motion.move[0].decel_rpm_s\" = \"fast\" }\n"
                           "caught_by = \"stop\"\n";
  // The replaced value has no position of its own: the error points at the set table (line
  // 32, column 7) and names the key it was checked as.
  const std::string got = error_of(text);
  EXPECT_EQ(got.rfind("t.toml:32:7: fault[0].set: motion.move[0].decel_rpm_s: ", 0), 0U) << got;
}

TEST(FaultSet, CampaignKeysOtherThanTheEndCannotBeSet) {
  const std::string text = kPress + "[[fault]]\nname = \"f\"\nset = { \"campaign.seed\" = 3 }\n"
                                    "caught_by = \"stop\"\n";
  EXPECT_NE(error_of(text).find("fault[0].set: a key of the scenario"), std::string::npos) << error_of(text);
}

} // namespace
} // namespace hilrig::campaign
