#include "rig/campaign/campaign_error.hpp"

#include <fmt/format.h>

namespace hilrig::campaign {

namespace {
std::string describe(const std::string& file, SourcePos where, const std::string& key,
                     const std::string& expected) {
  // A problem of the whole file (too big, not there) has no line: "file: key: ...", not a 0:0
  // no editor can go to.
  if (where.line == 0) return fmt::format("{}: {}: {}", file, key, expected);
  return fmt::format("{}:{}:{}: {}: {}", file, where.line, where.column, key, expected);
}
} // namespace

CampaignError::CampaignError(std::string file, SourcePos where, std::string key, std::string expected)
    : std::runtime_error(describe(file, where, key, expected)), file_(std::move(file)), where_(where),
      key_(std::move(key)), expected_(std::move(expected)) {}

} // namespace hilrig::campaign
