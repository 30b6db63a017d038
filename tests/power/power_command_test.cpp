// `hilrig power` as the command line runs it: bad input before anything runs (a hardware
// campaign, an unknown --check), --max-margin gating the exit status, power.json written with
// its format and version, and checks without a knob named, never left out.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "rig/cli/exit_status.hpp"
#include "rig/cli/power_command.hpp"

namespace hilrig::cli {
namespace {

const std::string kSource = HILRIG_SOURCE_DIR;

std::filesystem::path scratch() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const auto dir = std::filesystem::path(::testing::TempDir()) / "power_command" / info->name();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(PowerCommand, AHardwareCampaignIsBadInput) {
  const auto dir = scratch();
  std::string text = read(kSource + "/campaigns/ans1/ans1_throughput.toml");
  const std::string dut = "[dut]\nmodel = \"ans1\"\n";
  ASSERT_NE(text.find(dut), std::string::npos);
  text.replace(text.find(dut), dut.size(), dut + "backend = \"hardware\"\n");
  std::ofstream(dir / "hw.toml") << text;
  PowerOptions o;
  o.file = (dir / "hw.toml").string();
  std::ostringstream out, err;
  EXPECT_EQ(power_campaign(o, out, err), kBadInput);
  EXPECT_NE(err.str().find("virtual"), std::string::npos) << err.str();
  EXPECT_EQ(out.str(), "");
}

TEST(PowerCommand, AnUnknownCheckIsBadInput) {
  PowerOptions o;
  o.file = kSource + "/campaigns/ans1/ans1_throughput.toml";
  o.checks = {"of"};
  std::ostringstream out, err;
  EXPECT_EQ(power_campaign(o, out, err), kBadInput);
  EXPECT_NE(err.str().find("did you mean"), std::string::npos) << err.str();
}

// The "on" check reads at most 1 ns beyond 20 us at its threshold (power_ans1_test.cpp): a
// margin of at most 0.005 % and a board worst case at most one 0.1 us phase bin (0.5 %) beyond 20 us,
// so the gate --max-margin 1 passes (the failing side is tested on a check without a knob below, and
// over_margin() in power_ans1_test.cpp).
TEST(PowerCommand, MaxMarginGatesTheExitStatusAndPowerJsonIsWritten) {
  const auto dir = scratch();
  PowerOptions o;
  o.file = kSource + "/campaigns/ans1/ans1_throughput.toml";
  o.checks = {"on"};
  o.out = dir;
  o.max_margin_pct = 1.0;
  std::ostringstream out, err;
  EXPECT_EQ(power_campaign(o, out, err), kPassed) << err.str();
  EXPECT_NE(out.str().find("output_delay"), std::string::npos) << out.str();
  EXPECT_NE(err.str().find("power: ans1-throughput: on: output_delay"), std::string::npos); // progress
  const auto doc = nlohmann::json::parse(read(dir / "power.json"));
  EXPECT_EQ(doc.at("format"), "hilrig-power");
  EXPECT_EQ(doc.at("version"), 1);
  ASSERT_EQ(doc.at("checks").size(), 2u); // up against limit_us, down against min_limit_us
  EXPECT_EQ(doc.at("checks")[0].at("knob"), "output_delay");
  EXPECT_EQ(doc.at("checks")[1].at("direction"), "down");
  EXPECT_TRUE(std::filesystem::exists(dir / "power.html"));
}

// A check with no knob (a value check: a word, not a timing) is in the table with its reason,
// and fails a --max-margin gate.
TEST(PowerCommand, ACheckWithoutAKnobIsNamedNotOmitted) {
  PowerOptions o;
  o.file = kSource + "/campaigns/ssi7361/ssi7361_data_types.toml";
  o.max_margin_pct = 100.0;
  std::ostringstream out, err;
  EXPECT_EQ(power_campaign(o, out, err), kCheckFailed);
  EXPECT_NE(out.str().find("no knob: a value check"), std::string::npos) << out.str();
  EXPECT_NE(err.str().find("no margin"), std::string::npos) << err.str();
}

} // namespace
} // namespace hilrig::cli
