// `hilrig run` as a user meets it: the exit status (0 passed, 1 a check failed, 2 bad
// input, 3 rig fault), the files it writes, --shard, suites of campaigns (--jobs), --only and
// --tag, and `hilrig check`.

#include <sys/stat.h>

#include <gtest/gtest.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <csignal>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>

#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/executive.hpp"
#include "rig/campaign/stop_request.hpp"

#include "rig/cli/check_command.hpp"
#include "rig/cli/output_dir.hpp"
#include "rig/cli/run_command.hpp"
#include "rig/cli/run_progress.hpp"
#include "rig/cli/stop_signals.hpp"
#include "rig/cli/suite_files.hpp"
#include "rig/results/results_json.hpp"
#include "rig/results/run_log.hpp"
#include "test_support.hpp"
#include "tests/tools/scratch_files.hpp"
#include "tests/tools/vcd_reader.hpp"

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
  // The first run's failure trace is its trace.vcd: the same bytes (written once, linked).
  EXPECT_EQ(hilrig::test::read_file(dir / "out" / "trace-run0.vcd"),
            hilrig::test::read_file(dir / "out" / "trace.vcd"));
}

// docs/campaigns.md ("trace.vcd: the full trace of the shard's first run"): the trace ends at
// the campaign's end (300 ms), not at its last change, so a viewer draws the levels held to
// the end. The shaft's last move ends at 300.21 ms, after the end, so nothing changes at
// 300 ms itself: the end is the last time stamp, once, after every change.
TEST(RunCommand, TheTraceEndsAtTheCampaignsEnd) {
  const fs::path out = scratch("trace_end");
  ASSERT_EQ(run(write_file(out, "pass.toml", campaign::test::kPlsCampaign).string(), out / "out"), 0);
  const hilrig::test::Vcd vcd = hilrig::test::read_vcd_file((out / "out" / "trace.vcd").string());
  ASSERT_GE(vcd.times.size(), 2U);
  EXPECT_EQ(vcd.times.back(), 300'000'000);
  EXPECT_LT(vcd.times[vcd.times.size() - 2], 300'000'000);
  for (std::size_t i = 1; i < vcd.times.size(); ++i) EXPECT_LT(vcd.times[i - 1], vcd.times[i]) << i;
}

// --trace: which runs keep their trace files. The campaigns: the inline reference PLS (one
// nominal run, which passes), and the same with a fault run that nothing catches (run 1 fails:
// the fault changes nothing its catcher could see).
std::string failing_second_run() {
  return campaign::test::kPlsCampaign +
         "[[fault]]\nname = \"unseen\"\nset = { \"campaign.end\" = \"300ms\" }\ncaught_by = \"on_latency\"\n";
}

int run_traced(const fs::path& file, const fs::path& out, std::optional<rig::TracePolicy> policy) {
  std::ostringstream err;
  RunOptions o;
  o.file = file.string();
  o.out = out;
  if (policy) o.trace = *policy;
  return run_campaign(o, err);
}

// The trace files in a directory (VCDs and GTKWave save files), by name, with their bytes.
std::map<std::string, std::string> trace_files_in(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string ext = e.path().extension().string();
    if (ext == ".vcd" || ext == ".gtkw")
      files[e.path().filename().string()] = hilrig::test::read_file(e.path());
  }
  return files;
}

std::set<std::string> names_of(const std::map<std::string, std::string>& files) {
  std::set<std::string> names;
  for (const auto& [name, bytes] : files) names.insert(name);
  return names;
}

// Every trace results.json and report.html name is a file in `out`, and every kept trace is
// named by its run: nothing links a trace that was not kept.
void expect_links_only_kept_traces(const fs::path& out) {
  const rig::CampaignResult r = rig::read_results_file(out / "results.json");
  std::set<std::string> linked;
  for (const rig::RunResult& run : r.runs)
    if (!run.trace.empty()) linked.insert(run.trace);
  const std::string report = hilrig::test::read_file(out / "report.html");
  const std::regex href("href=\"([^\"]+\\.vcd)\"");
  for (auto it = std::sregex_iterator(report.begin(), report.end(), href); it != std::sregex_iterator(); ++it)
    EXPECT_TRUE(linked.contains((*it)[1].str())) << (*it)[1].str();
  for (const std::string& f : linked) EXPECT_TRUE(fs::exists(out / f)) << f;
  for (const auto& [name, bytes] : trace_files_in(out)) {
    if (name.ends_with(".vcd")) {
      EXPECT_TRUE(linked.contains(name) || name == "trace.vcd") << name;
    }
  }
  EXPECT_EQ(hilrig::test::read_file(out / "junit.xml").find(".vcd"), std::string::npos);
}

// A check's expected window may begin, or lie wholly, before t = 0: an edge due at a count the
// shaft had passed before the run. The inline reference PLS turned on at count -49, one count
// after the shaft's start at -50 (250 us a count). The trace marks the window from 0 on; the
// verdict is the check's, not a rig fault.
std::string edge_near_start(double position) {
  std::string text = campaign::test::kPlsCampaign;
  text.replace(text.find("on = 100"), 8, "on = -49");
  text.erase(text.find("[[check]]"));
  return text + fmt::format("[[check]]\nkind = \"edge_at_position\"\nname = \"on_edge\"\noutput = \"ls1\"\n"
                            "position = {}\ntolerance_counts = 3\nmin_edges = 1\nto_us = 1000\n",
                            position);
}

TEST(RunTrace, AWindowBeforeTheRunIsMarkedFromZero) {
  const fs::path dir = scratch("window_before_zero");
  // Count -49 at 250 us; seen within a 200 us scan, on the pin 50 us later: at most count -48,
  // inside [-52, -46], whose first 500 us lie before the run.
  const fs::path pass = write_file(dir, "pass.toml", edge_near_start(-49));
  EXPECT_EQ(run(pass.string(), dir / "pass"), 0);
  const std::string vcd = hilrig::test::read_file(dir / "pass" / "trace.vcd");
  // The check's mark rises at #0, inside $dumpvars' block: the window's part after the start.
  std::smatch var;
  ASSERT_TRUE(std::regex_search(vcd, var, std::regex(R"(\$var wire 1 (\S+) on_edge \$end)")));
  EXPECT_NE(vcd.find("$end\n1" + var[1].str() + "\n#"), std::string::npos);
  // [-63, -57] lies wholly before the run: the edge is outside it, a failure, not a rig fault.
  const fs::path fail = write_file(dir, "fail.toml", edge_near_start(-60));
  EXPECT_EQ(run(fail.string(), dir / "fail"), 1);
  EXPECT_TRUE(fs::exists(dir / "fail" / "trace-run0.on_edge.gtkw"));
}

TEST(RunTrace, AllIsTheDefaultAndKeepsTheFirstRunAndEachFailedRun) {
  const fs::path dir = scratch("trace_all");
  const fs::path file = write_file(dir, "mixed.toml", failing_second_run());
  ASSERT_EQ(run_traced(file, dir / "default", std::nullopt), 1);
  ASSERT_EQ(run_traced(file, dir / "all", rig::TracePolicy::All), 1);
  const auto all = trace_files_in(dir / "all");
  EXPECT_EQ(names_of(all),
            (std::set<std::string>{"trace.vcd", "trace-run1.vcd", "trace-run1.on_latency.gtkw"}));
  EXPECT_EQ(trace_files_in(dir / "default"), all); // the same files, byte for byte
  const rig::CampaignResult r = rig::read_results_file(dir / "all" / "results.json");
  EXPECT_EQ(r.trace_policy, rig::TracePolicy::All);
  ASSERT_EQ(r.runs.size(), 2U);
  EXPECT_EQ(r.runs[0].outcome, rig::Outcome::Pass);
  EXPECT_EQ(r.runs[0].trace, "trace.vcd");
  EXPECT_EQ(r.runs[1].outcome, rig::Outcome::Fail);
  EXPECT_EQ(r.runs[1].trace, "trace-run1.vcd");
  expect_links_only_kept_traces(dir / "all");
  EXPECT_NE(hilrig::test::read_file(dir / "all" / "junit.xml")
                .find("<property name=\"trace_policy\" value=\"all\"/>"),
            std::string::npos);
}

TEST(RunTrace, FailedKeepsOnlyTheFailedRunsTraceWithTheBytesOfAll) {
  const fs::path dir = scratch("trace_failed");
  const fs::path file = write_file(dir, "mixed.toml", failing_second_run());
  ASSERT_EQ(run_traced(file, dir / "all", rig::TracePolicy::All), 1);
  ASSERT_EQ(run_traced(file, dir / "failed", rig::TracePolicy::Failed), 1);
  const auto all = trace_files_in(dir / "all");
  const auto failed = trace_files_in(dir / "failed");
  EXPECT_EQ(names_of(failed), (std::set<std::string>{"trace-run1.vcd", "trace-run1.on_latency.gtkw"}));
  for (const auto& [name, bytes] : failed) EXPECT_EQ(bytes, all.at(name)) << name;
  const rig::CampaignResult r = rig::read_results_file(dir / "failed" / "results.json");
  EXPECT_EQ(r.trace_policy, rig::TracePolicy::Failed);
  ASSERT_EQ(r.runs.size(), 2U);
  EXPECT_EQ(r.runs[0].trace, ""); // it passed: nothing kept, nothing linked
  EXPECT_EQ(r.runs[1].trace, "trace-run1.vcd");
  expect_links_only_kept_traces(dir / "failed");
  EXPECT_NE(hilrig::test::read_file(dir / "failed" / "report.html").find("traces kept</th><td>failed"),
            std::string::npos);
}

TEST(RunTrace, FailedFirstRunKeepsTraceVcdAndItsLinkAsAllDoes) {
  // The late variant as the DUT itself: every run fails, the first one too.
  const fs::path dir = scratch("trace_failed_first");
  std::string text = campaign::test::kPlsCampaign;
  text.replace(text.find("model = \"reference_pls\""), 23, "model = \"reference_pls\"\nvariant = \"late\"");
  const fs::path file = write_file(dir, "late.toml", text);
  ASSERT_EQ(run_traced(file, dir / "all", rig::TracePolicy::All), 1);
  ASSERT_EQ(run_traced(file, dir / "failed", rig::TracePolicy::Failed), 1);
  const auto failed = trace_files_in(dir / "failed");
  EXPECT_EQ(names_of(failed),
            (std::set<std::string>{"trace.vcd", "trace-run0.vcd", "trace-run0.on_latency.gtkw"}));
  EXPECT_EQ(failed, trace_files_in(dir / "all"));
  expect_links_only_kept_traces(dir / "failed");
}

TEST(RunTrace, NoneKeepsNoTraceFile) {
  const fs::path dir = scratch("trace_none");
  const fs::path file = write_file(dir, "mixed.toml", failing_second_run());
  ASSERT_EQ(run_traced(file, dir / "none", rig::TracePolicy::None), 1);
  ASSERT_EQ(run_traced(file, dir / "all", rig::TracePolicy::All), 1);
  EXPECT_TRUE(trace_files_in(dir / "none").empty());
  const rig::CampaignResult none = rig::read_results_file(dir / "none" / "results.json");
  const rig::CampaignResult all = rig::read_results_file(dir / "all" / "results.json");
  EXPECT_EQ(none.trace_policy, rig::TracePolicy::None);
  for (const rig::RunResult& run : none.runs) EXPECT_EQ(run.trace, "") << run.index;
  expect_links_only_kept_traces(dir / "none");
  // What was judged does not depend on which traces were kept.
  EXPECT_EQ(none.verdict, all.verdict);
  EXPECT_EQ(none.totals, all.totals);
}

TEST(RunTrace, PassingCampaignKeepsItsTraceOnlyUnderAll) {
  const fs::path dir = scratch("trace_pass");
  const fs::path file = write_file(dir, "pass.toml", campaign::test::kPlsCampaign);
  for (const rig::TracePolicy p : {rig::TracePolicy::All, rig::TracePolicy::Failed, rig::TracePolicy::None}) {
    const fs::path out = dir / rig::to_string(p);
    ASSERT_EQ(run_traced(file, out, p), 0) << rig::to_string(p);
    EXPECT_EQ(names_of(trace_files_in(out)),
              p == rig::TracePolicy::All ? std::set<std::string>{"trace.vcd"} : std::set<std::string>{})
        << rig::to_string(p);
    EXPECT_EQ(rig::read_results_file(out / "results.json").trace_policy, p);
    expect_links_only_kept_traces(out);
  }
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

TEST(RunCommand, HardwareWithoutARigIsBadInputExitTwo) {
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
  // The campaign asks for a rig and the command line names none: the same status as
  // `--backend hardware` without --rig (bad input, nothing runs).
  std::string err;
  EXPECT_EQ(run(write_file(dir, "ext.toml", text).string(), dir / "out", &err), 2);
  EXPECT_NE(err.find("needs --rig RIG.toml"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(dir / "out" / "results.json"));
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
  const rig::CampaignResult r = exec.run_all(c.runs, c.seed, rig::Shard{0, 1}, {},
                                             [&](const campaign::RunSpec&, const campaign::RunOutput&) {
                                               stop.request(SIGTERM);
                                               return std::string{}; // no trace kept
                                             });
  ASSERT_EQ(r.runs.size(), 1U);
  EXPECT_FALSE(r.runs[0].interrupted);
  EXPECT_EQ(r.interrupted, std::optional<std::string>("SIGTERM"));
  const std::string text = interruption_text(r, "out");
  EXPECT_NE(text.find("interrupted by SIGTERM: 1 of 4 run(s) done, the signal landed between runs"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("stopped early"), std::string::npos) << text;
  // A run the signal cut short is reported as stopped early, and not as done: with no run
  // finished before it, none of the 4 is done.
  rig::CampaignResult cut = r;
  cut.runs[0].interrupted = true;
  rig::finalize(cut);
  const std::string cut_text = interruption_text(cut, "out");
  EXPECT_NE(cut_text.find("interrupted by SIGTERM: 0 of 4 run(s) done, and the next stopped early"),
            std::string::npos)
      << cut_text;
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
  // The fold of the run log, plus the wall-clock facts of this run (which can.log's epoch is).
  nlohmann::json written = nlohmann::json::parse(text.str());
  ASSERT_TRUE(written.contains("wall_clock"));
  EXPECT_TRUE(std::regex_match(written["wall_clock"]["started_at"].get<std::string>(),
                               std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)")));
  EXPECT_FALSE(written["wall_clock"]["host"].get<std::string>().empty());
  written.erase("wall_clock");
  // hilrig run keeps the first run's trace (trace.vcd) and names it in that run; the bare
  // executive keeps none.
  ASSERT_EQ(written["runs"][0]["trace"], "trace.vcd");
  for (auto& r : written["runs"]) r.erase("trace");
  EXPECT_EQ(written.dump(), nlohmann::json::parse(rig::to_json_text(campaign::Executive(c).run_all(
                                                      c.runs, c.seed, rig::Shard{0, 1})))
                                .dump());
}

// Traceability (issue 18): the start time, tool version, campaign file and SHA-256, seed, host
// link, backend, DUT serial ([dut] serial) and station (--station) are in results.json, in
// every testsuite's <properties> of junit.xml and in report.html's header table; results.json
// reads back the serial and station as written (round trip). Without them: null, no property,
// "not given".
TEST(RunCommand, TraceabilityInResultsJunitAndReport) {
  const fs::path dir = scratch("traceability");
  std::string text = hilrig::test::read_file(campaign::test::shipped("reference_pls_pass.toml"));
  text.replace(text.find("[dut]\n"), 6, "[dut]\nserial = \"SN-0042 <A&B>\"\n");
  const fs::path file = write_file(dir, "serial.toml", text);
  const campaign::Campaign c = campaign::load_campaign(file.string());
  ASSERT_EQ(c.runs.size(), 4U);
  RunOptions o;
  o.file = file.string();
  o.out = dir / "out";
  o.seed = 99;
  o.station = "bench 7 \"north\"";
  std::ostringstream err;
  ASSERT_EQ(run_campaign(o, err), 0) << err.str();

  const nlohmann::json j = nlohmann::json::parse(hilrig::test::read_file(o.out / "results.json"));
  EXPECT_EQ(j["campaign_file"], file.string());
  EXPECT_EQ(j["campaign_sha256"], c.sha256);
  EXPECT_TRUE(std::regex_match(j["campaign_sha256"].get<std::string>(), std::regex("[0-9a-f]{64}")));
  EXPECT_EQ(j["tool_version"], rig::tool_version());
  EXPECT_EQ(j["seed"], 99);
  EXPECT_EQ(j["dut_serial"], "SN-0042 <A&B>");
  EXPECT_EQ(j["station"], "bench 7 \"north\"");
  EXPECT_EQ(j["host_link"], "in-process");
  EXPECT_EQ(j["backend"], "virtual");
  const std::string started = j["wall_clock"]["started_at"].get<std::string>();
  EXPECT_TRUE(std::regex_match(started, std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)"))) << started;
  const rig::CampaignResult back = rig::read_results_file(o.out / "results.json");
  EXPECT_EQ(back.station, o.station);
  EXPECT_EQ(back.dut_serial, "SN-0042 <A&B>");
  EXPECT_EQ(back.campaign_file, file.string());

  const std::string junit = hilrig::test::read_file(o.out / "junit.xml");
  const auto property = [](const std::string& name, const std::string& value) {
    return "<property name=\"" + name + "\" value=\"" + value + "\"/>";
  };
  for (const std::string& p :
       {property("dut_serial", "SN-0042 &lt;A&amp;B&gt;"), property("station", "bench 7 &quot;north&quot;"),
        property("campaign_file", file.string()), property("campaign_sha256", c.sha256),
        property("campaign_seed", "99"), property("tool_version", rig::tool_version()),
        property("backend", "virtual"), property("host_link", "in-process")})
    EXPECT_EQ(hilrig::test::count_of(junit, p), 4U) << p; // one per run's testsuite
  EXPECT_EQ(hilrig::test::count_of(junit, "timestamp=\"" + started + "\""), 4U);

  const std::string report = hilrig::test::read_file(o.out / "report.html");
  for (const std::string& row :
       {"<tr class=\"wall-clock\"><th>started</th><td>" + started + "</td></tr>",
        "<tr><th>tool version</th><td>hilrig " + std::string(rig::tool_version()) + "</td></tr>",
        "<tr><th>campaign file</th><td>" + file.string() + "</td></tr>",
        "<tr><th>campaign SHA-256</th><td>" + c.sha256 + "</td></tr>",
        std::string("<tr><th>DUT serial</th><td>SN-0042 &lt;A&amp;B&gt;</td></tr>"),
        std::string("<tr><th>station</th><td>bench 7 &quot;north&quot;</td></tr>"),
        std::string("<tr><th>seed</th><td>99</td></tr>"),
        std::string("<tr><th>backend</th><td>virtual</td></tr>"),
        std::string("<tr><th>host link</th><td>in-process</td></tr>")})
    EXPECT_NE(report.find(row), std::string::npos) << row;

  // Neither given: null in results.json, no property, "not given" in the report.
  o.file = campaign::test::shipped("reference_pls_pass.toml");
  o.station.clear();
  ASSERT_EQ(run_campaign(o, err), 0) << err.str();
  const nlohmann::json none = nlohmann::json::parse(hilrig::test::read_file(o.out / "results.json"));
  EXPECT_TRUE(none["dut_serial"].is_null());
  EXPECT_TRUE(none["station"].is_null());
  const std::string junit_none = hilrig::test::read_file(o.out / "junit.xml");
  EXPECT_EQ(junit_none.find("name=\"station\""), std::string::npos);
  EXPECT_EQ(junit_none.find("name=\"dut_serial\""), std::string::npos);
  const std::string report_none = hilrig::test::read_file(o.out / "report.html");
  EXPECT_NE(report_none.find("<tr><th>station</th><td>not given</td></tr>"), std::string::npos);
  EXPECT_NE(report_none.find("<tr><th>DUT serial</th><td>not given</td></tr>"), std::string::npos);
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

  // --out naming a file, or a path through one, is the user's to change: bad input (exit 2),
  // and the file is left as it was (it was a filesystem error, a rig fault, exit 3).
  const fs::path file = scratch("a_file") / "notes.txt";
  write_file(file.parent_path(), "notes.txt", "mine\n");
  for (const fs::path& given : {file, file / "sub"}) {
    EXPECT_EQ(run(campaign::test::shipped("reference_pls_pass.toml"), given, &err), 2) << given;
    EXPECT_NE(err.find("not a directory"), std::string::npos) << err;
    EXPECT_EQ(hilrig::test::read_file(file), "mine\n");
  }
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

TEST(RunCommand, UnknownKeyAndCheckParameterNameTheClosest) {
  const fs::path dir = scratch("did_you_mean");
  std::string text = campaign::test::kPlsCampaign;
  text.replace(text.find("[motion]"), 8, "[motoin]");
  std::string err;
  EXPECT_EQ(run(write_file(dir, "key.toml", text).string(), dir / "out", &err), 2);
  EXPECT_NE(err.find(": motoin: unknown key (expected one of: "), std::string::npos) << err;
  EXPECT_NE(err.find(") (did you mean \"motion\"?)"), std::string::npos) << err;
  text = campaign::test::kPlsCampaign;
  text.replace(text.find("limit_us = 250"), 14, "limt_us = 250");
  EXPECT_EQ(run(write_file(dir, "param.toml", text).string(), dir / "out", &err), 2);
  EXPECT_NE(err.find("check[0].limt_us: a parameter of throughput (one of "), std::string::npos) << err;
  EXPECT_NE(err.find(") (did you mean \"limit_us\"?)"), std::string::npos) << err;
}

// ---- suites ----------------------------------------------------------------------------

// kPlsCampaign as the late variant: every latency is over the 250 us limit (exit 1).
std::string late_campaign(const std::string& name) {
  std::string text = campaign::test::kPlsCampaign;
  text.replace(text.find("name = \"inline\""), 15, "name = \"" + name + "\"");
  text.replace(text.find("model = \"reference_pls\""), 23, "model = \"reference_pls\"\nvariant = \"late\"");
  return text;
}

std::string passing_campaign(const std::string& name) {
  std::string text = campaign::test::kPlsCampaign;
  text.replace(text.find("name = \"inline\""), 15, "name = \"" + name + "\"");
  return text;
}

struct SuiteRun {
  int status = -1;
  std::string out;
  std::string err;
};

SuiteRun run_suite(const std::vector<std::string>& files, const fs::path& out_dir, std::size_t jobs = 1,
                   const campaign::CheckSelection& checks = {}, std::optional<std::int64_t> epoch = {}) {
  RunOptions o;
  o.files = files;
  o.out = out_dir;
  o.jobs = jobs;
  o.checks = checks;
  o.epoch = epoch;
  std::ostringstream out;
  std::ostringstream err;
  SuiteRun r;
  r.status = run_campaigns(o, out, err);
  r.out = out.str();
  r.err = err.str();
  return r;
}

TEST(RunSuite, DirectoryRunsEveryCampaignSortedIntoItsOwnDirectory) {
  const fs::path dir = scratch("suite_dir");
  fs::create_directories(dir / "in" / "sub");
  write_file(dir / "in", "b_pass.toml", passing_campaign("b"));
  write_file(dir / "in" / "sub", "a_pass.toml", passing_campaign("a"));
  write_file(dir / "in", "notes.txt", "not a campaign");
  const SuiteRun r = run_suite({(dir / "in").string()}, dir / "out");
  EXPECT_EQ(r.status, 0) << r.err;
  for (const char* sub : {"b_pass", "sub/a_pass"})
    for (const char* f : {"results.json", "junit.xml", "report.html", "trace.vcd"})
      EXPECT_TRUE(fs::exists(dir / "out" / sub / f)) << sub << "/" << f;
  // One testsuite per campaign, in path order ("b_pass" < "sub/a_pass").
  const std::string junit = hilrig::test::read_file(dir / "out" / "junit.xml");
  EXPECT_EQ(hilrig::test::count_of(junit, "<testsuite "), 2U);
  EXPECT_LT(junit.find("<testsuite name=\"b\""), junit.find("<testsuite name=\"a\""));
  // The index links each campaign's own report.
  const std::string index = hilrig::test::read_file(dir / "out" / "report.html");
  EXPECT_NE(index.find("href=\"b_pass/report.html\""), std::string::npos);
  EXPECT_NE(index.find("href=\"sub/a_pass/report.html\""), std::string::npos);
  // The summary lines and the report's path go to stdout.
  EXPECT_NE(r.out.find("a: 1 run(s), 1 passed"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("suite: 2 campaign(s), 2 passed"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("report: " + (dir / "out" / "report.html").string() + "\n"), std::string::npos)
      << r.out;
  EXPECT_EQ(r.err, "");
}

TEST(RunSuite, ExitStatusIsTheWorstOfTheCampaigns) {
  const fs::path dir = scratch("suite_worst");
  const std::string pass = write_file(dir, "pass.toml", passing_campaign("pass")).string();
  const std::string late = write_file(dir, "late.toml", late_campaign("late")).string();
  const std::string blocked = write_file(dir, "blocked.toml", passing_campaign("blocked")).string();
  // pass + a failed check -> 1, and the failing campaign is first in the index.
  SuiteRun r = run_suite({pass, late}, dir / "out1");
  EXPECT_EQ(r.status, 1) << r.err;
  const std::string index = hilrig::test::read_file(dir / "out1" / "report.html");
  EXPECT_LT(index.find("late/report.html"), index.find("pass/report.html"));
  // + a campaign whose output directory another run holds: a rig fault, 3 (the rig cannot run
  // it now), and the other two still ran and wrote their results.
  {
    const OutputDirectory held(dir / "out3" / "blocked");
    r = run_suite({late, blocked, pass}, dir / "out3");
  }
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_TRUE(fs::exists(dir / "out3" / "late" / "results.json"));
  EXPECT_TRUE(fs::exists(dir / "out3" / "pass" / "results.json"));
  EXPECT_NE(r.err.find("rig fault"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("exit 3 (rig fault)"), std::string::npos) << r.out;
  // + a malformed campaign -> 2, and nothing runs at all (every file is checked first).
  std::string text = passing_campaign("bad");
  text.replace(text.find("board = \"OUT\""), 13, "board = \"OUT9\"");
  const std::string bad = write_file(dir, "bad.toml", text).string();
  r = run_suite({pass, late, bad}, dir / "out2");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind(bad + ":19:9: wiring[2].board:", 0), 0U) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out2" / "pass"));
  EXPECT_FALSE(fs::exists(dir / "out2" / "junit.xml"));
}

// docs/campaigns.md (judgement table): `error`, a check that could not be judged, is not
// `fail`. A suite's summary line and index word exit 1 by the verdict behind it. The
// unjudged campaign's setpoint (5000 counts) is never crossed by a shaft that turns one
// revolution of 400 counts each way, so its check judged nothing.
TEST(RunSuite, ACampaignThatCouldNotBeJudgedIsNotCalledFailed) {
  const fs::path dir = scratch("suite_unjudged");
  std::string text = passing_campaign("unjudged");
  text.replace(text.find("setpoint = 100"), 14, "setpoint = 5000");
  const std::string unjudged = write_file(dir, "unjudged.toml", text).string();
  const std::string pass = write_file(dir, "pass.toml", passing_campaign("pass")).string();
  const std::string late = write_file(dir, "late.toml", late_campaign("late")).string();
  SuiteRun r = run_suite({pass, unjudged}, dir / "out1");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.out.find("suite: 2 campaign(s), 1 passed, 0 with a failed check, 1 with a check that could not "
                       "be judged, 0 bad input, 0 rig fault; exit 1 (a check could not be judged)"),
            std::string::npos)
      << r.out;
  std::string index = hilrig::test::read_file(dir / "out1" / "report.html");
  EXPECT_EQ(index.find("a check failed"), std::string::npos) << index;
  EXPECT_NE(index.find("exit 1 (a check could not be judged)"), std::string::npos) << index;
  EXPECT_NE(index.find("<td class=\"error\">a check could not be judged</td>"), std::string::npos) << index;
  // A failed check beside it: each campaign in its own words, the suite's exit names both.
  r = run_suite({late, unjudged}, dir / "out2");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.out.find("0 passed, 1 with a failed check, 1 with a check that could not be judged"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("exit 1 (a check failed, another could not be judged)"), std::string::npos) << r.out;
  index = hilrig::test::read_file(dir / "out2" / "report.html");
  EXPECT_NE(index.find("<td class=\"fail\">a check failed</td>"), std::string::npos) << index;
  // A failed check alone reads as before.
  r = run_suite({pass, late}, dir / "out3");
  EXPECT_NE(r.out.find("exit 1 (a check failed)\n"), std::string::npos) << r.out;
}

TEST(RunSuite, WorstStatusRanksRigFaultOverBadInputOverFailure) {
  EXPECT_EQ(worst_status(0, 0), 0);
  EXPECT_EQ(worst_status(0, 1), 1);
  EXPECT_EQ(worst_status(2, 1), 2);
  EXPECT_EQ(worst_status(2, 3), 3);
  EXPECT_EQ(worst_status(3, 0), 3);
}

// A *.toml in a suite that cannot be read as a campaign file is bad input, named: skipped, it
// would drop out of the suite and the suite would pass without it. A path that exists but is
// not a regular file is named as such, not as missing.
TEST(RunSuite, AnUnreadableCampaignInASuiteIsBadInputNotSkipped) {
  const fs::path dir = scratch("suite_unreadable");
  fs::remove_all(dir);
  fs::create_directories(dir);
  write_file(dir, "good.toml", passing_campaign("good"));
  fs::create_symlink(dir / "gone.toml.target", dir / "gone.toml");
  SuiteRun r = run_suite({dir.string()}, scratch("suite_unreadable_out"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("gone.toml: a link to nothing, not a campaign file"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(scratch("suite_unreadable_out") / "good" / "results.json"));
  fs::remove(dir / "gone.toml");
  ASSERT_EQ(::mkfifo((dir / "pipe.toml").c_str(), 0600), 0);
  EXPECT_THROW((void)collect_campaigns({dir.string()}), std::invalid_argument);
  try {
    (void)collect_campaigns({(dir / "pipe.toml").string()});
    ADD_FAILURE() << "a FIFO was taken as a campaign file";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("pipe.toml: not a regular file"), std::string::npos) << e.what();
  }
}

TEST(RunSuite, TwoCampaignsWritingOneDirectoryAreBadInput) {
  const fs::path dir = scratch("suite_clash");
  fs::create_directories(dir / "x");
  const std::string a = write_file(dir / "x", "same.toml", passing_campaign("x")).string();
  fs::create_directories(dir / "y");
  const std::string b = write_file(dir / "y", "same.toml", passing_campaign("y")).string();
  EXPECT_THROW((void)collect_campaigns({a, b}), std::invalid_argument);
  const SuiteRun r = run_suite({a, b}, dir / "out");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("would both write to same/"), std::string::npos) << r.err;
  EXPECT_EQ(run_suite({(dir / "nowhere").string()}, dir / "out").status, 2);
}

// Every byte of a directory tree, by relative path.
std::map<std::string, std::string> tree_of(const fs::path& root) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(root))
    if (e.is_regular_file())
      files[e.path().lexically_relative(root).generic_string()] = hilrig::test::read_file(e.path());
  return files;
}

// junit.xml's `time` attributes (the wall time each run took, which --epoch cannot fix), and
// only those, blanked (rig/results/junit.hpp). Its timestamp comes from --epoch, and hostname
// is this machine's in both runs: they are compared as written.
std::string without_wall_durations(const std::string& junit) {
  static const std::regex wall(R"re(\btime="[^"]*")re");
  return std::regex_replace(junit, wall, "time=\"\"");
}

TEST(RunSuite, JobsRunInParallelWithTheSameOutputsAsOneJob) {
  const fs::path dir = scratch("suite_jobs");
  std::vector<std::string> files = {campaign::test::shipped("reference_pls_pass.toml"),
                                    campaign::test::shipped("reference_pls_faults.toml"),
                                    write_file(dir, "late.toml", late_campaign("late")).string(),
                                    write_file(dir, "other.toml", passing_campaign("other")).string()};
  // The same --epoch for both: started_at, junit.xml's timestamp and the report's start row
  // are then the same bytes, and only junit.xml's wall durations differ.
  constexpr std::int64_t kEpoch = 1'767'225'600; // 2026-01-01T00:00:00Z
  const SuiteRun one = run_suite(files, dir / "jobs1", 1, {}, kEpoch);
  const SuiteRun four = run_suite(files, dir / "jobs4", 4, {}, kEpoch);
  EXPECT_EQ(one.status, 1);
  EXPECT_EQ(four.status, 1);
  // The summary lines in suite order, whatever finished first.
  EXPECT_EQ(one.out.substr(0, one.out.find("report: ")), four.out.substr(0, four.out.find("report: ")));
  auto a = tree_of(dir / "jobs1");
  auto b = tree_of(dir / "jobs4");
  ASSERT_EQ(a.size(), b.size());
  std::size_t junit_files = 0;
  for (auto& [path, text] : a) {
    ASSERT_TRUE(b.count(path)) << path;
    if (path.ends_with("junit.xml")) {
      ++junit_files;
      EXPECT_NE(text.find("timestamp=\"2026-01-01T00:00:00Z\""), std::string::npos) << path;
      EXPECT_EQ(without_wall_durations(text), without_wall_durations(b[path])) << path;
    } else {
      EXPECT_EQ(text, b[path]) << path; // byte-identical, results.json's wall_clock included
    }
  }
  EXPECT_EQ(junit_files, 5U); // four campaigns and the suite's
}

TEST(RunSuite, JunitCarriesWallClockOnlyInTimestampHostnameAndTime) {
  const fs::path dir = scratch("suite_wall");
  const SuiteRun r = run_suite({campaign::test::shipped("reference_pls_pass.toml"),
                                write_file(dir, "late.toml", late_campaign("late")).string()},
                               dir / "out");
  EXPECT_EQ(r.status, 1);
  const std::string junit = hilrig::test::read_file(dir / "out" / "junit.xml");
  // A real start time, ISO 8601 UTC to the second, on every testsuite.
  const std::regex stamp(R"re(timestamp="(\d{4})-\d\d-\d\dT\d\d:\d\d:\d\dZ")re");
  EXPECT_EQ(std::distance(std::sregex_iterator(junit.begin(), junit.end(), stamp), std::sregex_iterator()),
            2);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(junit, m, stamp));
  EXPECT_GE(std::stoi(m[1]), 2024);
  EXPECT_EQ(junit.find("hostname=\"\""), std::string::npos);
  // Classnames: "<campaign>.<run>" with no other dot, though the sweep key and value have some
  // ("dut.params.delay='50us'" -> "dut_params_delay='50us'").
  const std::regex classname(R"re(classname="([^"]*)")re");
  std::set<std::string> names;
  for (auto it = std::sregex_iterator(junit.begin(), junit.end(), classname); it != std::sregex_iterator();
       ++it)
    names.insert((*it)[1]);
  EXPECT_TRUE(names.count("reference-pls-pass.dut_params_delay=&#39;50us&#39; rep 0")) << *names.begin();
  for (const std::string& n : names) EXPECT_EQ(hilrig::test::count_of(n, "."), 1U) << n;
  // The failing campaign's testsuite says so, and the counts agree with exit status 1.
  EXPECT_NE(junit.find("<testsuite name=\"late\" tests=\"1\" failures=\"1\" errors=\"0\""),
            std::string::npos);
  EXPECT_NE(junit.find("<testsuites name=\"hilrig suite: "), std::string::npos);
}

TEST(RunSuite, SingleFileKeepsItsOutputsInOut) {
  const fs::path dir = scratch("suite_single");
  const SuiteRun r = run_suite({campaign::test::shipped("reference_pls_pass.toml")}, dir / "out");
  EXPECT_EQ(r.status, 0);
  EXPECT_TRUE(fs::exists(dir / "out" / "results.json"));
  EXPECT_EQ(r.out,
            "reference-pls-pass: 4 run(s), 4 passed, 0 failed, 0 errored; faults caught 0/0; verdict pass\n"
            "report: " +
                (dir / "out" / "report.html").string() + "\n");
}

// A suite run into a directory a single campaign wrote: that campaign's results.json, run log
// and trace are removed first, as any earlier campaign's are (docs/campaigns.md, "The output
// directory"), so none sits beside the suite's junit.xml and index as the suite's. A file hilrig
// does not write there is refused (2) and a directory another run holds (3), nothing run.
TEST(RunSuite, ASingleCampaignsFilesInOutAreClearedFirst) {
  const fs::path dir = scratch("suite_over_single");
  const fs::path out = dir / "out";
  ASSERT_EQ(run(campaign::test::shipped("reference_pls_pass.toml"), out), 0);
  for (const char* f : {"results.json", "runs.jsonl", "trace.vcd"}) ASSERT_TRUE(fs::exists(out / f)) << f;
  const std::string a = write_file(dir, "a.toml", passing_campaign("a")).string();
  const std::string b = write_file(dir, "b.toml", passing_campaign("b")).string();
  const SuiteRun r = run_suite({a, b}, out);
  EXPECT_EQ(r.status, 0) << r.err;
  for (const char* f : {"results.json", "runs.jsonl", "trace.vcd"}) EXPECT_FALSE(fs::exists(out / f)) << f;
  for (const char* sub : {"a", "b"}) EXPECT_TRUE(fs::exists(out / sub / "results.json")) << sub;
  EXPECT_NE(hilrig::test::read_file(out / "junit.xml").find("<testsuites name=\"hilrig suite: "),
            std::string::npos);
  // Run again over itself: the suite's own files and directories are taken as they are.
  EXPECT_EQ(run_suite({a, b}, out).status, 0);

  const fs::path foreign = scratch("suite_over_foreign");
  write_file(foreign, "notes.txt", "mine\n");
  const SuiteRun f = run_suite({a, b}, foreign);
  EXPECT_EQ(f.status, 2);
  EXPECT_NE(f.err.find("holds notes.txt, which hilrig run does not write"), std::string::npos) << f.err;
  EXPECT_FALSE(fs::exists(foreign / "a"));
  EXPECT_EQ(hilrig::test::read_file(foreign / "notes.txt"), "mine\n");

  const OutputDirectory held(dir / "busy"); // another run holds it
  const SuiteRun busy = run_suite({a, b}, dir / "busy");
  EXPECT_EQ(busy.status, 3);
  EXPECT_NE(busy.err.find("another hilrig run is writing this directory"), std::string::npos) << busy.err;
  EXPECT_FALSE(fs::exists(dir / "busy" / "a"));
}

// ---- --only and --tag --------------------------------------------------------------------

// kPlsCampaign with a second check, off_latency, tagged "nightly".
std::string two_checks() {
  return campaign::test::kPlsCampaign + R"(
[[check]]
kind = "throughput"
name = "off_latency"
output = "ls1"
setpoint = 300
direction = "rising"
level = "low"
limit_us = 250
min_count = 2
tags = ["nightly", "timing"]
)";
}

std::set<std::string> checks_run(const fs::path& results) {
  std::set<std::string> names;
  for (const auto& run : rig::read_results_file(results).runs)
    for (const auto& c : run.checks) names.insert(c.check);
  return names;
}

TEST(RunSelection, OnlyAndTagRunASubsetOfTheChecks) {
  const fs::path dir = scratch("only");
  const std::string file = write_file(dir, "two.toml", two_checks()).string();
  EXPECT_EQ(run_suite({file}, dir / "all").status, 0);
  EXPECT_EQ(checks_run(dir / "all" / "results.json"), (std::set<std::string>{"on_latency", "off_latency"}));
  EXPECT_EQ(run_suite({file}, dir / "only", 1, {{"on_latency"}, {}}).status, 0);
  EXPECT_EQ(checks_run(dir / "only" / "results.json"), (std::set<std::string>{"on_latency"}));
  EXPECT_EQ(run_suite({file}, dir / "tag", 1, {{}, {"nightly"}}).status, 0);
  EXPECT_EQ(checks_run(dir / "tag" / "results.json"), (std::set<std::string>{"off_latency"}));
}

TEST(RunSelection, UnknownCheckOrTagIsBadInputWithTheClosestName) {
  const fs::path dir = scratch("only_bad");
  const std::string file = write_file(dir, "two.toml", two_checks()).string();
  SuiteRun r = run_suite({file}, dir / "out", 1, {{"on_latncy"}, {}});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(
      r.err.find("--only on_latncy: " + file + " has no check of this name (did you mean \"on_latency\"?)"),
      std::string::npos)
      << r.err;
  r = run_suite({file}, dir / "out", 1, {{}, {"nightlly"}});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("(did you mean \"nightly\"?)"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out" / "results.json"));
  // A tag that is not a list of names is refused where it is written.
  std::string text = two_checks();
  text.replace(text.find("tags = [\"nightly\", \"timing\"]"), 28, "tags = \"nightly\"");
  r = run_suite({write_file(dir, "badtag.toml", text).string()}, dir / "out");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("check[1].tags: an array of tag names"), std::string::npos) << r.err;
}

TEST(RunSelection, FaultsWhoseCatchersAreDroppedAreNotRun) {
  // reference_pls_faults: late is caught by on_latency or off_latency; the other three faults by
  // on_latency alone. --only off_latency keeps the nominal run and the "late" fault run.
  const fs::path dir = scratch("only_faults");
  EXPECT_EQ(
      run_suite({campaign::test::shipped("reference_pls_faults.toml")}, dir / "out", 1, {{"off_latency"}, {}})
          .status,
      0);
  const rig::CampaignResult r = rig::read_results_file(dir / "out" / "results.json");
  ASSERT_EQ(r.runs.size(), 2U);
  EXPECT_EQ(r.runs[1].fault, "late");
  EXPECT_EQ(r.runs[1].must_catch, std::vector<std::string>{"off_latency"});
}

TEST(RunSelection, InASuiteCampaignsWithoutTheTagAreLeftOut) {
  const fs::path dir = scratch("only_suite");
  const std::string tagged = write_file(dir, "tagged.toml", two_checks()).string();
  const std::string plain = write_file(dir, "plain.toml", passing_campaign("plain")).string();
  SuiteRun r = run_suite({tagged, plain}, dir / "out", 1, {{}, {"timing"}});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "out" / "tagged" / "results.json"));
  EXPECT_FALSE(fs::exists(dir / "out" / "plain"));
  r = run_suite({tagged, plain}, dir / "none", 1, {{}, {"timng"}});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--tag timng (did you mean \"timing\"?)"), std::string::npos) << r.err;
}

// ---- hilrig check ------------------------------------------------------------------------

TEST(CheckCommand, ValidatesWithoutRunningWithTheMessagesOfRun) {
  const fs::path dir = scratch("check");
  std::string text = campaign::test::kPlsCampaign;
  text.replace(text.find("board = \"OUT\""), 13, "board = \"OUT9\"");
  const std::string bad = write_file(dir, "bad.toml", text).string();
  std::ostringstream out;
  std::ostringstream err;
  EXPECT_EQ(check_campaigns({campaign::test::shipped("reference_pls_pass.toml"), bad}, out, err), 2);
  EXPECT_EQ(out.str(), campaign::test::shipped("reference_pls_pass.toml") +
                           ": ok (4 run(s), 5 check(s) a run)\n"); // its five [[check]] tables
  std::string run_err;
  EXPECT_EQ(run(bad, dir / "out", &run_err), 2);
  EXPECT_EQ(err.str(), run_err); // word for word what `hilrig run` says
  std::ostringstream out2;
  std::ostringstream err2;
  EXPECT_EQ(check_campaigns({campaign::test::campaign_dir("reference")}, out2, err2), 0) << err2.str();
  EXPECT_EQ(hilrig::test::count_of(out2.str(), ": ok ("), 2U);
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// ---- --progress --------------------------------------------------------------------------

TEST(RunProgressLines, EachRunWithOutcomeWallTimeAndEta) {
  const fs::path dir = scratch("progress");
  RunOptions o;
  o.files = {campaign::test::shipped("reference_pls_pass.toml"),
             write_file(dir, "late.toml", late_campaign("late")).string()};
  o.out = dir / "out";
  o.progress_lines = true;
  std::ostringstream out;
  std::ostringstream err;
  EXPECT_EQ(run_campaigns(o, out, err), 1);
  const std::string text = err.str();
  // Each run as it starts, then as it ends: outcome, wall time, the estimate of what is left.
  const std::regex started(R"re(\[(\d)/5\] (\S+): run (\d+) ([^:\n]*)\n)re");
  const std::regex ended(
      R"re(\[(\d)/5\] (\S+): run (\d+): (pass|fail|error) in \d+\.\d\d s; ETA \d+:\d\d\n)re");
  std::vector<std::string> starts;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), started); it != std::sregex_iterator(); ++it)
    starts.push_back((*it)[1].str() + " " + (*it)[2].str() + " " + (*it)[3].str());
  std::vector<std::string> outcomes;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), ended); it != std::sregex_iterator(); ++it)
    outcomes.push_back((*it)[2].str() + ":" + (*it)[5 - 1].str());
  EXPECT_EQ(starts,
            (std::vector<std::string>{"1 reference-pls-pass 0", "2 reference-pls-pass 1",
                                      "3 reference-pls-pass 2", "4 reference-pls-pass 3", "5 late 0"}))
      << text;
  EXPECT_EQ(outcomes,
            (std::vector<std::string>{"reference-pls-pass:pass", "reference-pls-pass:pass",
                                      "reference-pls-pass:pass", "reference-pls-pass:pass", "late:fail"}))
      << text;
  // Nothing but progress on stderr; the summaries are on stdout.
  EXPECT_EQ(hilrig::test::count_of(text, "\n"), 10U) << text;
  EXPECT_EQ(clock_text(7.4), "0:07");
  EXPECT_EQ(clock_text(750), "12:30");
  EXPECT_EQ(clock_text(3723), "1:02:03");
}

// A stream that, at each "run N: <outcome> in" line, counts the run records in runs.jsonl.
class LogAtEachFinishedLine : public std::stringbuf {
public:
  explicit LogAtEachFinishedLine(fs::path log) : log_(std::move(log)) {}
  std::vector<std::string> seen; // "run N: records M"

protected:
  int sync() override {
    const std::string text = str();
    static const std::regex finished(R"re(\] run (\d+): [a-z]+ in [^\n]*\n)re");
    const auto from = text.begin() + static_cast<std::ptrdiff_t>(scanned_);
    for (auto it = std::sregex_iterator(from, text.end(), finished); it != std::sregex_iterator(); ++it) {
      std::ifstream in(log_);
      std::size_t records = 0;
      for (std::string line; std::getline(in, line);)
        if (line.rfind("{\"run\":", 0) == 0) ++records;
      seen.push_back("run " + (*it)[1].str() + ": records " + std::to_string(records));
    }
    scanned_ = text.size();
    return 0;
  }

private:
  fs::path log_;
  std::size_t scanned_ = 0;
};

// docs/campaigns.md: a kill leaves runs.jsonl with every finished run, and the end-of-run line
// is what scripts wait for; so a run is reported finished only once its record is in the log.
TEST(RunProgressLines, ARunIsReportedFinishedOnlyOnceItsRecordIsInTheLog) {
  const fs::path dir = scratch("progress_after_record");
  RunOptions o;
  o.files = {campaign::test::shipped("reference_pls_pass.toml")};
  o.out = dir / "out";
  o.progress_lines = true;
  LogAtEachFinishedLine buf(o.out / "runs.jsonl");
  std::ostream err(&buf);
  std::ostringstream out;
  EXPECT_EQ(run_campaigns(o, out, err), 0) << buf.str();
  EXPECT_EQ(buf.seen, (std::vector<std::string>{"run 0: records 1", "run 1: records 2", "run 2: records 3",
                                                "run 3: records 4"}))
      << buf.str();
}

int g_earlier_handler_saw = 0;
void earlier_handler(int signal) { g_earlier_handler_saw = signal; }

TEST(StopSignals, ASignalIsAStopRequestWhileItLivesAndTheEarlierActionIsBackAfter) {
  struct sigaction earlier {};
  earlier.sa_handler = earlier_handler;
  sigemptyset(&earlier.sa_mask);
  struct sigaction before_int {};
  struct sigaction before_term {};
  ASSERT_EQ(sigaction(SIGINT, &earlier, &before_int), 0);
  ASSERT_EQ(sigaction(SIGTERM, &earlier, &before_term), 0);
  campaign::StopRequest stop;
  {
    const StopSignals signals(stop);
    EXPECT_FALSE(stop.requested());
    EXPECT_FALSE(stop.flag().load());  // the flag `serve` and `latency` poll
    ASSERT_EQ(std::raise(SIGTERM), 0); // handled on this thread before raise returns
    EXPECT_TRUE(stop.requested());
    EXPECT_TRUE(stop.flag().load());
    ASSERT_EQ(std::raise(SIGINT), 0); // absorbed: the first signal names the stop
    EXPECT_EQ(stop.reason(), "SIGTERM");
    EXPECT_EQ(g_earlier_handler_saw, 0);
    // No thread of its own: /proc/self/task holds one entry per thread of the test process.
    std::size_t threads = 0;
    for ([[maybe_unused]] const auto& task : std::filesystem::directory_iterator("/proc/self/task"))
      ++threads;
    EXPECT_EQ(threads, 1U);
  }
  ASSERT_EQ(std::raise(SIGINT), 0);
  EXPECT_EQ(g_earlier_handler_saw, SIGINT);
  sigaction(SIGINT, &before_int, nullptr);
  sigaction(SIGTERM, &before_term, nullptr);
}

} // namespace
} // namespace hilrig::cli
