// Placing a campaign on a rig: every digital rig line needs its [[gpio.line]]; a missing one
// is bad input at the campaign's [[wiring]] entry, naming both files. So is a resolver on a
// rig without a [can] interface, or host actions the rig cannot carry.

#include <gtest/gtest.h>

#include <string>

#include "rig/campaign/campaign_parser.hpp"
#include "rig/hardware/drive_plan.hpp"
#include "rig/hardware/hardware_backend.hpp"
#include "tests/hardware/loop_campaign.hpp"

namespace hilrig::hardware {
namespace {

using campaign::CampaignError;

std::string without_line(const std::string& text, const std::string& line) {
  const std::size_t at = text.find(line + "\n");
  return text.substr(0, at) + text.substr(at + line.size() + 1);
}

TEST(DrivePlan, OutputsAndInputsInWiringOrder) {
  const campaign::Campaign c = campaign::parse_campaign(test::kLoopCampaign, "loop.toml");
  const RigConfig rig = parse_rig_config(test::kLoopRig, "rig.toml");
  const DrivePlan plan = plan_lines(c.file, c.points.at(0), rig);
  ASSERT_EQ(plan.outputs.size(), 3U);
  EXPECT_EQ(plan.outputs[2].rig, "en");
  EXPECT_EQ(plan.outputs[2].gpio->offset, 2U);
  ASSERT_EQ(plan.inputs.size(), 1U); // the board's output is captured
  EXPECT_EQ(plan.inputs[0].rig, "ls1");
  EXPECT_EQ(plan.inputs[0].gpio->offset, 8U);
  EXPECT_FALSE(plan.resolver);
  EXPECT_FALSE(plan.host);
}

TEST(DrivePlan, MissingGpioLineNamesBothFiles) {
  const campaign::Campaign c = campaign::parse_campaign(test::kLoopCampaign, "loop.toml");
  // The rig has no line for "en" (the campaign's third [[wiring]], at line 16).
  const std::string rig_text = without_line(test::kLoopRig, "[[gpio.line]]\nrig = \"en\"\noffset = 2");
  const RigConfig rig = parse_rig_config(rig_text, "bench/rig.toml");
  try {
    (void)plan_lines(c.file, c.points.at(0), rig);
    FAIL() << "placed a campaign whose rig line has no [[gpio.line]]";
  } catch (const CampaignError& e) {
    EXPECT_EQ(e.file(), "loop.toml");
    EXPECT_EQ(e.where().line, 16U);
    EXPECT_EQ(e.key(), "wiring[2].rig");
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("loop.toml:16:1: wiring[2].rig: ", 0), 0U) << what;
    EXPECT_NE(what.find("bench/rig.toml"), std::string::npos) << what;
    EXPECT_NE(what.find("\"en\" has no [[gpio.line]]"), std::string::npos) << what;
  }
  // The run command checks every scenario before anything moves.
  EXPECT_THROW(check_campaign_on_rig(c, rig), CampaignError);
}

TEST(DrivePlan, HostActionsNeedAHostLinkAndAnAddressableDevice) {
  const std::string with_host = test::kLoopCampaign + "[[host]]\nat = \"1ms\"\nread = 1\nname = \"count\"\n";
  const campaign::Campaign c = campaign::parse_campaign(with_host, "loop.toml");
  const RigConfig no_host = parse_rig_config(test::kLoopRig, "rig.toml");
  try {
    (void)plan_lines(c.file, c.points.at(0), no_host);
    FAIL() << "host actions on a rig without [host]";
  } catch (const CampaignError& e) {
    EXPECT_NE(std::string(e.what()).find("rig.toml has no [host] table"), std::string::npos) << e.what();
  }
  // The reference PLS is a test double with no Modbus register map: the rig cannot reach its words.
  const RigConfig tcp = parse_rig_config(
      test::kLoopRig + "[host]\nlink = \"modbus-tcp\"\naddress = \"127.0.0.1:1502\"\n", "rig.toml");
  try {
    (void)plan_lines(c.file, c.points.at(0), tcp);
    FAIL() << "host actions for a device without a register map";
  } catch (const CampaignError& e) {
    EXPECT_NE(std::string(e.what()).find("\"reference_pls\" is not one"), std::string::npos) << e.what();
  }
}

TEST(DrivePlan, ResolverGoesOutOnTheCanInterface) {
  // The shipped ANS1 resolver campaign: stators SIN/COS (analog) and the output ls1 at line 37.
  const campaign::Campaign c =
      campaign::load_campaign(HILRIG_SOURCE_DIR "/campaigns/ans1/ans1_resolver.toml");
  // Its host actions (the ANS1's words are addressable) go over Modbus TCP.
  const std::string lines = "[gpio]\nchip = \"gpiochip0\"\n[[gpio.line]]\nrig = \"ls1\"\noffset = 8\n"
                            "[host]\nlink = \"modbus-tcp\"\naddress = \"127.0.0.1:1502\"\n";
  // The stators need no GPIO line: the resolver front end on CAN drives them.
  const DrivePlan plan = plan_lines(c.file, c.points.at(0),
                                    parse_rig_config(lines + "[can]\nresolver = \"can0\"\n", "rig.toml"));
  EXPECT_TRUE(plan.resolver);
  EXPECT_TRUE(plan.host);
  EXPECT_TRUE(plan.outputs.empty());
  ASSERT_EQ(plan.inputs.size(), 1U);
  // Without a [can] interface the campaign cannot run there: bad input at its [resolver] table.
  try {
    (void)plan_lines(c.file, c.points.at(0), parse_rig_config(lines, "rig.toml"));
    FAIL() << "a resolver campaign on a rig without [can]";
  } catch (const CampaignError& e) {
    EXPECT_EQ(e.key(), "resolver");
    EXPECT_EQ(e.where().line, 37U);
    EXPECT_NE(std::string(e.what()).find("rig.toml has no [can] resolver interface"), std::string::npos)
        << e.what();
  }
}

} // namespace
} // namespace hilrig::hardware
