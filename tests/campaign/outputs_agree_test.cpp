// Issue 16 item 6: exit status, results.json, junit.xml and report.html agree on every shipped
// campaign (campaigns/**.toml but the RT VM lane's). Each campaign is run as `hilrig run` runs
// it and the three files are read back as files; junit.xml and report.html are derived from
// results.json, so every count below must match the words results.json holds.

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "rig/cli/run_command.hpp"
#include "test_support.hpp"
#include "tests/tools/scratch_files.hpp"

namespace hilrig::cli {
namespace {

namespace fs = std::filesystem;

using campaign::test::shipped_campaigns;

// An attribute of the <testsuites> element.
std::size_t suites_attr(const std::string& junit, const std::string& name) {
  std::smatch m;
  const std::regex re("<testsuites [^>]*\\b" + name + "=\"([0-9]+)\"");
  if (!std::regex_search(junit, m, re)) return static_cast<std::size_t>(-1);
  return std::stoul(m[1].str());
}

TEST(OutputsAgree, EveryShippedCampaign) {
  const auto files = shipped_campaigns();
  ASSERT_GE(files.size(), 30U);
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.filename().string());
    const fs::path out = hilrig::test::scratch_dir("campaign", "agree_" + file.stem().string());
    std::ostringstream err;
    RunOptions o;
    o.file = file.string();
    o.out = out;
    o.shard = "0/1";
    const int status = run_campaign(o, err);

    const auto results = nlohmann::json::parse(hilrig::test::read_file(out / "results.json"));
    const std::string junit = hilrig::test::read_file(out / "junit.xml");
    const std::string report = hilrig::test::read_file(out / "report.html");
    const std::string verdict = results.at("verdict");

    // Exit status and verdict.
    EXPECT_EQ(status == 0, verdict == "pass") << err.str();
    if (verdict == "fail") {
      EXPECT_EQ(status, 1);
    }
    // Shipped campaigns are meant to pass: a failure here is a rig or model regression.
    EXPECT_EQ(verdict, "pass") << err.str();

    // The words results.json holds, counted.
    std::map<std::string, std::size_t> words;
    std::size_t rig_errors = 0;
    for (const auto& run : results.at("runs")) {
      if (!run.at("error").is_null()) ++rig_errors;
      for (const auto& c : run.at("checks")) ++words[c.at("outcome").get<std::string>()];
    }
    const auto& t = results.at("totals");
    EXPECT_EQ(t.at("checks_passed"), words["pass"]);
    EXPECT_EQ(t.at("checks_failed"), words["fail"]);
    EXPECT_EQ(t.at("checks_caught"), words["caught"]);
    EXPECT_EQ(t.at("checks_not_judged"), words["not judged"]);
    EXPECT_EQ(t.at("checks_errored"), words["error"]);

    // junit.xml: failures, errors and skips are the fail, error and not-judged words.
    EXPECT_EQ(suites_attr(junit, "failures"), words["fail"]);
    EXPECT_EQ(suites_attr(junit, "errors"), words["error"] + rig_errors);
    EXPECT_EQ(hilrig::test::count_of(junit, "<skipped "), words["not judged"]);
    EXPECT_EQ(suites_attr(junit, "failures") + suites_attr(junit, "errors") == 0, verdict == "pass");

    // report.html: the same verdict, the same words, and nothing red in a passing campaign.
    EXPECT_NE(report.find("Verdict: <span class=\"" + verdict + "\">" + verdict + "</span>"),
              std::string::npos);
    const std::size_t check_sections =
        hilrig::test::count_of(report, "<h4>") - hilrig::test::count_of(report, "<h4>observations</h4>");
    EXPECT_EQ(check_sections,
              words["pass"] + words["fail"] + words["caught"] + words["not judged"] + words["error"]);
    for (const auto& [word, n] : words) {
      const std::string cls = word == "not judged" ? "not-judged" : word;
      EXPECT_GE(hilrig::test::count_of(report, "<span class=\"" + cls + "\">" + word + "</span>"), n) << word;
    }
    if (verdict == "pass") {
      EXPECT_EQ(hilrig::test::count_of(report, "class=\"fail\""), 0U);
      EXPECT_EQ(hilrig::test::count_of(report, "class=\"error\""), 0U);
    }
  }
}

} // namespace
} // namespace hilrig::cli
