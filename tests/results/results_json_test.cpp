#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "json_schema_subset.hpp"
#include "rig/results/merge.hpp"
#include "rig/results/results_json.hpp"
#include "sample_campaign.hpp"

namespace hilrig::rig {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

json load_schema() {
  std::ifstream in(HILRIG_SOURCE_DIR "/docs/results.schema.json");
  EXPECT_TRUE(in.good());
  return json::parse(in);
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(HILRIG_BINARY_DIR) / "tests" / "results" / "scratch";
  fs::create_directories(dir);
  return dir / name;
}

TEST(ResultsJson, ValidatesAgainstTheDocumentedSchema) {
  CampaignResult c = test::sample_campaign(6);
  c.runs[0].error = "bus-off"; // a null-able string present
  c.started_at = "2026-11-22T05:00:00";
  finalize(c);
  const auto errors = test::validate_json_schema(load_schema(), to_json(c));
  EXPECT_TRUE(errors.empty()) << errors.front();
}

TEST(ResultsJson, MotionAndProbesValidateAndRoundTrip) {
  CampaignResult c = test::sample_campaign(2);
  c.runs[0].motion.points = {{Nanos{0}, 0.0, 1000.0}, {Nanos{100'000'000}, 50.0, 0.0}};
  c.runs[0].motion.events = {{Nanos{0}, "valve off: brake applied, clutch released"}};
  c.runs[1].checks[0].probes = {{Nanos{20'000}, false}, {Nanos{40'000}, true, Nanos{100'500'000}}};
  finalize(c);
  const json j = to_json(c);
  const auto errors = test::validate_json_schema(load_schema(), j);
  EXPECT_TRUE(errors.empty()) << errors.front();
  EXPECT_EQ(j["runs"][0]["motion"]["points"][1], json::array({100'000'000, 50.0, 0.0}));
  EXPECT_FALSE(j["runs"][1].contains("motion")); // absent when not recorded: other runs keep their bytes
  const CampaignResult back = campaign_from_json(json::parse(to_json_text(c)));
  EXPECT_EQ(to_json(back), j);
  ASSERT_EQ(back.runs[1].checks[0].probes.size(), 2U);
  EXPECT_TRUE(back.runs[1].checks[0].probes[1].accepted);
  // A probe's start phase only when the debounce check probed several: others keep their bytes.
  EXPECT_FALSE(j["runs"][1]["checks"][0]["probes"][0].contains("start_ns"));
  EXPECT_EQ(j["runs"][1]["checks"][0]["probes"][1]["start_ns"], 100'500'000);
  EXPECT_EQ(back.runs[1].checks[0].probes[1].start, Nanos{100'500'000});
}

TEST(ResultsJson, TheSchemaCheckerRejectsABrokenFile) {
  // The checker is only worth something if it says no: drop a required field, retype another.
  json j = to_json(test::sample_campaign(3));
  j["runs"][0]["checks"][0]["measurements"][0].erase("unit");
  j["totals"]["runs"] = "three";
  j["extra"] = 1;
  const auto errors = test::validate_json_schema(load_schema(), j);
  EXPECT_EQ(errors.size(), 3U);
}

TEST(ResultsJson, RoundTripKeepsEverything) {
  CampaignResult c = test::sample_campaign(5);
  c.host = "rig-7";
  const CampaignResult back = campaign_from_json(json::parse(to_json_text(c)));
  EXPECT_EQ(to_json(back), to_json(c));
  ASSERT_TRUE(back.runs[0].checks[1].measurements[0].at);
  EXPECT_EQ(back.runs[0].checks[1].measurements[0].at->count(), 156'666'667);
  EXPECT_EQ(back.runs[0].checks[0].series[0].values, (std::vector<double>{12.0, 15.0, 10.0}));
}

// A run index twice (a hand-edited file, two pasted together) is refused by every reader
// (compare and trend counted it twice; merge refused it already), naming the index.
TEST(ResultsJson, ARunIndexTwiceIsRefused) {
  const json j = to_json(test::sample_campaign(3));
  ASSERT_NO_THROW((void)campaign_from_json(j));
  json twice = j;
  twice["runs"].push_back(j["runs"][1]);
  try {
    (void)campaign_from_json(twice);
    ADD_FAILURE() << "accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("run 1 appears twice"), std::string::npos) << e.what();
  }
}

// A resolver board's stators are analog lanes: their volts survive the round trip exactly,
// beside an integer lane that stays as it was (no "real" key), and both fit the schema.
TEST(ResultsJson, ARealLaneRoundTripsWithItsVolts) {
  CampaignResult c = test::sample_campaign(6);
  finalize(c);
  CheckResult& check = c.runs[0].checks[1];
  ASSERT_TRUE(check.measurements[0].window);
  const TraceWindow around = *check.measurements[0].window;
  WindowTrace w{around, around, {}};
  TraceLane sin{"resolver.sin", LaneRole::Stimulus, {}, 3, true};
  for (const double v : {-0.1, 0.3826834323650898, 0.7071067811865476, -1.0, 1e-300})
    sin.changes.push_back(
        LaneChange{around.begin + Nanos{static_cast<std::int64_t>(sin.changes.size()) * 200'000}, 0, v});
  w.lanes.push_back(sin);
  w.lanes.push_back(TraceLane{"shaft.count", LaneRole::Count, {{around.begin, 41}, {around.end, 42}}, 0});
  check.traces.push_back(w);
  const json j = to_json(c);
  const auto errors = test::validate_json_schema(load_schema(), j);
  EXPECT_TRUE(errors.empty()) << errors.front();
  const json& lanes = j["runs"][0]["checks"][1]["traces"][0]["lanes"];
  EXPECT_EQ(lanes[0]["real"], true);
  EXPECT_FALSE(lanes[1].contains("real"));
  const CampaignResult back = campaign_from_json(json::parse(to_json_text(c)));
  EXPECT_EQ(to_json(back), j);
  const TraceLane& got = back.runs[0].checks[1].traces.at(0).lanes.at(0);
  EXPECT_TRUE(got.real);
  EXPECT_EQ(got.thinned, 3U);
  ASSERT_EQ(got.changes.size(), sin.changes.size());
  for (std::size_t i = 0; i < got.changes.size(); ++i) {
    EXPECT_EQ(got.changes[i].time, sin.changes[i].time);
    EXPECT_EQ(got.changes[i].real, sin.changes[i].real); // shortest round-trip text: exact
  }
  EXPECT_FALSE(back.runs[0].checks[1].traces.at(0).lanes.at(1).real);
  EXPECT_EQ(back.runs[0].checks[1].traces.at(0).lanes.at(1).changes.at(1).value, 42);
  // A real value in an integer lane is no lane change.
  json broken = j;
  broken["runs"][0]["checks"][1]["traces"][0]["lanes"][1]["changes"][0][1] = 0.5;
  EXPECT_THROW((void)campaign_from_json(broken), std::runtime_error);
}

// Stator volts as the cut writes them, to 1 uV (kRealLaneResolution in
// rig/campaign/window_traces.hpp): the text holds at most six decimals (no float noise such as
// 0.38268300000000002) and reads back to the same doubles.
TEST(ResultsJson, StatorVoltsToOneMicrovoltRoundTripInSixDecimals) {
  CampaignResult c = test::sample_campaign(2);
  finalize(c);
  CheckResult& check = c.runs[0].checks[1];
  const TraceWindow around = *check.measurements[0].window;
  TraceLane sin{"resolver.sin", LaneRole::Stimulus, {}, 0, true};
  for (const double v : {0.382683, -0.707107, 1.0, 0.000001, -0.999999, 0.1, 2.123457})
    sin.changes.push_back(
        LaneChange{around.begin + Nanos{static_cast<std::int64_t>(sin.changes.size()) * 200'000}, 0, v});
  check.traces.push_back(WindowTrace{around, around, {sin}});
  const std::string text = to_json_text(c);
  const json lane = json::parse(text)["runs"][0]["checks"][1]["traces"][0]["lanes"][0];
  for (const auto& change : lane["changes"]) {
    const std::string volts = change[1].dump();
    const auto dot = volts.find('.');
    EXPECT_TRUE(dot == std::string::npos || volts.size() - dot - 1 <= 6) << volts;
  }
  const CampaignResult back = campaign_from_json(json::parse(text));
  const auto& got = back.runs[0].checks[1].traces.at(0).lanes.at(0).changes;
  ASSERT_EQ(got.size(), sin.changes.size());
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i].real, sin.changes[i].real);
}

// A shaft_move check's expected profile (CheckResult::expected_rate) round-trips as
// [time_ns, steps/s] knots, fits the schema, and is absent (the entry's bytes unchanged) for a
// check without one.
TEST(ResultsJson, ExpectedRateKnotsRoundTrip) {
  CampaignResult c = test::sample_campaign(2);
  finalize(c);
  const json before = to_json(c);
  CheckResult& check = c.runs[0].checks[0];
  EXPECT_FALSE(before["runs"][0]["checks"][0].contains("expected_rate"));
  check.expected_rate = {
      {Nanos{610'000'000}, 1000.0}, {Nanos{678'102'497}, 7810.249675906654}, {Nanos{746'204'994}, 1000.0}};
  const json j = to_json(c);
  const auto errors = test::validate_json_schema(load_schema(), j);
  EXPECT_TRUE(errors.empty()) << errors.front();
  EXPECT_EQ(j["runs"][0]["checks"][0]["expected_rate"][1], json::array({678'102'497, 7810.249675906654}));
  const CampaignResult back = campaign_from_json(json::parse(to_json_text(c)));
  ASSERT_EQ(back.runs[0].checks[0].expected_rate.size(), 3U);
  EXPECT_EQ(back.runs[0].checks[0].expected_rate[1].time, Nanos{678'102'497});
  EXPECT_EQ(back.runs[0].checks[0].expected_rate[1].rate, 7810.249675906654);
  EXPECT_EQ(to_json(back), j);
  json broken = j;
  broken["runs"][0]["checks"][0]["expected_rate"][0] = json::array({0.5, 1000.0});
  EXPECT_THROW((void)campaign_from_json(broken), std::runtime_error);
}

TEST(ResultsJson, ANotANumberValueIsWrittenAsNullAndReadBackAsNaN) {
  CampaignResult c = test::sample_campaign(1);
  c.runs[0].checks[0].measurements[1].value = std::numeric_limits<double>::quiet_NaN();
  c.runs[0].checks[0].measurements[1].outcome = Outcome::Error;
  finalize(c);
  const json j = json::parse(to_json_text(c));
  EXPECT_TRUE(j["runs"][0]["checks"][0]["measurements"][1]["value"].is_null());
  EXPECT_TRUE(test::validate_json_schema(load_schema(), j).empty());
  EXPECT_TRUE(std::isnan(campaign_from_json(j).runs[0].checks[0].measurements[1].value));
}

TEST(ResultsJson, DeterministicTextWhateverOrderRunsArrive) {
  CampaignResult a = test::sample_campaign(6);
  CampaignResult b = a;
  std::reverse(b.runs.begin(), b.runs.end());
  finalize(b);
  EXPECT_EQ(to_json_text(a), to_json_text(b));
  // Keys sorted: "campaign" comes before "complete" before "device".
  const std::string text = to_json_text(a);
  EXPECT_LT(text.find("\"campaign\""), text.find("\"complete\""));
  EXPECT_LT(text.find("\"complete\""), text.find("\"device\""));
}

TEST(ResultsJson, AtomicWriteLeavesNoTempAndPartialProgressIsReadable) {
  const fs::path path = scratch("progress.json");
  CampaignResult c = test::sample_campaign(6);
  CampaignResult partial = c;
  partial.runs.resize(2);
  finalize(partial);
  write_results_file(path, partial);
  EXPECT_FALSE(fs::exists(path.string() + ".tmp"));
  CampaignResult read = read_results_file(path);
  EXPECT_FALSE(read.complete);
  EXPECT_EQ(read.verdict, Outcome::Error);
  EXPECT_EQ(read.runs.size(), 2U);
  write_results_file(path, c); // rewritten as runs finish
  read = read_results_file(path);
  EXPECT_TRUE(read.complete);
  EXPECT_TRUE(same_content(read, c));
}

// The compact text made from the indented one is nlohmann's own compact dump, byte for byte:
// strings that hold what the compaction drops outside them (spaces, ": ", escaped line
// breaks, quotes and backslashes, "</"), empty and nested containers, numbers of each kind.
TEST(ResultsJson, CompactTextFromTheIndentedDumpIsTheCompactDump) {
  const json tricky = {
      {"a key: with spaces", "value: \"quoted\" \\ back\\slash\\"},
      {"lines", "one\ntwo\r\n  three\t"},
      {"empty", json::object()},
      {"none", json::array()},
      {"nested",
       {{"x", {1, -2, 3.5, 1e300, -0.0}},
        {"y", {true, false, nullptr}},
        {"z", json::array({json::array()})}}},
      {"unicode", "µs \u00e9 </script> \x01"},
      {"trailing\\", "\\"},
  };
  for (const int indent : {0, 1, 2, 4})
    EXPECT_EQ(compact_json_text(tricky.dump(indent)), tricky.dump()) << indent;
  CampaignResult c = test::sample_campaign(4);
  c.runs[1].error = "bus-off: \"frame\"\n  lost";
  finalize(c);
  for (const RunResult& run : c.runs) {
    const json j = run_to_json(run);
    EXPECT_EQ(compact_json_text(j.dump(2)), j.dump());
  }
  EXPECT_EQ(compact_json_text(to_json(c).dump(2)), to_json(c).dump());
}

TEST(ResultsJson, ReadingRejectsWhatIsNotAResultsFile) {
  const fs::path path = scratch("bad.json");
  std::ofstream(path) << "{\"format\": \"something-else\", \"version\": 1}";
  EXPECT_THROW((void)read_results_file(path), std::runtime_error);
  std::ofstream(path) << "{ not json";
  EXPECT_THROW((void)read_results_file(path), std::runtime_error);
  EXPECT_THROW((void)read_results_file(scratch("does-not-exist.json")), std::runtime_error);
}

} // namespace
} // namespace hilrig::rig
