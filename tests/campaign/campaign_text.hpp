#pragma once
// Shared by the campaign parser tests: edit a campaign text by line and read the parser's
// verdict on it as the one line a user sees.

#include <gtest/gtest.h>

#include <string>

#include "rig/campaign/campaign_error.hpp"
#include "rig/campaign/campaign_parser.hpp"

namespace hilrig::campaign::test {

// A valid campaign up to its one check's setpoint, 27 lines: a reference PLS (on 10, off 20)
// wired to the rig's encoder, one constant move, one throughput check; the check's table is
// lines 23..27 and cases append to it.
inline const std::string kCampaignToSetpoint = R"([campaign]
name = "t"
end = "100ms"
[dut]
model = "reference_pls"
[dut.params]
on = 10
off = 20
[[wiring]]
rig = "enc.A"
board = "A"
[[wiring]]
rig = "enc.B"
board = "B"
[[wiring]]
rig = "ls1"
board = "OUT"
[motion]
[[motion.move]]
kind = "constant"
speed_rpm = 60
duration = "100ms"
[[check]]
kind = "throughput"
name = "on"
output = "ls1"
setpoint = 10
)";

// The same campaign whole, 30 lines: the check's limit and an encoder of 100 lines = 400
// counts/turn. Cases replace one line (replace_line) or append lines.
inline const std::string kValidCampaign = kCampaignToSetpoint + R"(limit_us = 250
[encoder]
lines = 100
)";

// TEXT with its 1-based LINE replaced by WITH.
inline std::string replace_line(const std::string& text, int line, const std::string& with) {
  std::size_t begin = 0;
  for (int i = 1; i < line; ++i) begin = text.find('\n', begin) + 1;
  const std::size_t end = text.find('\n', begin);
  return text.substr(0, begin) + with + text.substr(end);
}

// The error's "file:line:column: key: " message, or "accepted" when the text parses.
inline std::string error_of(const std::string& text) {
  try {
    (void)parse_campaign(text, "t.toml");
    return "accepted";
  } catch (const CampaignError& e) {
    return e.what();
  }
}

inline ::testing::AssertionResult rejected_at(const std::string& text, const std::string& prefix) {
  const std::string got = error_of(text);
  if (got.rfind(prefix, 0) == 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "expected prefix \"" << prefix << "\", got \"" << got << "\"";
}

// A reference PLS whose EN input is debounced by a 1 ms filter (its param), judged by a
// debounce check (filter 1000 us ± 250, probes 100 .. 3000 us from 1 ms); the check's table
// ends the text, so cases append keys to it.
inline const std::string kDebounce = R"([campaign]
name = "debounce"
end = "6ms"
[dut]
model = "reference_pls"
[dut.params]
preset = 150
filter = "1ms"
[[wiring]]
rig = "en"
board = "EN"
[[wiring]]
rig = "ls1"
board = "OUT"
[[check]]
kind = "debounce"
name = "en_filter"
input = "en"
output = "ls1"
filter_us = 1000
tolerance_us = 250
narrow_us = 100
wide_us = 3000
resolution_us = 5
probe_at = "1ms"
)";

} // namespace hilrig::campaign::test
