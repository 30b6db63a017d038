// Bad input found by a robustness audit, each refused before anything runs (exit 2, naming
// what and where) without losing what was already captured, and incomplete evidence or a failed
// write judged 3.

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "tests/campaign/hilrig_process.hpp"
#include "tests/tools/scratch_files.hpp"

// A namespace of its own: a unity build puts this file beside command_line_test.cpp, whose
// anonymous namespace has the same helpers.
namespace hilrig::robust_input {
namespace {

namespace fs = std::filesystem;

using Result = test::ProcessResult;
Result hilrig(const std::string& args, const std::string& wrap = "") { return test::run_hilrig(args, wrap); }

const std::string kPass = std::string(HILRIG_SOURCE_DIR) + "/campaigns/reference/reference_pls_pass.toml";

// A merge whose output is one of its inputs (here shard 0's results.json given as both, and a
// link to it) would replace that shard's results.json, junit.xml and report.html: refused, 2,
// with every shard file as it was. A merge of several shards does not write over a run log's
// own results.json either; the kill recovery, one run's log folded into its own directory, does.
TEST(RobustInput, MergeRefusesToOverwriteAnInput) {
  const fs::path dir = test::scratch_dir("campaign", "robust_merge_overwrite");
  for (const char* k : {"0", "1"})
    ASSERT_EQ(
        hilrig("run " + kPass + " --trace none --shard " + k + "/2 --out " + (dir / "s").string() + k).status,
        0);
  const fs::path s0 = dir / "s0";
  const std::string s1 = (dir / "s1" / "results.json").string();
  const std::string results = test::read_file(s0 / "results.json");
  const std::string junit = test::read_file(s0 / "junit.xml");
  const std::string input = (s0 / "results.json").string();
  const Result same = hilrig("merge " + input + " " + input + " " + s1);
  EXPECT_EQ(same.status, 2) << same.err;
  EXPECT_NE(same.err.find("is also an input"), std::string::npos) << same.err;
  fs::create_symlink(s0 / "results.json", dir / "alias.json");
  const Result linked = hilrig("merge " + (dir / "alias.json").string() + " " + input + " " + s1);
  EXPECT_EQ(linked.status, 2) << linked.err;
  const Result log = hilrig("merge " + input + " " + (s0 / "runs.jsonl").string() + " " + s1);
  EXPECT_EQ(log.status, 2) << log.err;
  EXPECT_NE(log.err.find("the run's own file beside the input"), std::string::npos) << log.err;
  EXPECT_EQ(test::read_file(s0 / "results.json"), results);
  EXPECT_EQ(test::read_file(s0 / "junit.xml"), junit);
  // Elsewhere, and into a directory of the shards under another name (NAME.junit.xml), it merges.
  EXPECT_EQ(hilrig("merge " + (s0 / "merged.json").string() + " " + input + " " + s1).status, 0);
  EXPECT_EQ(test::read_file(s0 / "junit.xml"), junit);
  // The kill recovery: a run's one log folded into its own directory.
  ASSERT_EQ(hilrig("run " + kPass + " --trace none --out " + (dir / "whole").string()).status, 0);
  const Result fold = hilrig("merge " + (dir / "whole" / "results.json").string() + " " +
                             (dir / "whole" / "runs.jsonl").string());
  EXPECT_EQ(fold.status, 0) << fold.err;
}

// The run log of a killed run holds fewer runs than planned: incomplete evidence, 3, as its
// results.json cut at the same run is, though every run it holds passed (not 1, a check's).
TEST(RobustInput, MergeOfAnIncompleteRunLogExitsThree) {
  const fs::path dir = test::scratch_dir("campaign", "robust_merge_incomplete");
  ASSERT_EQ(hilrig("run " + kPass + " --trace none --out " + (dir / "ran").string()).status, 0);
  // The log as a kill leaves it: the header and the first run's record, the rest never written.
  std::ifstream log(dir / "ran" / "runs.jsonl");
  std::string header;
  std::string first;
  ASSERT_TRUE(std::getline(log, header) && std::getline(log, first));
  std::string rest;
  ASSERT_TRUE(std::getline(log, rest)) << "the campaign plans more than one run";
  std::ofstream(dir / "cut.jsonl") << header << '\n' << first << '\n';
  nlohmann::json results = nlohmann::json::parse(test::read_file(dir / "ran" / "results.json"));
  results["runs"].erase(results["runs"].begin() + 1, results["runs"].end());
  std::ofstream(dir / "cut.json") << results.dump();

  const Result from_log = hilrig("merge " + (dir / "m1.json").string() + " " + (dir / "cut.jsonl").string());
  EXPECT_EQ(from_log.status, 3) << from_log.err;
  EXPECT_NE(from_log.err.find("incomplete evidence: 1 of the"), std::string::npos) << from_log.err;
  const Result from_json = hilrig("merge " + (dir / "m2.json").string() + " " + (dir / "cut.json").string());
  EXPECT_EQ(from_json.status, 3) << from_json.err;
  // The whole log still merges to the run's own verdict.
  EXPECT_EQ(
      hilrig("merge " + (dir / "m3.json").string() + " " + (dir / "ran" / "runs.jsonl").string()).status, 0);
}

// A link loop among a suite's *.toml is bad input naming the link (as given alone), not a
// library's "filesystem error" as a rig fault.
TEST(RobustInput, ALinkLoopInASuiteIsBadInputNamingIt) {
  const fs::path dir = test::scratch_dir("campaign", "robust_suite_loop");
  const fs::path suite = dir / "suite";
  fs::create_directories(suite);
  fs::copy_file(kPass, suite / "a.toml");
  fs::create_symlink("loop2", suite / "loop1.toml");
  fs::create_symlink("loop1.toml", suite / "loop2");
  for (const std::string& command :
       {"check " + suite.string(),
        "run " + suite.string() + " --out " + (dir / "out").string() + " --trace none"}) {
    const Result r = hilrig(command);
    EXPECT_EQ(r.status, 2) << command << ": " << r.err;
    EXPECT_NE(r.err.find("loop1.toml: Too many levels of symbolic links"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("filesystem error"), std::string::npos) << r.err;
  }
}

// A --port-file that cannot be written (a directory that is not there) is bad input before
// anything serves: a script waiting for the file would wait for ever.
TEST(RobustInput, ServeRefusesAPortFileItCannotWrite) {
  const Result r = hilrig("serve ans1 --modbus-tcp 0 --port-file /nonexistent/dir/p", "timeout 20 ");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("/nonexistent/dir/p"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("No such file or directory"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("listening"), std::string::npos) << r.out;
}

// An address that is not IPv4 and a speed beyond the boards' rpm word are the command line's
// mistakes (2), not the rig's (3), named before a port is bound.
TEST(RobustInput, ServeRefusesABadBindAndAnOutOfRangeMotion) {
  const Result bind = hilrig("serve ans1 --modbus-tcp 0 --bind 999.1.1.1", "timeout 20 ");
  EXPECT_EQ(bind.status, 2) << bind.err;
  EXPECT_NE(bind.err.find("999.1.1.1 is not an IPv4 address"), std::string::npos) << bind.err;
  const Result motion = hilrig("serve pls2700 --modbus-tcp 0 --motion constant:1e308rpm", "timeout 20 ");
  EXPECT_EQ(motion.status, 2) << motion.err;
  EXPECT_NE(motion.err.find("-32767 .. 32767 rpm"), std::string::npos) << motion.err;
}

// A rate near 0 made the move's nanoseconds overflow (every edge at #0, exit 0): the move must
// end within a campaign's run, and the least rate that does is named.
TEST(RobustInput, SynthRefusesAMoveLongerThanARun) {
  const fs::path dir = test::scratch_dir("campaign", "robust_synth_time");
  const std::string stroke = "synth quadrature --out " + (dir / "a.vcd").string() + " --lines 100 --rpm 600 ";
  const std::string base = stroke + "--turns 1 "; // a move's distance: not the press's option
  const Result accel = hilrig(base + "--profile trapezoid --accel 1e-300");
  EXPECT_EQ(accel.status, 2) << accel.err;
  EXPECT_NE(accel.err.find("--accel"), std::string::npos) << accel.err;
  EXPECT_NE(accel.err.find("at least"), std::string::npos) << accel.err;
  const Result jerk = hilrig(base + "--profile scurve --accel 10 --jerk 1e-300");
  EXPECT_EQ(jerk.status, 2) << jerk.err;
  EXPECT_NE(jerk.err.find("--jerk"), std::string::npos) << jerk.err;
  const Result brake = hilrig(stroke + "--profile press --duration 1s --brake 1e-300");
  EXPECT_EQ(brake.status, 2) << brake.err;
  EXPECT_NE(brake.err.find("--brake"), std::string::npos) << brake.err;
  EXPECT_FALSE(fs::exists(dir / "a.vcd"));
  // A slow move within the hour is still made.
  EXPECT_EQ(hilrig(base + "--profile trapezoid --accel 0.001").status, 0);
}

// A [[wiring]] rig line's name follows the rule of every name (1 .. 64 printable ASCII): an
// empty one or a control character (BEL, which went raw into trace.vcd) is bad input.
TEST(RobustInput, WiringRigNamesAreLabels) {
  const fs::path dir = test::scratch_dir("campaign", "robust_wiring_name");
  const std::string text = test::read_file(kPass);
  const std::string line = "rig = \"ls1\"";
  ASSERT_NE(text.find(line), std::string::npos);
  for (const std::string& name : {std::string(""), std::string("l\\u0007s1")}) {
    std::string bad = text;
    bad.replace(bad.find(line), line.size(), "rig = \"" + name + "\"");
    const fs::path file = test::write_file(dir, "bad.toml", bad);
    const Result r = hilrig("check " + file.string());
    EXPECT_EQ(r.status, 2) << name << ": " << r.err;
    EXPECT_NE(r.err.find("the rig line's name: 1 .. 64 printable ASCII characters"), std::string::npos)
        << r.err;
  }
}

// `run --out ""` is bad input (2), not a rig fault (3).
TEST(RobustInput, RunRefusesAnEmptyOut) {
  const Result r = hilrig("run " + kPass + " --out ''");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("--out"), std::string::npos) << r.err;
}

// A --threshold naming no measurement (a misspelt name) is warned about, naming it; the
// comparison's exit status is its own.
TEST(RobustInput, CompareWarnsOfAThresholdThatNamesNothing) {
  const fs::path dir = test::scratch_dir("campaign", "robust_compare_threshold");
  ASSERT_EQ(hilrig("run " + kPass + " --trace none --out " + (dir / "ran").string()).status, 0);
  const std::string results = (dir / "ran" / "results.json").string();
  const Result r = hilrig("compare " + results + " " + results + " --threshold nosuch=5 --threshold max=5");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("warning: --threshold nosuch: no measurement"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("--threshold max"), std::string::npos) << r.err;
}

// Every *.tmp left anywhere under dir (the docs promise none after a failed write).
std::vector<std::string> tmp_files_under(const fs::path& dir) {
  std::vector<std::string> found;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().extension() == ".tmp") found.push_back(e.path().string());
  return found;
}

// A file size limit (`ulimit -f`) is a failed write as a full disk is (docs/campaigns.md, "The
// output directory"): exit 3 with the system's reason and no *.tmp left, not a process killed by
// SIGXFSZ (exit 153, no message, trace.vcd.tmp left). The limit is in 512-byte blocks (popen's
// sh is dash): 64 blocks cut this campaign's report.html (over 200 kB) with or without traces,
// 1024 its trace.vcd (over 1 MB) and the trace spill the runs record into.
TEST(RobustInput, AFileSizeLimitIsAFailedWriteNotAKill) {
  const fs::path dir = test::scratch_dir("campaign", "robust_file_size");
  const std::pair<const char*, const char*> cases[] = {{"64", "all"}, {"64", "none"}, {"1024", "all"}};
  for (const auto& [blocks, trace] : cases) {
    SCOPED_TRACE(std::string("ulimit -f ") + blocks + ", --trace " + trace);
    const fs::path out = dir / (std::string("out") + blocks + trace);
    const Result r = hilrig("run " + kPass + " --epoch 1 --out " + out.string() + " --trace " + trace,
                            std::string("ulimit -f ") + blocks + "; ");
    EXPECT_EQ(r.status, 3) << r.err;
    EXPECT_NE(r.err.find("File too large"), std::string::npos) << r.err;
    EXPECT_EQ(tmp_files_under(out), std::vector<std::string>{});
  }
  // Every command that writes: merge's output under the same limit fails the same way.
  ASSERT_EQ(hilrig("run " + kPass + " --out " + (dir / "whole").string() + " --trace none").status, 0);
  const Result merged = hilrig("merge " + (dir / "merged" / "m.json").string() + " " +
                                   (dir / "whole" / "results.json").string(),
                               "ulimit -f 8; ");
  EXPECT_EQ(merged.status, 3) << merged.err; // the rig's failure, as run's: not bad input
  EXPECT_NE(merged.err.find("File too large"), std::string::npos) << merged.err;
  EXPECT_EQ(tmp_files_under(dir / "merged"), std::vector<std::string>{});
}

// `trend --out` naming one of its inputs, by any spelling (the path as given, a symbolic link,
// "DIR/../DIR/results.json"), would replace that night's results.json with the page: refused, 2,
// the input as it was and no page written; one file given twice is not two nights.
TEST(RobustInput, TrendRefusesToOverwriteAnInputOrReadOneTwice) {
  const fs::path dir = test::scratch_dir("campaign", "robust_trend_inputs");
  ASSERT_EQ(hilrig("run " + kPass + " --trace none --out " + (dir / "night").string()).status, 0);
  const fs::path results = dir / "night" / "results.json";
  const std::string before = test::read_file(results);
  fs::create_symlink(results, dir / "alias.json");
  const std::string other_spelling = (dir / "night" / ".." / "night" / "results.json").string();
  for (const std::string& out : {results.string(), (dir / "alias.json").string(), other_spelling}) {
    const Result r = hilrig("trend " + results.string() + " --out " + out);
    EXPECT_EQ(r.status, 2) << out << ": " << r.err;
    EXPECT_NE(r.err.find("is also an input"), std::string::npos) << r.err;
    EXPECT_EQ(test::read_file(results), before);
  }
  for (const std::string& again : {results.string(), (dir / "alias.json").string(), other_spelling}) {
    const Result r =
        hilrig("trend " + results.string() + " " + again + " --out " + (dir / "t.html").string());
    EXPECT_EQ(r.status, 2) << again << ": " << r.err;
    EXPECT_NE(r.err.find("are one file given twice"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "t.html"));
  }
  // Beside it under the name of a file the run wrote: refused, the run's file as it was.
  for (const char* name : {"trace.vcd", "junit.xml", "report.html", "runs.jsonl"}) {
    const fs::path file = dir / "night" / name;
    const bool existed = fs::exists(file);
    const std::string kept = existed ? test::read_file(file) : std::string();
    const Result r = hilrig("trend " + results.string() + " --out " + file.string());
    EXPECT_EQ(r.status, 2) << name << ": " << r.err;
    EXPECT_NE(r.err.find("is the run's own file beside the input"), std::string::npos) << r.err;
    EXPECT_EQ(fs::exists(file), existed) << name;
    if (existed) {
      EXPECT_EQ(test::read_file(file), kept) << name;
    }
  }
  // Beside it under another name, it is written.
  const Result ok = hilrig("trend " + results.string() + " --out " + (dir / "night" / "trend.html").string());
  EXPECT_EQ(ok.status, 0) << ok.err;
  EXPECT_EQ(test::read_file(results), before);
}

// A merge written into a shard's run directory under the name of a file the run wrote (its
// trace.vcd, which the merged result links to, its junit.xml) would replace that evidence:
// refused, 2, every file as it was and nothing written (not even NAME.junit.xml beside it).
TEST(RobustInput, MergeRefusesToWriteOverAShardsOwnFiles) {
  const fs::path dir = test::scratch_dir("campaign", "robust_merge_run_files");
  for (const char* k : {"0", "1"})
    ASSERT_EQ(
        hilrig("run " + kPass + " --shard " + k + "/2 --epoch 1 --out " + (dir / "s").string() + k).status,
        0);
  const fs::path s0 = dir / "s0";
  const std::string inputs = (s0 / "results.json").string() + " " + (dir / "s1" / "results.json").string();
  ASSERT_TRUE(fs::exists(s0 / "trace.vcd"));
  const std::string trace = test::read_file(s0 / "trace.vcd");
  const std::string junit = test::read_file(s0 / "junit.xml");
  for (const char* name : {"trace.vcd", "junit.xml", "report.html", "runs.jsonl", "can.log"}) {
    const Result r = hilrig("merge " + (s0 / name).string() + " " + inputs);
    EXPECT_EQ(r.status, 2) << name << ": " << r.err;
    EXPECT_NE(r.err.find("the run's own file beside the input"), std::string::npos) << r.err;
  }
  // The other shard's directory, and a spelling through "..", alike.
  const Result other = hilrig("merge " + (dir / "s1" / "trace.vcd").string() + " " + inputs);
  EXPECT_EQ(other.status, 2) << other.err;
  const Result dots = hilrig("merge " + (dir / "s1" / ".." / "s0" / "trace.vcd").string() + " " + inputs);
  EXPECT_EQ(dots.status, 2) << dots.err;
  EXPECT_EQ(test::read_file(s0 / "trace.vcd"), trace);
  EXPECT_EQ(test::read_file(s0 / "junit.xml"), junit);
  for (const char* name : {"trace.junit.xml", "trace.report.html", "junit.junit.xml", "can.junit.xml"})
    EXPECT_FALSE(fs::exists(s0 / name)) << name;
  // Merged files named as no run's file, beside the shards, are still written.
  EXPECT_EQ(hilrig("merge " + (dir / "merged.json").string() + " " + inputs).status, 0);
}

// The messages of bad input say what was wrong where it was: a campaign given as --rig is named
// as one read as a rig config; a file that is not there has no 0:0 position and gives the
// system's reason; a results file of another version names the version found and the one read.
TEST(RobustInput, MessagesNameWhatWasReadAndFound) {
  const fs::path dir = test::scratch_dir("campaign", "robust_messages");
  const Result rig = hilrig("run " + kPass + " --out " + (dir / "rig").string() + " --rig " + kPass);
  EXPECT_EQ(rig.status, 2) << rig.err;
  EXPECT_NE(rig.err.find("campaign: a campaign file's table, in a file read as a rig config"),
            std::string::npos)
      << rig.err;
  EXPECT_FALSE(fs::exists(dir / "rig" / "results.json"));
  const std::string nowhere = (dir / "nowhere.toml").string();
  const Result missing = hilrig("run " + kPass + " --out " + (dir / "rig").string() + " --rig " + nowhere);
  EXPECT_EQ(missing.status, 2);
  EXPECT_EQ(missing.err,
            nowhere + ": file: a readable rig config file (cannot open it: No such file or directory)\n");
  const fs::path huge = test::write_file(dir, "huge.toml", std::string(1048577, '#'));
  const Result big = hilrig("check " + huge.string());
  EXPECT_EQ(big.status, 2);
  EXPECT_EQ(big.err, huge.string() + ": file: a campaign file of at most 1048576 bytes\n");
  ASSERT_EQ(hilrig("run " + kPass + " --trace none --out " + (dir / "ran").string()).status, 0);
  nlohmann::json results = nlohmann::json::parse(test::read_file(dir / "ran" / "results.json"));
  results["version"] = 3;
  std::ofstream(dir / "v3.json") << results.dump();
  const Result v3 = hilrig("merge " + (dir / "m.json").string() + " " + (dir / "v3.json").string());
  EXPECT_EQ(v3.status, 2);
  EXPECT_NE(v3.err.find("unsupported version 3: hilrig "), std::string::npos) << v3.err;
  EXPECT_NE(v3.err.find(" reads version 2"), std::string::npos) << v3.err;
}

// A campaign file that is not there is refused as docs/campaigns.md shows it, "x.toml: file: a
// readable campaign file (cannot open it: ...)", the form of every whole-file problem, by check
// (beside the files that are there, still checked) and by run (nothing written).
TEST(RobustInput, AMissingCampaignFileIsRefusedInTheDocumentedForm) {
  const fs::path dir = test::scratch_dir("campaign", "robust_missing");
  const std::string nowhere = (dir / "nope.toml").string();
  const std::string said =
      nowhere + ": file: a readable campaign file (cannot open it: No such file or directory)\n";
  const Result check = hilrig("check " + nowhere + " " + kPass);
  EXPECT_EQ(check.status, 2);
  EXPECT_EQ(check.err, said);
  EXPECT_NE(check.out.find(kPass + ": ok"), std::string::npos) << check.out;
  for (const std::string& files : {nowhere, nowhere + " " + kPass}) {
    const Result run = hilrig("run " + files + " --trace none --out " + (dir / "out").string());
    EXPECT_EQ(run.status, 2) << files;
    EXPECT_EQ(run.err, said) << files;
    EXPECT_FALSE(fs::exists(dir / "out")) << files;
  }
}

// `latency --cpu N` beyond the machine's CPUs would run unpinned (its header saying so in
// passing), and a --duration shorter than one --interval measures no wake-up (a table of 0 µs):
// both refused before anything runs, 2, naming the range. The last CPU and exactly one interval
// are measured (priority 0: no SCHED_FIFO needed).
TEST(RobustInput, LatencyRefusesACpuItHasNotAndADurationWithoutAWakeUp) {
  const long cpus = ::sysconf(_SC_NPROCESSORS_CONF);
  ASSERT_GT(cpus, 0);
  const Result beyond = hilrig(fmt::format("latency --priority 0 --duration 0.01 --quiet --cpu {}", cpus));
  EXPECT_EQ(beyond.status, 2) << beyond.err;
  EXPECT_NE(beyond.err.find(fmt::format("--cpu {}: this machine has CPUs 0 .. {}", cpus, cpus - 1)),
            std::string::npos)
      << beyond.err;
  EXPECT_EQ(beyond.out, "");
  const Result last = hilrig(fmt::format("latency --priority 0 --duration 0.01 --quiet --cpu {}", cpus - 1));
  EXPECT_EQ(last.status, 0) << last.err;
  for (const char* duration : {"1e-9", "0.000999"}) {
    const Result short_one =
        hilrig(std::string("latency --priority 0 --quiet --interval 1000 --duration ") + duration);
    EXPECT_EQ(short_one.status, 2) << duration << ": " << short_one.err;
    EXPECT_NE(short_one.err.find("shorter than one --interval (1000 us): at least 0.001 s"),
              std::string::npos)
        << short_one.err;
    EXPECT_EQ(short_one.out, "");
  }
  const Result one = hilrig("latency --priority 0 --quiet --interval 1000 --duration 0.001");
  EXPECT_EQ(one.status, 0) << one.err;
  EXPECT_NE(one.out.find("C:      1 "), std::string::npos) << one.out;
}

} // namespace
} // namespace hilrig::robust_input
