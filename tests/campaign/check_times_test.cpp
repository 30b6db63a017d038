// A check's instants (a window's ends, crossing times, at_ms, applied_ms) lie within the run,
// 0 .. campaign.end, and a word check's at_ms is not before the first read of its word: either
// would judge nothing, found only after the whole run. The campaign reader refuses them before
// anything runs, with the key, the run's range and the value (the standard's "bad input gets a
// clear error before anything runs"). Each instant is swept across the run's end (100 ms in
// kValidCampaign): at the end accepted, one ns past it refused, as the check itself rounds
// the number to whole ns.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "campaign_text.hpp"
#include "rig/checks/registry.hpp"

namespace hilrig::campaign {
namespace {

using test::error_of;

// kValidCampaign (30 lines, end 100 ms) with a [[host]] read "pos" (at 0 unless given) (lines 31..34) and
// one more check from line 35: kind, name, its keys, then KEY = VALUE on line 38 + keys.
struct SweptInstant {
  const char* kind;
  std::vector<std::string> keys; // the check's other keys, one a line
  const char* key;
  double end_value; // campaign.end (100 ms) in the key's unit
};

const std::vector<SweptInstant>& swept_instants() {
  static const std::vector<SweptInstant> all = {
      {"throughput", {"output = \"ls1\"", "limit_us = 250", "setpoint = 10"}, "from_us", 100'000},
      {"throughput", {"output = \"ls1\"", "limit_us = 250", "setpoint = 10"}, "to_us", 100'000},
      {"edge_at_position", {"output = \"ls1\"", "position = 10"}, "from_us", 100'000},
      {"edge_at_position", {"output = \"ls1\"", "position = 10"}, "to_us", 100'000},
      {"brake_stop_time", {"limit_ms = 10"}, "applied_ms", 100},
      {"word_equals", {"observation = \"pos\"", "value = 1"}, "at_ms", 100},
      {"word_within", {"observation = \"pos\"", "upper = 5"}, "at_ms", 100},
      {"word_bits", {"observation = \"pos\"", "mask = 1", "value = 1"}, "at_ms", 100},
      {"shaft_move", {"step_line = \"ls1\"", "dir_line = \"ls1\"", "steps = 0"}, "from_ms", 100},
      {"shaft_move", {"step_line = \"ls1\"", "dir_line = \"ls1\"", "steps = 0", "from_ms = 0"}, "to_ms", 100},
  };
  return all;
}

std::string campaign_with_check(const SweptInstant& c, const std::string& value_line,
                                const std::string& read_at = "0ms") {
  std::string text = test::kValidCampaign + "[[host]]\nat = \"" + read_at + "\"\nread = 0\nname = \"pos\"\n";
  text += "[[check]]\nkind = \"" + std::string(c.kind) + "\"\nname = \"c\"\n";
  for (const std::string& k : c.keys) text += k + "\n";
  return text + value_line + "\n";
}

// "t.toml:LINE:COL: check[1].KEY: " for the instant's value line.
std::string instant_where(const SweptInstant& c) {
  const std::size_t line = 38 + c.keys.size();
  return "t.toml:" + std::to_string(line) + ":" + std::to_string(std::string(c.key).size() + 4) +
         ": check[1]." + c.key + ": ";
}

std::string as_toml_number(double v) {
  std::string s = std::to_string(v);
  s.erase(s.find_last_not_of('0') + 1);
  if (s.back() == '.') s.pop_back();
  return s;
}

// A shaft_move's window (from_ms, to_ms] or a throughput scan's (from_us, to_us] with no whole
// ns in it (the other end at its default, 0 or campaign.end): refused on its own (below).
bool empty_step_window(const SweptInstant& c, double v) {
  const std::string kind = c.kind;
  const std::string key = c.key;
  if (kind != "shaft_move" && kind != "throughput") return false;
  const double ns = std::round(v * (key.ends_with("_us") ? 1e3 : 1e6));
  return key.starts_with("from") ? ns >= 100e6 : ns <= 0.0;
}

TEST(CheckTimes, EachInstantIsAcceptedUpToTheRunsEndAndRefusedPastIt) {
  for (const SweptInstant& c : swept_instants()) {
    SCOPED_TRACE(std::string(c.kind) + "." + c.key);
    const double ns = std::string(c.key).ends_with("_us") ? 1e3 : 1e6;
    for (const double v : {0.0, c.end_value / 2, c.end_value, c.end_value + 0.4 / ns})
      if (!empty_step_window(c, v)) {
        EXPECT_EQ(error_of(campaign_with_check(c, std::string(c.key) + " = " + as_toml_number(v))),
                  "accepted")
            << v;
      }
    for (const double v : {c.end_value + 1.0 / ns, c.end_value * 1.03, c.end_value + 1'000})
      EXPECT_EQ(error_of(campaign_with_check(c, std::string(c.key) + " = " + as_toml_number(v))),
                instant_where(c) + "a time within the run, 0 .. " + as_toml_number(c.end_value) + " " +
                    std::string(c.key).substr(std::string(c.key).size() - 2) + " (campaign.end); " +
                    as_toml_number(v) + " " + std::string(c.key).substr(std::string(c.key).size() - 2) +
                    " is after it")
          << v;
  }
}

// shaft_move counts the steps after from_ms and up to to_ms (the run's end, 100 ms, by
// default), in whole ns: a window with no ns in it holds no step, and its limits (steps = 0
// here) would pass a board having judged nothing. Swept across the empty window's edge.
TEST(CheckTimes, AShaftMoveWindowWithNoInstantInItIsRefused) {
  const SweptInstant from{
      "shaft_move", {"step_line = \"ls1\"", "dir_line = \"ls1\"", "steps = 0"}, "from_ms", 100};
  for (const char* v : {"0", "99.999999", "99.9999994"})
    EXPECT_EQ(error_of(campaign_with_check(from, std::string("from_ms = ") + v)), "accepted") << v;
  for (const char* v : {"99.9999996", "100", "100.0000004"})
    EXPECT_EQ(error_of(campaign_with_check(from, std::string("from_ms = ") + v)),
              instant_where(from) + "a window with time in it: steps after from_ms (" + v +
                  " ms) and up to campaign.end (100 ms) count, in whole ns, and this one holds none")
        << v;
  const SweptInstant to{
      "shaft_move", {"step_line = \"ls1\"", "dir_line = \"ls1\"", "steps = 0", "from_ms = 40"}, "to_ms", 100};
  EXPECT_EQ(error_of(campaign_with_check(to, "to_ms = 40.000001")), "accepted");
  EXPECT_EQ(error_of(campaign_with_check(to, "to_ms = 40.0000004")),
            instant_where(to) +
                "a window with time in it: steps after from_ms (40 ms) and up to to_ms (40 ms) "
                "count, in whole ns, and this one holds none");
  EXPECT_EQ(error_of(campaign_with_check(to, "to_ms = 40")),
            instant_where(to) +
                "a window with time in it: steps after from_ms (40 ms) and up to to_ms (40 ms) "
                "count, in whole ns, and this one holds none");
}

// A throughput scan finds the setpoint's crossings after from_us and up to to_us (0 and
// campaign.end, 100 ms, by default), in whole ns (rig/checks/crossings.hpp: (from, to]): a window
// with no ns in it finds none, and the run could only err. Swept across the empty window's edge.
TEST(CheckTimes, AThroughputScanWindowWithNoInstantInItIsRefused) {
  const std::vector<std::string> scan{"output = \"ls1\"", "limit_us = 250", "setpoint = 10"};
  const SweptInstant from{"throughput", scan, "from_us", 100'000};
  for (const char* v : {"0", "99999.999", "99999.9994"})
    EXPECT_EQ(error_of(campaign_with_check(from, std::string("from_us = ") + v)), "accepted") << v;
  for (const char* v : {"99999.9996", "100000", "100000.0004"})
    EXPECT_EQ(error_of(campaign_with_check(from, std::string("from_us = ") + v)),
              instant_where(from) + "a window with time in it: setpoint crossings after from_us (" + v +
                  " us) and up to campaign.end (100000 us) count, in whole ns, and this one holds none")
        << v;
  const SweptInstant to{"throughput", scan, "to_us", 100'000};
  for (const char* v : {"0.001", "0.0005"})
    EXPECT_EQ(error_of(campaign_with_check(to, std::string("to_us = ") + v)), "accepted") << v;
  for (const char* v : {"0.0004", "0"})
    EXPECT_EQ(error_of(campaign_with_check(to, std::string("to_us = ") + v)),
              instant_where(to) +
                  "a window with time in it: setpoint crossings after the run's start (0 us) and up to "
                  "to_us (0 us) count, in whole ns, and this one holds none")
        << v;
  // Both given (the auditor's from_us = to_us, and a pair equal once rounded): to_us is named.
  std::vector<std::string> from_1000 = scan;
  from_1000.emplace_back("from_us = 1000");
  const SweptInstant both{"throughput", from_1000, "to_us", 100'000};
  for (const char* v : {"1000.001", "1000.0006"})
    EXPECT_EQ(error_of(campaign_with_check(both, std::string("to_us = ") + v)), "accepted") << v;
  for (const char* v : {"1000", "1000.0004"})
    EXPECT_EQ(error_of(campaign_with_check(both, std::string("to_us = ") + v)),
              instant_where(both) +
                  "a window with time in it: setpoint crossings after from_us (1000 us) and up to to_us "
                  "(1000 us) count, in whole ns, and this one holds none")
        << v;
  std::vector<std::string> from_round = scan;
  from_round.emplace_back("from_us = 1000.0001");
  EXPECT_EQ(error_of(campaign_with_check({"throughput", from_round, "to_us", 100'000}, "to_us = 1000.0004")),
            "t.toml:42:9: check[1].to_us: a window with time in it: setpoint crossings after from_us "
            "(1000.0001 us) and up to to_us (1000 us) count, in whole ns, and this one holds none");
}

// Every parameter the registry calls an instant is swept above: one added later is too.
TEST(CheckTimes, TheSweepCoversEveryInstantTheChecksName) {
  std::set<std::pair<std::string, std::string>> swept;
  for (const SweptInstant& c : swept_instants()) swept.emplace(c.kind, c.key);
  swept.emplace("throughput", "crossings_us"); // a list: its own test below
  std::set<std::pair<std::string, std::string>> named;
  for (const checks::CheckKind& k : checks::check_kinds())
    for (const checks::ParamSpec& p : k.params)
      if (p.instant_ns > 0) named.emplace(k.name, p.name);
  EXPECT_EQ(named, swept);
}

TEST(CheckTimes, ACrossingAfterTheRunsEndIsRefused) {
  const SweptInstant c{"throughput", {"output = \"ls1\"", "limit_us = 250"}, "crossings_us", 100'000};
  EXPECT_EQ(error_of(campaign_with_check(c, "crossings_us = [10, 50000, 100000]")), "accepted");
  EXPECT_EQ(error_of(campaign_with_check(c, "crossings_us = [10, 100000.001, 20]")),
            instant_where(c) +
                "a time within the run, 0 .. 100000 us (campaign.end); 100000.001 us is after it");
}

// A word check judges the latest observation at or before at_ms: before the first read
// (1 ms) there is none.
TEST(CheckTimes, AWordJudgedBeforeItsFirstReadIsRefused) {
  const SweptInstant c{"word_equals", {"observation = \"pos\"", "value = 1"}, "at_ms", 100};
  for (const char* ok : {"at_ms = 1", "at_ms = 0.9999996", "at_ms = 2"})
    EXPECT_EQ(error_of(campaign_with_check(c, ok, "1ms")), "accepted") << ok;
  for (const char* early : {"at_ms = 0.999999", "at_ms = 0.97", "at_ms = 0"})
    EXPECT_EQ(error_of(campaign_with_check(c, early, "1ms"))
                  .rfind(instant_where(c) + "a time at or after the first [[host]] read of \"pos\" (1 ms): "
                                            "no observation exists before it;",
                         0),
              0U)
        << early << ": " << error_of(campaign_with_check(c, early, "1ms"));
}

} // namespace
} // namespace hilrig::campaign
