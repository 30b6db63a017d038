// Issue 20: scan skipping is exact. Every shipped campaign (campaigns/**.toml but the RT VM
// lane's) runs twice as `hilrig run` runs it: skipping the scans that change nothing (the
// default) and with --exact-scan (a scan every period, the oracle), both with the same --epoch
// (the wall-clock start they write). trace.vcd and can.log (a campaign on a resolver: the CAN
// stream to the resolver emulator) must be the same bytes, and results.json and junit.xml too
// once the wall time junit.xml measures (its time attributes), which differs between any two
// runs, is blanked.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "rig/cli/run_command.hpp"
#include "test_support.hpp"
#include "tests/tools/scratch_files.hpp"

namespace hilrig::cli {
namespace {

namespace fs = std::filesystem;

using campaign::test::shipped_campaigns;

// The first line where two texts differ, for a readable failure (the VCDs run to megabytes).
std::string first_difference(const std::string& a, const std::string& b) {
  std::istringstream sa(a);
  std::istringstream sb(b);
  std::string la;
  std::string lb;
  for (std::size_t line = 1;; ++line) {
    const bool ga = static_cast<bool>(std::getline(sa, la));
    const bool gb = static_cast<bool>(std::getline(sb, lb));
    if (!ga && !gb) return "same lines";
    if (ga != gb || la != lb)
      return "line " + std::to_string(line) + ": skipping \"" + la + "\", every scan \"" + lb + "\"";
  }
}

// junit.xml's `time` attributes (the wall time each run took) blanked: the one thing --epoch
// cannot fix. Its timestamp comes from the --epoch both runs share, its hostname is this machine.
std::string without_wall_durations(const std::string& text) {
  static const std::regex junit(R"( time="[^"]*")");
  return std::regex_replace(text, junit, " time=\"\"");
}

fs::path run(const fs::path& file, bool exact_scan) {
  const fs::path out =
      hilrig::test::scratch_dir("campaign", (exact_scan ? "exact_" : "skip_") + file.stem().string());
  std::ostringstream err;
  RunOptions o;
  o.file = file.string();
  o.out = out;
  o.shard = "0/1";
  o.exact_scan = exact_scan;
  o.epoch = 1'767'225'600; // 2026-01-01T00:00:00Z
  EXPECT_NE(run_campaign(o, err), 2) << err.str();
  return out;
}

// results.json, junit.xml (wall durations blanked), trace.vcd and, for a board on a resolver, the
// can.log it reads the resolver from, of both engines, byte for byte.
void expect_same_bytes(const fs::path& file) {
  const fs::path skip = run(file, false);
  const fs::path every = run(file, true);
  // A board on a resolver reads it from the CAN stream, which can.log records.
  const std::string text = hilrig::test::read_file(file);
  const bool can = text.find("\n[resolver]") != std::string::npos;
  std::vector<std::string> names{"results.json", "junit.xml", "trace.vcd"};
  if (can) names.emplace_back("can.log");
  EXPECT_EQ(fs::exists(skip / "can.log"), can);
  for (const std::string& name : names) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(fs::exists(every / name));
    const bool wall = name == "junit.xml";
    std::string a = hilrig::test::read_file(skip / name);
    std::string b = hilrig::test::read_file(every / name);
    if (wall) {
      a = without_wall_durations(a);
      b = without_wall_durations(b);
    }
    EXPECT_FALSE(b.empty());
    EXPECT_TRUE(a == b) << first_difference(a, b);
  }
}

TEST(ExactScan, EveryShippedCampaignGivesTheSameBytesAsScanningEveryPeriod) {
  const auto files = shipped_campaigns();
  ASSERT_GE(files.size(), 30U);
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.filename().string());
    expect_same_bytes(file);
  }
}

// The bench press (bench/campaigns/ans1_press.toml: 1,800 RPM on a 1,024-line encoder, 16
// advanced outputs, the brake monitor), shortened to 6 strokes: scans skipped while the
// encoder moves, between output changes and brake-monitor ticks.
TEST(ExactScan, TheBenchPressCampaignGivesTheSameBytesWhileMoving) {
  std::string text = hilrig::test::read_file(fs::path(HILRIG_SOURCE_DIR) / "bench/campaigns/ans1_press.toml");
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"strokes = 60", "strokes = 6"},
                                 {"end = \"2100ms\"", "end = \"300ms\""}}) {
    const std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  }
  expect_same_bytes(hilrig::test::write_file(hilrig::test::scratch_dir("campaign", "exact_press"),
                                             "ans1_press_short.toml", text));
}

// The knobs move what a scan decides in time (a timer's expiry with timer_error): the deadline
// scan skipping wakes for must move with it. ans1_timed swept across its thresholds both ways
// (docs/power.md: the on time is ceil((timer + e) / 10 us) scans), including values at which
// the pulse widths fail.
TEST(ExactScan, KnobsAwayFromTheManualGiveTheSameBytes) {
  std::string text = hilrig::test::read_file(fs::path(HILRIG_SOURCE_DIR) / "campaigns/ans1/ans1_timed.toml");
  const std::string model = "[dut]\nmodel = \"ans1\"\n";
  const std::size_t at = text.find(model);
  ASSERT_NE(at, std::string::npos);
  text.insert(at + model.size(), "[dut.params]\ntimer_error = \"0ns\"\n");
  text += "\n[[sweep]]\nkey = \"dut.params.timer_error\"\n"
          "values = [\"-1010001ns\", \"-1010000ns\", \"-1009999ns\", \"-3ms\", \"1ms\", \"1000001ns\", "
          "\"7ms\"]\n";
  const fs::path file = hilrig::test::write_file(hilrig::test::scratch_dir("campaign", "exact_knobs"),
                                                 "ans1_timed_knobs.toml", text);
  const fs::path skip = run(file, false);
  const fs::path every = run(file, true);
  for (const char* name : {"results.json", "junit.xml"}) {
    SCOPED_TRACE(name);
    const std::string a = without_wall_durations(hilrig::test::read_file(skip / name));
    const std::string b = without_wall_durations(hilrig::test::read_file(every / name));
    EXPECT_NE(b.find("\"fail\""), std::string::npos); // some points are beyond the limit
    EXPECT_TRUE(a == b) << first_difference(a, b);
  }
}

} // namespace
} // namespace hilrig::cli
