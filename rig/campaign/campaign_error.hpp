#pragma once
// A campaign file that cannot run: where (file:line:column), which key, and what was
// expected. The run command prints what() and exits 2 before anything runs.

#include <cstdint>
#include <stdexcept>
#include <string>

namespace hilrig::campaign {

// A place in a campaign file; line and column are 1-based (0 when unknown).
struct SourcePos {
  std::uint32_t line = 0;
  std::uint32_t column = 0;
};

class CampaignError : public std::runtime_error {
public:
  CampaignError(std::string file, SourcePos where, std::string key, std::string expected);

  [[nodiscard]] const std::string& file() const { return file_; }
  [[nodiscard]] SourcePos where() const { return where_; }
  [[nodiscard]] const std::string& key() const { return key_; }
  [[nodiscard]] const std::string& expected() const { return expected_; }

private:
  std::string file_;
  SourcePos where_;
  std::string key_;
  std::string expected_;
};

} // namespace hilrig::campaign
