// `hilrig run` stopped by SIGTERM, as an operator or a CI job timeout does it: the program
// (the real binary) stops the run at its next event, drives every line it drives to its
// inactive level, writes what ran (the stopped run marked interrupted) and exits 3.

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "../results/json_schema_subset.hpp"
#include "rig/results/results_json.hpp"
#include "tests/tools/scratch_files.hpp"
#include "tests/tools/vcd_reader.hpp"

extern char** environ;

namespace hilrig::campaign {
namespace {

namespace fs = std::filesystem;

// An ANS1 turning slowly for ten virtual minutes (about a minute of wall time to run out):
// IN1 switched on at 1 ms and left on, one programming write, one read near the end. The
// rig drives enc.A, enc.B and in1; their inactive level is low.
const char* const kLongCampaign = R"([campaign]
name = "long"
end = "600s"
host_poll = "100us"
[dut]
model = "ans1"
[[wiring]]
rig = "enc.A"
board = "A"
[[wiring]]
rig = "enc.B"
board = "B"
[[wiring]]
rig = "in1"
board = "IN1"
[[wiring]]
rig = "ls1"
board = "OUT1"
[encoder]
lines = 90
[motion]
[[motion.move]]
kind = "constant"
speed_rpm = 100
duration = "600s"
[[stimulus]]
kind = "level"
at = "1ms"
line = "in1"
level = "high"
[[host]]
at = "0ms"
write = [0x0382, 0x0008, 360, 360]
name = "cb2_encoder"
[[host]]
at = "590s"
read = 11
name = "revolutions"
[[check]]
kind = "word_equals"
name = "revolutions"
observation = "revolutions"
value = 983
)";

// Starts `hilrig run FILE --out DIR --progress` with stderr on a pipe.
struct Hilrig {
  pid_t pid = -1;
  int err = -1; // read end of its stderr

  Hilrig(const fs::path& file, const fs::path& out) {
    std::array<int, 2> p{};
    if (::pipe2(p.data(), O_CLOEXEC) != 0) throw std::runtime_error("pipe");
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, p[1], STDERR_FILENO);
    const std::string exe = HILRIG_EXE;
    std::vector<std::string> args{exe, "run", file.string(), "--out", out.string(), "--progress"};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const int rc = posix_spawn(&pid, exe.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(p[1]);
    err = p[0];
    if (rc != 0) throw std::runtime_error("cannot start " + exe);
  }
  ~Hilrig() {
    if (pid > 0) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, nullptr, 0);
    }
    ::close(err);
  }
  Hilrig(const Hilrig&) = delete;
  Hilrig& operator=(const Hilrig&) = delete;

  // Reads stderr up to and including the next newline ("" at end of file).
  std::string line() {
    std::string s;
    char c = 0;
    while (::read(err, &c, 1) == 1) {
      s += c;
      if (c == '\n') break;
    }
    return s;
  }
  std::string rest() {
    std::string s;
    for (std::string l = line(); !l.empty(); l = line()) s += l;
    return s;
  }
  int wait() {
    int status = 0;
    ::waitpid(pid, &status, 0);
    pid = -1;
    return status;
  }
};

TEST(Interrupt, SigtermLeavesEveryOutputInactiveAndAReadablePartialReport) {
  const fs::path dir = fs::path(HILRIG_BINARY_DIR) / "tests" / "campaign" / "scratch" / "interrupt";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path file = dir / "long.toml";
  std::ofstream(file) << kLongCampaign;
  const fs::path out = dir / "out";

  Hilrig hilrig(file, out);
  const std::string progress = hilrig.line(); // the run has started
  ASSERT_EQ(progress.rfind("[1/1] run 0", 0), 0U) << progress;
  ASSERT_EQ(::kill(hilrig.pid, SIGTERM), 0);
  const std::string said = hilrig.rest();
  const int status = hilrig.wait();
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status) << "\n" << said;
  EXPECT_EQ(WEXITSTATUS(status), 3) << said; // a rig fault
  EXPECT_NE(said.find("interrupted by SIGTERM"), std::string::npos) << said;

  // results.json: valid against the published schema, naming the interruption.
  const nlohmann::json results = nlohmann::json::parse(hilrig::test::read_file(out / "results.json"));
  const nlohmann::json schema = nlohmann::json::parse(
      hilrig::test::read_file(fs::path(HILRIG_SOURCE_DIR) / "docs" / "results.schema.json"));
  const std::vector<std::string> problems = rig::test::validate_json_schema(schema, results);
  EXPECT_TRUE(problems.empty()) << problems.front();
  EXPECT_EQ(results.at("interrupted"), "SIGTERM");
  EXPECT_EQ(results.at("complete"), false);
  EXPECT_EQ(results.at("verdict"), "error");
  ASSERT_EQ(results.at("runs").size(), 1U);
  const nlohmann::json& run = results.at("runs")[0];
  EXPECT_EQ(run.at("interrupted"), true);
  EXPECT_EQ(run.at("error").get<std::string>().rfind("interrupted by SIGTERM at ", 0), 0U) << run.at("error");
  EXPECT_EQ(rig::read_results_file(out / "results.json").interrupted.value_or(""), "SIGTERM");

  EXPECT_NE(hilrig::test::read_file(out / "report.html").find("Interrupted by SIGTERM"), std::string::npos);
  EXPECT_NE(hilrig::test::read_file(out / "junit.xml").find("interrupted by SIGTERM"), std::string::npos);
  for (const char* f : {"results.json.tmp", "trace.vcd.tmp"}) EXPECT_FALSE(fs::exists(out / f)) << f;

  // Every line the rig drives ends at its inactive level (low) in the trace.
  const hilrig::test::Vcd vcd = hilrig::test::read_vcd_file((out / "trace.vcd").string());
  for (const char* line : {"enc.A", "enc.B", "in1"}) {
    const hilrig::test::VcdVar* wire = vcd.find(line);
    ASSERT_NE(wire, nullptr) << line;
    ASSERT_FALSE(wire->values().empty()) << line;
    EXPECT_EQ(wire->values().back(), "0") << line;
  }
}

// docs/ci.md: junit.xml's timestamp and hostname are the start and the host; classnames
// <campaign>.<run>. A suite stopped by SIGTERM in its first campaign never starts the second:
// that campaign's testsuite carries the suite's start and the host (not 1970 and
// "localhost"), its [campaign] name (not its file's stem) and says it was not run, and why.
TEST(Interrupt, ASuiteCampaignTheStopKeptFromStartingSaysSoInJunit) {
  const fs::path dir = fs::path(HILRIG_BINARY_DIR) / "tests" / "campaign" / "scratch" / "interrupt_suite";
  fs::remove_all(dir);
  fs::create_directories(dir / "in");
  std::ofstream(dir / "in" / "a_long.toml") << kLongCampaign;
  std::string second = kLongCampaign;
  second.replace(second.find("name = \"long\""), 13, "name = \"second-campaign\"");
  std::ofstream(dir / "in" / "b_next.toml") << second;

  Hilrig hilrig(dir / "in", dir / "out");
  const std::string progress = hilrig.line(); // the first campaign's run has started
  ASSERT_NE(progress.find("run 0"), std::string::npos) << progress;
  ASSERT_EQ(::kill(hilrig.pid, SIGTERM), 0);
  const std::string said = hilrig.rest();
  const int status = hilrig.wait();
  ASSERT_TRUE(WIFEXITED(status)) << said;
  EXPECT_EQ(WEXITSTATUS(status), 3) << said;
  EXPECT_NE(said.find("b_next.toml: not run (stopped by SIGTERM)"), std::string::npos) << said;

  const std::string junit = hilrig::test::read_file(dir / "out" / "junit.xml");
  const std::regex suite_re(R"re(<testsuite name="([^"]*)"[^>]*timestamp="([^"]*)" hostname="([^"]*)")re");
  std::vector<std::smatch> suites;
  for (auto it = std::sregex_iterator(junit.begin(), junit.end(), suite_re); it != std::sregex_iterator();
       ++it)
    suites.push_back(*it);
  ASSERT_EQ(suites.size(), 2U) << junit;
  EXPECT_EQ(suites[0][1], "long");
  EXPECT_EQ(suites[1][1], "second-campaign") << junit;
  // The suite's start: at or before the first campaign's (ISO 8601 UTC compares as text).
  EXPECT_LE(suites[1][2].str(), suites[0][2].str()) << junit;
  EXPECT_GE(suites[1][2].str(), "2020") << junit;
  EXPECT_EQ(suites[1][3], suites[0][3]) << junit;
  EXPECT_NE(junit.find("classname=\"second-campaign.campaign\""), std::string::npos) << junit;
  EXPECT_NE(junit.find("message=\"not run: the suite was stopped by SIGTERM\""), std::string::npos) << junit;
}

// A crash (here SIGKILL, which no handler sees) after the first of two runs leaves the run log
// with that run's whole record, and `hilrig merge OUT.json OUT/runs.jsonl` folds it into a
// results.json (incomplete) with that run in it.
TEST(Interrupt, SigkillAfterARunLeavesTheRunsDoneReadable) {
  const fs::path dir = fs::path(HILRIG_BINARY_DIR) / "tests" / "campaign" / "scratch" / "sigkill";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::string text = kLongCampaign;
  // Run 0 lasts 10 ms of virtual time, run 1 the full ten minutes.
  text += "[[sweep]]\nkey = \"campaign.end\"\nvalues = [\"10ms\", \"600s\"]\n";
  const std::string late_read = "at = \"590s\"";
  text.replace(text.find(late_read), late_read.size(), "at = \"5ms\"");
  const fs::path file = dir / "two_runs.toml";
  std::ofstream(file) << text;
  const fs::path out = dir / "out";

  Hilrig hilrig(file, out);
  ASSERT_EQ(hilrig.line().rfind("[1/2] run 0", 0), 0U);
  // Run 0 ends ("[1/2] run 0: fail in ..."), its results are written, then run 1 starts.
  const std::string ended = hilrig.line();
  ASSERT_EQ(ended.rfind("[1/2] run 0: ", 0), 0U) << ended;
  const std::string second = hilrig.line();
  ASSERT_EQ(second.rfind("[2/2] run 1", 0), 0U) << second;
  ASSERT_EQ(::kill(hilrig.pid, SIGKILL), 0);
  const int status = hilrig.wait();
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_FALSE(fs::exists(out / "results.json")); // written at the end only
  const std::string log = hilrig::test::read_file(out / "runs.jsonl");
  EXPECT_EQ(std::count(log.begin(), log.end(), '\n'), 2); // the header and run 0's record

  const std::string merge = std::string(HILRIG_EXE) + " merge " + (out / "results.json").string() + " " +
                            (out / "runs.jsonl").string() + " >/dev/null";
  // The folded result is incomplete, verdict error: incomplete evidence, 3, having written it.
  const int merged = std::system(merge.c_str());
  ASSERT_TRUE(WIFEXITED(merged) && WEXITSTATUS(merged) == 3) << merge << ": " << merged;
  const nlohmann::json results = nlohmann::json::parse(hilrig::test::read_file(out / "results.json"));
  const nlohmann::json schema = nlohmann::json::parse(
      hilrig::test::read_file(fs::path(HILRIG_SOURCE_DIR) / "docs" / "results.schema.json"));
  const std::vector<std::string> problems = rig::test::validate_json_schema(schema, results);
  EXPECT_TRUE(problems.empty()) << problems.front();
  EXPECT_EQ(results.at("complete"), false);
  EXPECT_EQ(results.at("planned_runs"), 2);
  ASSERT_EQ(results.at("runs").size(), 1U);
  EXPECT_EQ(results.at("runs")[0].at("index"), 0);
  // When and where the campaign ran survive the fold too (a trend labels the night by it).
  ASSERT_TRUE(results.contains("wall_clock"));
  EXPECT_TRUE(results.at("wall_clock").contains("started_at"));
  EXPECT_TRUE(results.at("wall_clock").contains("host"));
}

} // namespace
} // namespace hilrig::campaign
