// A power cycle within a run ([[power_cycle]], issue 17): the parser's typed event and its
// errors (file:line:column: key: what is valid, naming a device whose model has none), and the
// shipped 7361 campaign end to end: it passes on the virtual board, and without its power
// cycle the check that judges what power-up clears fails.

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "campaign_text.hpp"
#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/executive.hpp"
#include "test_support.hpp"

namespace hilrig::campaign {
namespace {

using test::error_of;
using test::rejected_at;
using test::replace_line;

using namespace hilrig::literals;
using rig::Outcome;

// A 7361 campaign with one power cycle, 18 lines; cases replace one line or append lines.
const std::string kSsiPowerCycle = R"([campaign]
name = "t"
end = "50ms"
[dut]
model = "ssi7361"
[[host]]
at = "20ms"
read = 0
name = "status"
[[check]]
kind = "word_bits"
name = "ack"
observation = "status"
mask = 32768
value = 0
[[power_cycle]]
at = "10ms"
off = "5ms"
)";

TEST(PowerCycleParser, BuildsTheTypedEventOnce) {
  const Campaign c = parse_campaign(kSsiPowerCycle, "t.toml");
  ASSERT_EQ(c.points.at(0).power_cycles.size(), 1U);
  const PowerCycleEvent& p = c.points[0].power_cycles[0];
  EXPECT_EQ(p.at, 10_ms);
  EXPECT_EQ(p.off, 5_ms);
  EXPECT_EQ(p.on_at(), 15_ms);
  EXPECT_EQ(p.where.line, 16U);
}

TEST(PowerCycleParser, ADeviceWhoseModelHasNoneIsNamed) {
  EXPECT_TRUE(
      rejected_at(replace_line(kSsiPowerCycle, 5, "model = \"reference_pls\""),
                  "t.toml:17:6: power_cycle[0].at: none: the reference_pls model has no power cycle"));
}

TEST(PowerCycleParser, ARealBoardIsRefused) {
  const std::string external =
      replace_line(kSsiPowerCycle, 5, "model = \"external\"\nbackend = \"gpiod\"\npins = {}");
  EXPECT_TRUE(rejected_at(external, "t.toml:19:6: power_cycle[0].at: a virtual board"));
}

TEST(PowerCycleParser, TheStartLiesWithinTheRunAndTheSupplyIsOffForSomeTime) {
  EXPECT_TRUE(rejected_at(replace_line(kSsiPowerCycle, 17, "at = \"51ms\""),
                          "t.toml:17:6: power_cycle[0].at: a time within"));
  EXPECT_EQ(error_of(replace_line(kSsiPowerCycle, 17, "at = \"50ms\"")), "accepted"); // at the end: inclusive
  EXPECT_TRUE(rejected_at(replace_line(kSsiPowerCycle, 18, "off = \"0ms\""),
                          "t.toml:18:7: power_cycle[0].off: a duration in 1ns .. 3600s"));
  EXPECT_EQ(error_of(replace_line(kSsiPowerCycle, 18, "off = \"1ns\"")), "accepted");
  EXPECT_TRUE(rejected_at(replace_line(kSsiPowerCycle, 18, "of = \"5ms\""),
                          "t.toml:16:1: power_cycle[0].off: missing"));
  // Back on after the run's end: the board stays off to the end.
  EXPECT_EQ(error_of(replace_line(kSsiPowerCycle, 18, "off = \"3600s\"")), "accepted");
}

TEST(PowerCycleParser, ACycleStartsOnlyOnceTheOneAboveIsBackOn) {
  // The first is back on at 15 ms: a second at 15 ms is in order, one at 14.999 ms is not.
  EXPECT_EQ(error_of(kSsiPowerCycle + "[[power_cycle]]\nat = \"15ms\"\noff = \"1ms\"\n"), "accepted");
  EXPECT_TRUE(rejected_at(kSsiPowerCycle + "[[power_cycle]]\nat = \"14999us\"\noff = \"1ms\"\n",
                          "t.toml:20:6: power_cycle[1].at: a time after the power cycle above is back on"));
}

TEST(PowerCycleParser, UnknownKeysAreErrors) {
  EXPECT_TRUE(
      rejected_at(kSsiPowerCycle + "until = \"20ms\"\n", "t.toml:19:1: power_cycle[0].until: unknown key"));
}

// ---- The shipped campaigns, end to end

struct ShippedPowerCycle {
  const char* device;
  const char* file;
  std::set<std::string> judge_the_power_cycle; // checks that fail on a run without it
};

class PowerCycleCampaign : public ::testing::TestWithParam<ShippedPowerCycle> {};

TEST_P(PowerCycleCampaign, PassesAndItsChecksJudgeThePowerCycle) {
  const ShippedPowerCycle& p = GetParam();
  Campaign c = load_campaign(test::campaign_dir(p.device) + "/" + p.file);
  ASSERT_FALSE(c.points.at(0).power_cycles.empty());
  const rig::CampaignResult pass = test::run_everything(c);
  EXPECT_EQ(pass.verdict, Outcome::Pass) << test::failures(pass);
  for (Scenario& s : c.points) s.power_cycles.clear();
  const rig::CampaignResult without = test::run_everything(c);
  std::set<std::string> failed;
  for (const auto& run : without.runs)
    for (const auto& check : run.checks)
      if (check.judgement == rig::Judgement::Fail) failed.insert(check.check);
  EXPECT_EQ(failed, p.judge_the_power_cycle);
}

INSTANTIATE_TEST_SUITE_P(
    Shipped, PowerCycleCampaign,
    // 7361: CMDErr clears only on a valid cycle (seeds/004 L2037) or a power cycle (L254-256,
    // L921-923). 4501: no non-volatile memory, mode 1 at power-up (seeds/001 L176). SMD23E: after
    // a flash save the unit answers nothing until power is cycled (seeds/003 L2331), and loads the
    // saved configuration at power-up (L2235, L2243).
    ::testing::Values(
        ShippedPowerCycle{"ssi7361", "ssi7361_power_cycle.toml", {"errors_cleared"}},
        ShippedPowerCycle{"amci4501", "amci4501_power_cycle.toml", {"mode_1_after_power_up"}},
        ShippedPowerCycle{
            "smd23e", "smd23e_power_cycle.toml", {"flash_configuration_at_power_up", "moves_after_power_up"}},
        // 2700: the OFF space a deleted overlapping pair leaves lasts until power is
        // cycled (seeds/002 L1074); nvRAM keeps the pairs (L776). Without the cycle the
        // module also answers while it should be off.
        ShippedPowerCycle{
            "pls2700", "pls2700_power_cycle.toml", {"no_answer_while_off", "on_after_power_up"}},
        // ANS1: a saved program comes back at power-up, an unsaved change does not (seeds/000
        // L2224, L2236); a latched resolver fault is RAM (L1839, [MODEL]).
        ShippedPowerCycle{"ans1", "ans1_power_cycle.toml", {"fault_gone", "saved_program_at_power_up"}}),
    [](const ::testing::TestParamInfo<ShippedPowerCycle>& p) { return std::string(p.param.device); });

} // namespace
} // namespace hilrig::campaign
