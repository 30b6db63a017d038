// The RT VM lane's campaigns (campaigns/lane/*.toml) on the virtual bus, where they run
// unchanged: each passes, with the figures worked by hand in its header comment (positions
// from the ANS1 digest; 15 counts/s at 2.5 RPM with 360 counts per turn). The lane itself
// (rt-config/vm/payload-e2e.sh) runs them through the kernel's interfaces.
#include <gtest/gtest.h>

#include <string>

#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/executive.hpp"
#include "rig/results/campaign_result.hpp"

namespace hilrig::test {
namespace {

rig::CampaignResult run_lane(const std::string& stem) {
  const campaign::Campaign c =
      campaign::load_campaign(std::string(HILRIG_SOURCE_DIR) + "/campaigns/lane/" + stem + ".toml");
  return campaign::Executive(c).run_all(c.runs, c.seed, rig::Shard{0, 1});
}

const rig::Measurement* find(const rig::CampaignResult& r, const std::string& name) {
  for (const auto& c : r.runs.at(0).checks)
    for (const auto& m : c.measurements)
      if (m.name == name) return &m;
  return nullptr;
}

double value(const rig::CampaignResult& r, const std::string& name) {
  const rig::Measurement* m = find(r, name);
  EXPECT_NE(m, nullptr) << name;
  return m != nullptr ? m->value : -1.0;
}

TEST(LaneCampaigns, EncoderCampaignSwitchesAtItsSetpoints) {
  const rig::CampaignResult r = run_lane("ans1_lane");
  EXPECT_EQ(r.verdict, rig::Outcome::Pass);
  // Each edge within one count of its setpoint (the board: 10..20 us after the crossing).
  EXPECT_NEAR(value(r, "out1_on.edge0"), 10.0, 0.05);
  EXPECT_NEAR(value(r, "out1_off.edge0"), 20.0, 0.05);
  EXPECT_NEAR(value(r, "out2_on.edge0"), 40.0, 0.05);
  EXPECT_NEAR(value(r, "out2_off.edge0"), 50.0, 0.05);
  EXPECT_EQ(value(r, "bit_parameters"), 0x18);
  EXPECT_EQ(value(r, "cpc"), 360.0);
  EXPECT_EQ(value(r, "gmp"), 60.0);
}

TEST(LaneCampaigns, ResolverCampaignPulsesOnceAndRestsAt25) {
  const rig::CampaignResult r = run_lane("ans1_lane_resolver");
  EXPECT_EQ(r.verdict, rig::Outcome::Pass);
  // On from GMP 10 to 20: 10 counts at 15 counts/s = 666.7 ms, each end within a 100 us
  // stator sample and the 12-bit angle's truncation (0.088 counts = 5.9 ms).
  EXPECT_EQ(value(r, "out1_pulse.count"), 1.0);
  EXPECT_NEAR(value(r, "out1_pulse.longest"), 666'667.0, 7'000.0);
  EXPECT_EQ(value(r, "gmp"), 25.0);
  EXPECT_EQ(value(r, "outputs"), 0.0);
}

TEST(LaneCampaigns, BusOffCampaignPassesWhenNothingFaults) {
  // The lane takes can0 off the bus mid-run; undisturbed, the run passes.
  const rig::CampaignResult r = run_lane("ans1_bus_off");
  EXPECT_EQ(r.verdict, rig::Outcome::Pass);
  EXPECT_NEAR(value(r, "out1_on.edge0"), 10.0, 0.1);
}

} // namespace
} // namespace hilrig::test
