// Front-panel actions within a run ([[panel]], issue 17: "Program/Display mode ... where the
// board has them"): the parser's typed event and its errors (file:line:column: key: the
// device's actions, or naming a device that has none), and the shipped Series 2700 campaign end
// to end: it passes, its fault runs (the switch at program from the start, the jumper removed)
// are caught, and without its panel actions the AutoZero checks fail.

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

// A 2741 campaign with one panel action, 18 lines; cases replace one line or append lines.
const std::string kPls = R"([campaign]
name = "t"
end = "50ms"
[dut]
model = "pls2700"
[[host]]
at = "20ms"
read = 0
name = "position"
[[check]]
kind = "word_within"
name = "any"
observation = "position"
lower = 0
upper = 65535
[[panel]]
at = "10ms"
action = "program_mode"
)";

TEST(PanelParser, BuildsTheTypedEventOnce) {
  const Campaign c = parse_campaign(kPls, "t.toml");
  ASSERT_EQ(c.points.at(0).panel.size(), 1U);
  const PanelEvent& p = c.points[0].panel[0];
  EXPECT_EQ(p.name, "program_mode");
  EXPECT_EQ(p.action, 0U);
  EXPECT_EQ(p.at, 10_ms);
}

TEST(PanelParser, AnActionTheDeviceLacksNamesTheValidOnes) {
  EXPECT_TRUE(
      rejected_at(replace_line(kPls, 18, "action = \"run_mode\""),
                  "t.toml:18:10: panel[0].action: a front-panel action of pls2700: one of program_mode, "
                  "display_mode, autozero_1, autozero_2"));
}

TEST(PanelParser, ADeviceWithoutAPanelIsNamed) {
  EXPECT_TRUE(
      rejected_at(replace_line(kPls, 5, "model = \"ssi7361\""),
                  "t.toml:18:10: panel[0].action: none: ssi7361 has no front panel the rig operates"));
}

TEST(PanelParser, TheActionLiesWithinTheRunInTimeOrder) {
  EXPECT_TRUE(
      rejected_at(replace_line(kPls, 17, "at = \"51ms\""), "t.toml:17:6: panel[0].at: a time within"));
  EXPECT_EQ(error_of(replace_line(kPls, 17, "at = \"50ms\"")), "accepted");
  EXPECT_TRUE(rejected_at(kPls + "[[panel]]\nat = \"9ms\"\naction = \"autozero_1\"\n",
                          "t.toml:20:6: panel[1].at: times in order"));
  EXPECT_EQ(error_of(kPls + "[[panel]]\nat = \"10ms\"\naction = \"autozero_1\"\n"), "accepted");
  EXPECT_TRUE(rejected_at(kPls + "key = \"clear\"\n", "t.toml:19:1: panel[0].key: unknown key"));
}

TEST(PanelCampaign, Pls2700ProgramModePassesAndCatchesItsFaults) {
  Campaign c = load_campaign(test::campaign_dir("pls2700") + "/pls2700_program_mode.toml");
  const rig::CampaignResult pass = test::run_everything(c);
  EXPECT_EQ(pass.verdict, Outcome::Pass) << test::failures(pass);
  EXPECT_EQ(pass.totals.faults, 2U);
  EXPECT_EQ(pass.totals.faults_caught, 2U);
  // Without the front panel nothing resets the position (seeds/002_46e90574ec92805f.txt:368): it
  // stays 1024 at 16 and 64 ms, and the quarter turn ends at 2048, not 1024 (50 and 57 ms).
  for (Scenario& s : c.points) s.panel.clear();
  c.faults.clear();
  c.fault_points.clear();
  c.runs = plan_runs(c, c.seed);
  const rig::CampaignResult without = test::run_everything(c);
  std::set<std::string> failed;
  for (const auto& run : without.runs)
    for (const auto& check : run.checks)
      if (check.judgement == rig::Judgement::Fail) failed.insert(check.check);
  EXPECT_EQ(failed, (std::set<std::string>{"program_mode_autozero", "quarter_turn_later",
                                           "locked_in_display_mode", "autozero_after_enable"}));
}

} // namespace
} // namespace hilrig::campaign
