// An SSI transducer on a plant (campaigns/ssi7361/ssi7361_plant.toml): the rig's [ssi]
// transducer answers the 7361's clock with a coasting rotary axis's angle, and the 7361's Data
// Value at every read is the closed form of the axis, latched at the frame's first falling edge.

#include <cmath>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "rig/campaign/campaign_error.hpp"
#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/executive.hpp"
#include "test_support.hpp"

namespace hilrig::campaign {
namespace {

using rig::Outcome;

const std::string kSsiPlantFile = test::campaign_dir("ssi7361") + "/ssi7361_plant.toml";

// By hand (the file's comments): J = 0.01 kg·m², b = 0.1 N·m·s/rad, tau = 0.1 s, w0 = 2 pi rad/s:
// angle(t) = 0.1 (1 - e^(-t / tau)) turn; a 12-bit single-turn transducer reads
// floor(4096 x angle). The 7361 (ssi7361 manual seeds/004_2d8564fc60a2b9d4.txt:1085, 1090,
// 1123) latches at F1 = 0.1 ms + k x 0.5 ms and has the 25 bits 200 us later, so a read at a
// whole ms R sees the frame latched at R - 0.4 ms.
double counts_at(double t_s) { return 4096.0 * 0.1 * (1.0 - std::exp(-t_s / 0.1)); }

TEST(SsiPlant, TheShippedCampaignReadsWhatTheClosedFormSays) {
  EXPECT_EQ(std::floor(counts_at(0.0096)), 37.0);
  EXPECT_EQ(std::floor(counts_at(0.0996)), 258.0);
  EXPECT_EQ(std::floor(counts_at(0.9996)), 409.0);
  const rig::CampaignResult r = test::run_everything(load_campaign(kSsiPlantFile));
  ASSERT_EQ(r.runs.size(), 1U);
  EXPECT_EQ(r.verdict, Outcome::Pass) << test::failures(r);
}

// Every 10 ms over the whole coast: each read is the closed form at its latch, to the count.
TEST(SsiPlant, EveryReadIsTheAxisAngleAtItsLatch) {
  std::string text = test::read_file(kSsiPlantFile);
  const std::size_t from = text.find("[[host]]\nat = \"10ms\"");
  const std::size_t to = text.find("[[check]]");
  ASSERT_NE(from, std::string::npos);
  ASSERT_NE(to, std::string::npos);
  std::string reads;
  for (int ms = 10; ms <= 1000; ms += 10)
    reads += fmt::format("[[host]]\nat = \"{}ms\"\nread = 1\nname = \"dv_{}ms\"\n\n", ms, ms);
  text.replace(from, to - from, reads);
  const Campaign c = parse_campaign(text, "reads.toml");
  const RunOutput out = Executive(c).run(c.runs[0]);
  double last = -1.0;
  for (int ms = 10; ms <= 1000; ms += 10) {
    const rig::Observation* o = test::find_observation(out.result, fmt::format("dv_{}ms", ms));
    ASSERT_NE(o, nullptr) << ms;
    const double exact = counts_at((ms - 0.4) / 1e3);
    ASSERT_GT(exact - std::floor(exact), 1e-6) << ms << ": too close to a count to judge";
    EXPECT_EQ(o->value, std::floor(exact)) << ms << " ms: " << exact;
    EXPECT_GE(o->value, last); // coasting forward
    last = o->value;
  }
}

// Bad input before anything runs: a data line a stimulus also drives, a clock line that is not
// the board's output, a position that does not fit the data field.
TEST(SsiPlant, BadSsiTablesAreRefusedWithTheirKey) {
  const std::string base = test::read_file(kSsiPlantFile);
  const auto error_of = [&](const std::string& from, const std::string& to) {
    std::string t = base;
    const std::size_t at = t.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    t.replace(at, from.size(), to);
    try {
      (void)parse_campaign(t, "t.toml");
      return std::string("accepted");
    } catch (const CampaignError& e) {
      return std::string(e.what());
    }
  };
  EXPECT_NE(error_of("clock = \"ssi.clk\"", "clock = \"ssi.data\"").find("ssi.clock"), std::string::npos);
  EXPECT_NE(error_of("counts_per_turn = 4096", "counts_per_turn = 4097").find("ssi.counts_per_turn"),
            std::string::npos);
  EXPECT_NE(error_of("data_bits = 12", "data_bits = 26").find("ssi.data_bits"), std::string::npos);
  EXPECT_NE(error_of("\n[ssi]\n",
                     "\n[[stimulus]]\nkind = \"level\"\nat = \"0ms\"\nline = \"ssi.data\"\nlevel = "
                     "\"high\"\n\n[ssi]\n")
                .find("ssi.data"),
            std::string::npos);
}

// [ssi] monoflop is longer than half a period of the 7361's slower clock and at most 1 ms: every
// clock edge retriggers the monoflop, and the clock's edges are T/2 apart (T = 8 us at 125 kHz,
// manual L1123; the 7361 may be set to 125 or 500 kHz at run time, L2150-2152), so a TM of at most
// 4 us returns DATA to idle inside a frame and the 7361 reads all ones. 4.001 us still reads the
// closed form, at 125 kHz as the shipped campaign runs.
TEST(SsiPlant, MonoflopIsLongerThanHalfTheSlowerClocksPeriod) {
  const std::string base = test::read_file(kSsiPlantFile);
  const auto with_monoflop = [&](const std::string& tm) {
    std::string t = base;
    const std::string code = "code = \"binary\"\n";
    const std::size_t at = t.find(code);
    EXPECT_NE(at, std::string::npos);
    t.insert(at + code.size(), "monoflop = \"" + tm + "\"\n");
    return t;
  };
  for (const char* bad : {"4us", "3.999us", "1ns", "1000.001us"}) {
    try {
      (void)parse_campaign(with_monoflop(bad), "t.toml");
      ADD_FAILURE() << bad << " accepted";
    } catch (const CampaignError& e) {
      EXPECT_EQ(e.key(), "ssi.monoflop") << bad;
      EXPECT_EQ(
          e.expected().rfind("a monoflop time above 4us (half a period of the 7361's slower clock, "
                             "125 kHz: at or below it DATA returns to idle inside a frame), at most 1ms",
                             0),
          0U)
          << e.what();
    }
  }
  for (const char* good : {"4.001us", "1ms"})
    EXPECT_NO_THROW((void)parse_campaign(with_monoflop(good), "t.toml")) << good;
  const rig::CampaignResult r = test::run_everything(parse_campaign(with_monoflop("4.001us"), "t.toml"));
  EXPECT_EQ(r.verdict, Outcome::Pass) << test::failures(r);
}

} // namespace
} // namespace hilrig::campaign
