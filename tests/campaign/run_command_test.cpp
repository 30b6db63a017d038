// `hilrig run` as a user meets it: the exit status (0 passed, 1 a check failed, 2 bad
// input, 3 rig fault), the files it writes, and --shard.

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/executive.hpp"
#include "rig/campaign/stop_request.hpp"

#include "rig/cli/output_dir.hpp"
#include "rig/cli/run_command.hpp"
#include "rig/results/results_json.hpp"
#include "rig/results/run_log.hpp"
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
[[wiring]]
rig = "ls1"
board = "OUT"
[[check]]
kind = "pulse_width"
name = "out"
line = "ls1"
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

// What the file got wrong is bad input (exit 2) before anything runs, never a rig fault (3):
// each of these was an out-of-memory exit 3, a run that never ended or a crash before.
TEST(RunCommand, OutOfRangeFilesExitTwoBeforeAnythingRuns) {
  const fs::path dir = scratch("ranges");
  struct Case {
    const char* name;
    std::string from;
    std::string to;
    std::string key;
  };
  const std::string base = campaign::test::kPlsCampaign;
  const Case cases[] = {
      {"repeat", "seed = 5", "seed = 5\nrepeat = 100000000",
       ": campaign.repeat: a repetition count in 1 .. 10000"},
      {"speed", "speed_rpm = 600", "speed_rpm = 1e12", ": motion.move[0].speed_rpm: a speed in rpm in"},
      {"scan", "preset = -50", "preset = -50\nscan = \"1ns\"", ": dut.params.scan: a value in 1us .. 100ms"},
      {"nan", "speed_rpm = 600", "speed_rpm = nan", ": motion.move[0].speed_rpm: a finite number"},
  };
  for (const Case& c : cases) {
    std::string text = base;
    ASSERT_NE(text.find(c.from), std::string::npos) << c.name;
    text.replace(text.find(c.from), c.from.size(), c.to);
    const fs::path file = write_file(dir, std::string(c.name) + ".toml", text);
    std::string err;
    EXPECT_EQ(run(file.string(), dir / c.name, &err), 2) << c.name << ": " << err;
    EXPECT_NE(err.find(c.key), std::string::npos) << c.name << ": " << err;
    EXPECT_FALSE(fs::exists(dir / c.name / "results.json")) << c.name;
  }
  std::string err;
  EXPECT_EQ(run(dir.string(), dir / "out", &err), 2) << err;
  EXPECT_NE(err.find("is a directory"), std::string::npos) << err;
}

// A signal that lands after a run finished and before the next started stops the campaign
// there; the message says so instead of calling the last (whole) run "stopped early".
TEST(RunCommand, SignalBetweenRunsIsReportedAsSuch) {
  const campaign::Campaign c = campaign::load_campaign(campaign::test::shipped("reference_pls_pass.toml"));
  ASSERT_GE(c.runs.size(), 2U);
  campaign::Executive exec(c);
  campaign::StopRequest stop;
  exec.stop_on(&stop);
  // The sink runs after each run and before the executive looks at the stop request.
  const rig::CampaignResult r =
      exec.run_all(c.runs, c.seed, rig::Shard{0, 1}, {},
                   [&](const campaign::RunSpec&, const campaign::RunOutput&) { stop.request(SIGTERM); });
  ASSERT_EQ(r.runs.size(), 1U);
  EXPECT_FALSE(r.runs[0].interrupted);
  EXPECT_EQ(r.interrupted, std::optional<std::string>("SIGTERM"));
  const std::string text = interruption_text(r, "out");
  EXPECT_NE(text.find("interrupted by SIGTERM: 1 of 4 run(s) done, the signal landed between runs"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("stopped early"), std::string::npos) << text;
  // A run the signal cut short is still reported as stopped early.
  rig::CampaignResult cut = r;
  cut.runs[0].interrupted = true;
  EXPECT_NE(interruption_text(cut, "out").find("the last stopped early"), std::string::npos);
}

// Streaming the runs: with a recorder the executive keeps no run whatever the run count (the
// memory a campaign holds does not grow with its runs), hands each run to the recorder once,
// and the run log folds into the byte-identical results.json of an in-memory campaign.
TEST(RunCommand, RecordedRunsAreNotHeldAndFoldToTheSameResults) {
  const campaign::Campaign c = campaign::load_campaign(campaign::test::shipped("reference_pls_faults.toml"));
  const fs::path dir = scratch("recorded");
  ASSERT_GE(c.runs.size(), 3U);
  for (std::size_t n = 1; n <= c.runs.size(); ++n) {
    const std::vector<campaign::RunSpec> runs(c.runs.begin(),
                                              c.runs.begin() + static_cast<std::ptrdiff_t>(n));
    const campaign::Executive exec(c);
    const rig::CampaignResult in_memory = exec.run_all(runs, c.seed, rig::Shard{0, 1});
    ASSERT_EQ(in_memory.runs.size(), n);
    std::size_t recorded = 0;
    rig::CampaignResult held;
    {
      rig::RunLog log(dir / rig::kRunLogName, exec.planned(runs, c.seed, rig::Shard{0, 1}));
      held = exec.run_all(runs, c.seed, rig::Shard{0, 1}, {}, {}, [&](const rig::RunResult& run) {
        ++recorded;
        log.append(run);
      });
    }
    EXPECT_EQ(held.runs.size(), 0U) << n; // nothing per run is kept, for any n
    EXPECT_EQ(recorded, n);
    EXPECT_EQ(rig::to_json_text(rig::read_run_log(dir / rig::kRunLogName)), rig::to_json_text(in_memory))
        << n;
  }
}

// `hilrig run` writes results.json from its run log: the same bytes as the in-memory result.
TEST(RunCommand, ResultsJsonIsTheFoldedRunLog) {
  const fs::path out = scratch("folded");
  EXPECT_EQ(run(campaign::test::shipped("reference_pls_pass.toml"), out), 0);
  ASSERT_TRUE(fs::exists(out / rig::kRunLogName));
  const campaign::Campaign c = campaign::load_campaign(campaign::test::shipped("reference_pls_pass.toml"));
  std::ifstream in(out / "results.json", std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), rig::to_json_text(campaign::Executive(c).run_all(c.runs, c.seed, rig::Shard{0, 1})));
}

// --out: an earlier campaign's evidence is removed before the run, so none of it is mistaken
// for this campaign's; a directory with something hilrig does not write is refused (exit 2)
// and left as it was; a directory another run holds is refused (exit 3) and left as it was.
TEST(RunCommand, OutputDirectoryIsCleanLockedAndOnlyHilrigs) {
  const fs::path out = scratch("stale");
  for (const char* f : {"trace-run7.vcd", "can.log", "trace.gtkw", "results.json.tmp", "junit.xml"})
    write_file(out, f, "earlier campaign\n");
  EXPECT_EQ(run(campaign::test::shipped("reference_pls_pass.toml"), out), 0);
  for (const char* f : {"trace-run7.vcd", "can.log", "trace.gtkw", "results.json.tmp"})
    EXPECT_FALSE(fs::exists(out / f)) << f;
  EXPECT_TRUE(fs::exists(out / "junit.xml"));
  EXPECT_TRUE(fs::exists(out / "trace.vcd"));

  const fs::path foreign = scratch("foreign");
  write_file(foreign, "notes.txt", "mine\n");
  write_file(foreign, "trace-run3.vcd", "earlier\n");
  std::string err;
  EXPECT_EQ(run(campaign::test::shipped("reference_pls_pass.toml"), foreign, &err), 2);
  EXPECT_NE(err.find("holds notes.txt, which hilrig run does not write"), std::string::npos) << err;
  EXPECT_TRUE(fs::exists(foreign / "trace-run3.vcd"));
  EXPECT_FALSE(fs::exists(foreign / "results.json"));

  const fs::path busy = scratch("busy");
  {
    const OutputDirectory held(busy); // another run holds it (flock on its own open file)
    EXPECT_EQ(run(campaign::test::shipped("reference_pls_pass.toml"), busy, &err), 3);
    EXPECT_NE(err.find("another hilrig run is writing this directory"), std::string::npos) << err;
    EXPECT_FALSE(fs::exists(busy / "results.json"));
    EXPECT_THROW(OutputDirectory{busy}, OutputBusy);
  }
  EXPECT_EQ(run(campaign::test::shipped("reference_pls_pass.toml"), busy), 0); // released
}

TEST(RunCommand, RunEvidenceIsWhatHilrigWrites) {
  for (const char* name :
       {"results.json", "junit.xml", "report.html", "runs.jsonl", "can.log", "trace.vcd", "trace-run12.vcd",
        "trace-run12.vcd.tmp", "results.json.tmp", "view.gtkw", ".hilrig.lock"})
    EXPECT_TRUE(is_run_evidence(name)) << name;
  for (const char* name :
       {"notes.txt", "campaign.toml", "results.json.bak", "trace.vcd.orig", "tmp", ".tmp", "my.vcd"})
    EXPECT_FALSE(is_run_evidence(name)) << name;
}

} // namespace
} // namespace hilrig::cli
