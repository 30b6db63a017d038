// `hilrig run` as a user meets it: the exit status (0 passed, 1 a check failed, 2 bad
// input, 3 rig fault), the files it writes, and --shard.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "rig/cli/run_command.hpp"
#include "rig/results/results_json.hpp"
#include "test_support.hpp"
#include "tests/tools/scratch_files.hpp"

namespace hilrig::cli {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) { return hilrig::test::scratch_dir("campaign", name); }
using hilrig::test::write_file;

int run(const std::string& file, const fs::path& out, std::string* err_text = nullptr,
        const std::string& shard = "0/1") {
  std::ostringstream err;
  RunOptions o;
  o.file = file;
  o.out = out;
  o.shard = shard;
  const int status = run_campaign(o, err);
  if (err_text != nullptr) *err_text = err.str();
  return status;
}

TEST(RunCommand, PassingCampaignExitsZeroAndWritesItsFiles) {
  const fs::path out = scratch("pass");
  EXPECT_EQ(run(campaign::test::shipped("reference_pls_pass.toml"), out), 0);
  for (const char* f : {"results.json", "junit.xml", "report.html", "trace.vcd"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  EXPECT_FALSE(fs::exists(out / "can.log")); // no CAN in this campaign
  const rig::CampaignResult r = rig::read_results_file(out / "results.json");
  EXPECT_EQ(r.runs.size(), 4U);
  EXPECT_EQ(r.verdict, rig::Outcome::Pass);
}

TEST(RunCommand, FaultCampaignWithEveryFaultCaughtExitsZero) {
  EXPECT_EQ(run(campaign::test::shipped("reference_pls_faults.toml"), scratch("faults")), 0);
}

TEST(RunCommand, FailedCheckExitsOne) {
  // The late variant as the DUT itself: every latency is over the 250 us limit.
  const fs::path dir = scratch("fail");
  std::string text = campaign::test::kPlsCampaign;
  text.replace(text.find("model = \"reference_pls\""), 23, "model = \"reference_pls\"\nvariant = \"late\"");
  const fs::path file = write_file(dir, "late.toml", text);
  EXPECT_EQ(run(file.string(), dir / "out"), 1);
  // A run that failed leaves its trace as evidence.
  EXPECT_TRUE(fs::exists(dir / "out" / "trace-run0.vcd"));
}

TEST(RunCommand, BadFileExitsTwoWithFileLineColumnKey) {
  const fs::path dir = scratch("bad");
  std::string text = campaign::test::kPlsCampaign;
  text.replace(text.find("board = \"OUT\""), 13, "board = \"OUT9\"");
  const fs::path file = write_file(dir, "bad.toml", text);
  std::string err;
  EXPECT_EQ(run(file.string(), dir / "out", &err), 2);
  // Line 19 of kPlsCampaign is the third wiring's board; the value starts at column 9.
  EXPECT_EQ(err.rfind(file.string() + ":19:9: wiring[2].board:", 0), 0U) << err;
  EXPECT_FALSE(fs::exists(dir / "out" / "results.json")); // nothing ran
}

TEST(RunCommand, BadShardExitsTwo) {
  EXPECT_EQ(run(campaign::test::shipped("reference_pls_pass.toml"), scratch("shard"), nullptr, "3/3"), 2);
  EXPECT_EQ(run(campaign::test::shipped("reference_pls_pass.toml"), scratch("shard"), nullptr, "1"), 2);
}

TEST(RunCommand, ShardRunsOnlyItsRuns) {
  const fs::path out = scratch("shard1of3");
  EXPECT_EQ(run(campaign::test::shipped("reference_pls_pass.toml"), out, nullptr, "1/3"), 0);
  const rig::CampaignResult r = rig::read_results_file(out / "results.json");
  // Runs 0..3; index mod 3 == 1 -> run 1 only.
  ASSERT_EQ(r.runs.size(), 1U);
  EXPECT_EQ(r.runs[0].index, 1U);
  EXPECT_EQ(r.shard.index, 1U);
  EXPECT_EQ(r.shard.count, 3U);
}

TEST(RunCommand, MissingBackendIsARigFaultExitThree) {
  const fs::path dir = scratch("rigfault");
  // An external board needs a hardware backend this build does not drive.
  const std::string text = R"([campaign]
name = "external"
end = "10ms"
[dut]
model = "external"
backend = "gpiod"
pins = { A = "input", OUT = "output" }
[[wiring]]
rig = "enc.A"
board = "A"
)";
  std::string err;
  EXPECT_EQ(run(write_file(dir, "ext.toml", text).string(), dir / "out", &err), 3);
  EXPECT_NE(err.find("rig fault"), std::string::npos) << err;
}

TEST(RunCommand, ParseShard) {
  EXPECT_EQ(parse_shard("0/1"), std::make_pair(std::size_t{0}, std::size_t{1}));
  EXPECT_EQ(parse_shard("2/5"), std::make_pair(std::size_t{2}, std::size_t{5}));
  EXPECT_FALSE(parse_shard("5/5"));
  EXPECT_FALSE(parse_shard("0/0"));
  EXPECT_FALSE(parse_shard("a/2"));
  EXPECT_FALSE(parse_shard("1/2x"));
}

} // namespace
} // namespace hilrig::cli
