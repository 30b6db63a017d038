#pragma once
// Strict reading of one TOML table: every key the campaign reads is asked for by name,
// and finish() rejects any key nobody asked for, so a typo is an error, not a default.
// Errors are CampaignErrors at the node's own line and column. Internal to the parser.

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "core/line.hpp"
#include "core/time.hpp"
#include "rig/campaign/campaign_error.hpp"

namespace hilrig::campaign {

[[nodiscard]] SourcePos pos_of(const toml::source_region& region);
[[nodiscard]] inline SourcePos pos_of(const toml::node& node) { return pos_of(node.source()); }

class TableReader {
public:
  // path: the table's name in messages, e.g. "dut" or "wiring[2]".
  TableReader(const std::string& file, const toml::table& table, std::string path);

  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] SourcePos where() const { return pos_of(table_); }
  [[nodiscard]] std::string key(std::string_view name) const;
  [[nodiscard]] const toml::table& table() const { return table_; }

  // The node under `name` (marking it read), or nullptr when absent.
  [[nodiscard]] const toml::node* node(std::string_view name);
  [[nodiscard]] bool has(std::string_view name) const { return table_.contains(name); }
  // Where `name` is written (its value), or the table when absent.
  [[nodiscard]] SourcePos pos(std::string_view name) const;

  [[nodiscard]] std::string string(std::string_view name);
  [[nodiscard]] std::optional<std::string> opt_string(std::string_view name);
  [[nodiscard]] std::int64_t integer(std::string_view name);
  [[nodiscard]] std::optional<std::int64_t> opt_integer(std::string_view name);
  [[nodiscard]] double number(std::string_view name); // integer or float
  [[nodiscard]] std::optional<double> opt_number(std::string_view name);
  [[nodiscard]] bool boolean(std::string_view name);
  [[nodiscard]] std::optional<bool> opt_boolean(std::string_view name);
  [[nodiscard]] Nanos duration(std::string_view name); // "10ms", "250us", ...
  [[nodiscard]] std::optional<Nanos> opt_duration(std::string_view name);
  [[nodiscard]] Level level(std::string_view name); // "high" / "low"
  [[nodiscard]] std::optional<Level> opt_level(std::string_view name);
  // An optional sub-table (plain or inline).
  [[nodiscard]] const toml::table* opt_table(std::string_view name);
  // An optional array of tables ([[name]]); empty when absent.
  [[nodiscard]] std::vector<const toml::table*> tables(std::string_view name);

  [[noreturn]] void fail(std::string_view name, const std::string& expected) const;
  [[noreturn]] void fail_at(SourcePos where, std::string_view name, const std::string& expected) const;
  // Rejects every key not asked for.
  void finish() const;

private:
  const std::string& file_;
  const toml::table& table_;
  std::string path_;
  std::set<std::string, std::less<>> asked_;
};

// Value of a duration node: a string with a unit. nullopt when it is not one; one too long to
// hold is kMaxDurationText (rig/campaign/duration.hpp), for the key's range check to refuse.
[[nodiscard]] std::optional<Nanos> duration_of(const toml::node& node);

} // namespace hilrig::campaign
