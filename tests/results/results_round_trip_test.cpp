// Every reader of our own files takes back everything our writers write: results.json and
// runs.jsonl written, read and written again are the same bytes, whatever a double holds (a
// number, NaN, +-inf: nlohmann writes the last three as null) and whether a check measured
// anything. And a file that is not what a writer wrote (cut short, hand-edited, another
// schema) is refused with its name and what is wrong, never read half-way or crashed on.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "json_schema_subset.hpp"
#include "rig/results/results_json.hpp"
#include "rig/results/run_log.hpp"
#include "sample_campaign.hpp"
#include "tests/tools/scratch_files.hpp"

namespace hilrig::rig {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// A double as a writer may hold it: an ordinary number most of the time, else NaN or +-inf.
double some_double(std::mt19937_64& rng) {
  switch (rng() % 6) {
  case 0:
    return kNaN;
  case 1:
    return kInf;
  case 2:
    return -kInf;
  default:
    return std::uniform_real_distribution<double>(-1e6, 1e6)(rng);
  }
}

// A run with every double field of every kind of entry, each possibly not finite; some checks
// measured nothing. Measurements are judged as checks judge them (judge()), so a value that is
// not a number reads "error", never "pass".
RunResult random_run(std::uint64_t index, std::mt19937_64& rng) {
  RunResult r = test::nominal_run(index, 12.0);
  for (CheckResult& c : r.checks) {
    for (Measurement& m : c.measurements) {
      m.value = some_double(rng);
      m.outcome = judge(m.value, m.lower, m.upper);
    }
    for (Series& s : c.series)
      for (double& v : s.values) v = some_double(rng);
    if (rng() % 4 == 0) c.measurements.clear(); // a check that judged nothing
  }
  for (Observation& o : r.observations) o.value = some_double(rng);
  r.motion.points = {{Nanos{0}, some_double(rng), some_double(rng)},
                     {Nanos{1'000'000}, some_double(rng), some_double(rng)}};
  CheckResult& c = r.checks.front();
  c.expected_rate = {{Nanos{0}, some_double(rng)}, {Nanos{5'000'000}, some_double(rng)}};
  TraceLane stator{"resolver.sin", LaneRole::Stimulus, {{Nanos{10}, 0, some_double(rng)}}, 0};
  stator.real = true;
  c.traces.push_back(WindowTrace{{Nanos{0}, Nanos{20}}, {Nanos{0}, Nanos{40}}, {stator}});
  return r;
}

CampaignResult random_campaign(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  CampaignResult c = test::sample_campaign(0);
  const std::size_t runs = 1 + rng() % 4;
  for (std::uint64_t i = 0; i < runs; ++i) c.runs.push_back(random_run(i, rng));
  c.planned_runs = runs;
  finalize(c);
  return c;
}

TEST(ResultsRoundTrip, ResultsJsonWriteReadWriteIsByteIdentical) {
  std::ifstream schema_file(HILRIG_SOURCE_DIR "/docs/results.schema.json");
  const json schema = json::parse(schema_file);
  for (std::uint64_t seed = 0; seed < 60; ++seed) {
    const std::string first = to_json_text(random_campaign(seed));
    const auto invalid = test::validate_json_schema(schema, json::parse(first)); // what it says it is
    ASSERT_TRUE(invalid.empty()) << "seed " << seed << ": " << invalid.front();
    const std::string second = to_json_text(campaign_from_json(json::parse(first)));
    ASSERT_EQ(first, second) << "seed " << seed;
  }
}

TEST(ResultsRoundTrip, RunLogWriteReadWriteIsByteIdentical) {
  const fs::path dir = hilrig::test::scratch_dir("results", "round_trip_log");
  for (std::uint64_t seed = 0; seed < 10; ++seed) { // each record is synced: ten campaigns
    const CampaignResult c = random_campaign(seed);
    const auto write_log = [&](const CampaignResult& r, const std::string& name) {
      RunLog log(dir / name, r);
      for (const RunResult& run : r.runs) log.append(run);
      return hilrig::test::read_file(dir / name);
    };
    const std::string a = "a" + std::to_string(seed) + ".jsonl";
    const std::string first = write_log(c, a);
    const CampaignResult back = read_run_log(dir / a);
    ASSERT_EQ(first, write_log(back, "b" + std::to_string(seed) + ".jsonl")) << "seed " << seed;
    // And the results.json folded from it is the one written from the runs themselves.
    ASSERT_EQ(to_json_text(back), to_json_text(c)) << "seed " << seed;
  }
}

// What was NaN or infinite reads back as NaN, which every check and output treats as "not a
// number": a measurement holding one is an error, and its check cannot pass.
TEST(ResultsRoundTrip, ANonFiniteMeasurementReadsBackAsAnErrorNeverAPass) {
  for (const double v : {kNaN, kInf, -kInf}) {
    CampaignResult c = test::sample_campaign(1);
    Measurement& m = c.runs[0].checks[0].measurements[1];
    m.value = v;
    m.outcome = judge(v, m.lower, m.upper);
    ASSERT_EQ(m.outcome, Outcome::Error);
    finalize(c);
    const CampaignResult back = campaign_from_json(json::parse(to_json_text(c)));
    const CheckResult& check = back.runs[0].checks[0];
    EXPECT_TRUE(std::isnan(check.measurements[1].value));
    EXPECT_EQ(check.measurements[1].outcome, Outcome::Error);
    EXPECT_EQ(check.judgement, Judgement::Error);
    EXPECT_EQ(back.verdict, Outcome::Error);
  }
  // A hand-edited file claiming such a measurement passed is refused, naming it.
  json j = json::parse(to_json_text(test::sample_campaign(1)));
  j["runs"][0]["checks"][0]["measurements"][1]["value"] = nullptr;
  try {
    (void)campaign_from_json(j);
    FAIL() << "a null value with outcome pass was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("runs[0]: checks[0]: measurements[1]: results: measurement "
                                         "'ls1-throughput.max' has no value (null) but outcome 'pass'"),
              std::string::npos)
        << e.what();
  }
}

// Reads `text` as file `name` in dir: nothing, or the refusal's message. Anything thrown that
// is not a std::runtime_error naming the file fails the test.
std::string refusal(const fs::path& dir, const std::string& name, const std::string& text) {
  const fs::path path = hilrig::test::write_file(dir, name, text);
  try {
    (void)read_results_file(path);
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(path.string(), 0), 0U) << "does not name the file: " << what;
    return what.empty() ? "?" : what;
  }
  return "";
}

// Every cut of a results.json and of a run log's header is refused (a run log's last record
// without its newline is a record a power loss cut short: its whole records are read).
TEST(ResultsRoundTrip, ACutShortFileIsRefusedWithItsName) {
  const fs::path dir = hilrig::test::scratch_dir("results", "cut_short");
  const std::string text = to_json_text(random_campaign(7));
  for (std::size_t n = 0; n + 1 < text.size(); n += 1 + n / 16)
    EXPECT_NE(refusal(dir, "results.json", text.substr(0, n)), "") << "cut at " << n;
  { RunLog log(dir / "whole.jsonl", random_campaign(7)); }
  const std::string header = hilrig::test::read_file(dir / "whole.jsonl");
  for (std::size_t n = 0; n + 1 < header.size(); n += 1 + n / 16) {
    const std::string why = refusal(dir, "runs.jsonl", header.substr(0, n));
    EXPECT_NE(why, "") << "cut at " << n;
  }
}

// Every value of the file, one at a time, replaced by a value of each other JSON type: the
// reader either takes it (a string where any string goes) or refuses it with a
// std::runtime_error (which read_results_file prefixes with the file's name); no other
// exception, no crash.
TEST(ResultsRoundTrip, AHandEditedValueIsTakenOrRefusedWithTheFilesName) {
  const fs::path dir = hilrig::test::scratch_dir("results", "hand_edited");
  const json doc = json::parse(to_json_text(random_campaign(3)));
  std::vector<json::json_pointer> leaves;
  const std::function<void(const json&, const json::json_pointer&)> walk = [&](const json& j,
                                                                               const json::json_pointer& at) {
    leaves.push_back(at);
    if (j.is_object())
      for (const auto& [k, v] : j.items()) walk(v, at / k);
    if (j.is_array())
      for (std::size_t i = 0; i < j.size(); ++i) walk(j[i], at / i);
  };
  walk(doc, json::json_pointer());
  const std::vector<json> strangers{
      nullptr, "x", -1, 1.5, true, json::array(), json::object(), 18446744073709551615ULL};
  // In memory, every leaf (the file's name is added by read_results_file around the same
  // reader, checked on the whole-file cases below).
  std::size_t refused = 0;
  for (const json::json_pointer& at : leaves)
    for (const json& v : strangers) {
      json edited = doc;
      if (edited[at] == v) continue;
      edited[at] = v;
      try {
        (void)campaign_from_json(edited);
      } catch (const std::runtime_error&) {
        ++refused;
      } // anything else thrown fails the test: gtest reports it with the edit's pointer unknown
    }
  EXPECT_GT(refused, leaves.size()); // most edits are refused; the rest were read, not crashed on
  // A field the reader needs, removed; and the whole of another schema.
  json no_runs = doc;
  no_runs.erase("runs");
  EXPECT_NE(refusal(dir, "results.json", no_runs.dump()).find("has no 'runs'"), std::string::npos);
  json runs_object = doc;
  runs_object["runs"] = json::object({{"0", doc["runs"][0]}});
  EXPECT_NE(refusal(dir, "results.json", runs_object.dump()).find("runs is object, not an array"),
            std::string::npos);
  EXPECT_NE(
      refusal(dir, "results.json", R"({"format": "junit", "version": 2})").find("not a hilrig results file"),
      std::string::npos);
  EXPECT_NE(refusal(dir, "results.json", "[1, 2, 3]"), "");
  EXPECT_NE(refusal(dir, "runs.jsonl", doc.dump() + "\n").find("not a hilrig run log"), std::string::npos);
}

} // namespace
} // namespace hilrig::rig
