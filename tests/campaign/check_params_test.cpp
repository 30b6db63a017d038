// Issue 16 item 5: check parameters are validated where the campaign is read. NaN, inf and
// negatives where a limit, tolerance or duration is expected, minimums of 0, a word_bits mask
// of 0 and a campaign with no check are bad input: "file:line:column: key: valid range".

#include <gtest/gtest.h>

#include <string>

#include "campaign_text.hpp"
#include "rig/campaign/campaign_parser.hpp"

namespace hilrig::campaign {
namespace {

using test::error_of;

TEST(CheckParams, AValidLimitIsAccepted) {
  EXPECT_EQ(error_of(test::kCampaignToSetpoint + "limit_us = 20.3\n"), "accepted");
}

TEST(CheckParams, NotFiniteOrNegativeLimitIsBadInputAtItsValue) {
  // Line 28 is the appended key; its value starts at column 12.
  for (const char* bad : {"nan", "+inf", "-inf", "-0.5"}) {
    SCOPED_TRACE(bad);
    EXPECT_EQ(error_of(test::kCampaignToSetpoint + "limit_us = " + bad + "\n"),
              "t.toml:28:12: check[0].limit_us: a finite number >= 0");
  }
  EXPECT_EQ(error_of(test::kCampaignToSetpoint + "limit_us = 20\ntimeout_us = 0\n"),
            "t.toml:29:14: check[0].timeout_us: a finite number >= 0.0005 (at least 1 ns once rounded to "
            "whole ns)");
  // 0.0004 us is 0 ns once rounded: no timeout at all, refused the same way.
  EXPECT_EQ(error_of(test::kCampaignToSetpoint + "limit_us = 20\ntimeout_us = 0.0004\n"),
            "t.toml:29:14: check[0].timeout_us: a finite number >= 0.0005 (at least 1 ns once rounded to "
            "whole ns)");
  EXPECT_EQ(error_of(test::kCampaignToSetpoint + "limit_us = 20\ntimeout_us = 0.0005\n"), "accepted");
  EXPECT_EQ(error_of(test::kCampaignToSetpoint + "limit_us = 20\nsetpoint_x = nan\n")
                .rfind("t.toml:29:14: check[0].setpoint_x: a parameter of throughput", 0),
            0U);
}

TEST(CheckParams, MinimumOfZeroIsBadInput) {
  EXPECT_EQ(error_of(test::kCampaignToSetpoint + "limit_us = 20\nmin_count = 0\n"),
            "t.toml:29:13: check[0].min_count: an integer >= 1");
}

TEST(CheckParams, ACampaignWithNoCheckIsBadInput) {
  const std::string no_check =
      test::kCampaignToSetpoint.substr(0, test::kCampaignToSetpoint.find("[[check]]"));
  const std::string got = error_of(no_check);
  EXPECT_NE(got.find("check: at least one [[check]]"), std::string::npos) << got;
  EXPECT_EQ(got.rfind("t.toml:", 0), 0U) << got;
}

// A debounce probe runs from probe_at (plus its start phase) for up to wide_us: a pulse still
// running at campaign.end could not be seen accepted, so a board within the limits would fail.
// Here the last start is at 1 ms + 180 us (scan_us 200 over 10 phases) and wide_us is 3 ms.
std::string debounce_ending(const std::string& end) {
  std::string t = test::kDebounce + "scan_us = 200\n";
  t.replace(t.find("end = \"6ms\""), 11, "end = \"" + end + "\"");
  return t;
}

TEST(CheckParams, DebounceProbesEndWithinTheRun) {
  EXPECT_EQ(error_of(debounce_ending("4.18ms")), "accepted");
  EXPECT_EQ(error_of(debounce_ending("4.179999ms")),
            "t.toml:23:11: check[0].wide_us: a probe that ends within the run: the last start phase at 1.18 "
            "ms + wide_us ends at 4.18 ms, after campaign.end (4.179999 ms)");
}

} // namespace
} // namespace hilrig::campaign
