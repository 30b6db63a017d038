#pragma once
// Shared by the campaign parser tests: edit a campaign text by line and read the parser's
// verdict on it as the one line a user sees.

#include <gtest/gtest.h>

#include <string>

#include "rig/campaign/campaign_error.hpp"
#include "rig/campaign/campaign_parser.hpp"

namespace hilrig::campaign::test {

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

} // namespace hilrig::campaign::test
