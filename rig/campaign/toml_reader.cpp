#include "rig/campaign/toml_reader.hpp"

#include "core/did_you_mean.hpp"

#include <cmath>

#include <fmt/format.h>

#include "rig/campaign/duration.hpp"
#include "rig/campaign/limits.hpp"

namespace hilrig::campaign {

SourcePos pos_of(const toml::source_region& region) {
  return SourcePos{static_cast<std::uint32_t>(region.begin.line),
                   static_cast<std::uint32_t>(region.begin.column)};
}

std::optional<Nanos> duration_of(const toml::node& node) {
  const auto* s = node.as_string();
  if (s == nullptr) return std::nullopt;
  return parse_duration_clamped(s->get()); // "1e400s" is out of the key's range, named by its check
}

TableReader::TableReader(const std::string& file, const toml::table& table, std::string path)
    : file_(file), table_(table), path_(std::move(path)) {}

std::string TableReader::key(std::string_view name) const {
  return path_.empty() ? std::string(name) : fmt::format("{}.{}", path_, name);
}

const toml::node* TableReader::node(std::string_view name) {
  asked_.emplace(name);
  return table_.get(name);
}

SourcePos TableReader::pos(std::string_view name) const {
  const toml::node* n = table_.get(name);
  return n != nullptr ? pos_of(*n) : where();
}

void TableReader::fail(std::string_view name, const std::string& expected) const {
  throw CampaignError(file_, pos(name), key(name), expected);
}

void TableReader::fail_at(SourcePos at, std::string_view name, const std::string& expected) const {
  throw CampaignError(file_, at, key(name), expected);
}

std::optional<std::string> TableReader::opt_string(std::string_view name) {
  const toml::node* n = node(name);
  if (n == nullptr) return std::nullopt;
  const auto* s = n->as_string();
  if (s == nullptr) fail(name, "expected " + kind_text(duts::ParamKind::Text));
  return s->get();
}

std::string TableReader::string(std::string_view name) {
  auto v = opt_string(name);
  if (!v) fail(name, "missing: expected " + kind_text(duts::ParamKind::Text));
  return *v;
}

std::optional<std::int64_t> TableReader::opt_integer(std::string_view name) {
  const toml::node* n = node(name);
  if (n == nullptr) return std::nullopt;
  const auto* i = n->as_integer();
  if (i == nullptr) fail(name, "expected " + kind_text(duts::ParamKind::Integer));
  return i->get();
}

std::int64_t TableReader::integer(std::string_view name) {
  auto v = opt_integer(name);
  if (!v) fail(name, "missing: expected " + kind_text(duts::ParamKind::Integer));
  return *v;
}

std::optional<double> TableReader::opt_number(std::string_view name) {
  const toml::node* n = node(name);
  if (n == nullptr) return std::nullopt;
  if (const auto* i = n->as_integer()) return static_cast<double>(i->get());
  if (const auto* f = n->as_floating_point()) {
    if (!std::isfinite(f->get())) fail(name, std::string(kNotFiniteText));
    return f->get();
  }
  fail(name, "expected " + kind_text(duts::ParamKind::Number));
}

double TableReader::number(std::string_view name) {
  auto v = opt_number(name);
  if (!v) fail(name, "missing: expected " + kind_text(duts::ParamKind::Number));
  return *v;
}

std::optional<bool> TableReader::opt_boolean(std::string_view name) {
  const toml::node* n = node(name);
  if (n == nullptr) return std::nullopt;
  const auto* b = n->as_boolean();
  if (b == nullptr) fail(name, "expected " + kind_text(duts::ParamKind::Boolean));
  return b->get();
}

bool TableReader::boolean(std::string_view name) {
  auto v = opt_boolean(name);
  if (!v) fail(name, "missing: expected " + kind_text(duts::ParamKind::Boolean));
  return *v;
}

std::optional<Nanos> TableReader::opt_duration(std::string_view name) {
  const toml::node* n = node(name);
  if (n == nullptr) return std::nullopt;
  auto d = duration_of(*n);
  if (!d) fail(name, "expected " + kind_text(duts::ParamKind::Duration));
  return d;
}

Nanos TableReader::duration(std::string_view name) {
  auto v = opt_duration(name);
  if (!v) fail(name, "missing: expected " + kind_text(duts::ParamKind::Duration));
  return *v;
}

std::optional<Level> TableReader::opt_level(std::string_view name) {
  const toml::node* n = node(name);
  if (n == nullptr) return std::nullopt;
  const auto* s = n->as_string();
  if (s != nullptr && s->get() == "high") return Level::High;
  if (s != nullptr && s->get() == "low") return Level::Low;
  fail(name, "expected \"high\" or \"low\"");
}

Level TableReader::level(std::string_view name) {
  auto v = opt_level(name);
  if (!v) fail(name, "missing: expected \"high\" or \"low\"");
  return *v;
}

const toml::table* TableReader::opt_table(std::string_view name) {
  const toml::node* n = node(name);
  if (n == nullptr) return nullptr;
  const auto* t = n->as_table();
  if (t == nullptr) fail(name, "expected a table");
  return t;
}

std::vector<const toml::table*> TableReader::tables(std::string_view name) {
  std::vector<const toml::table*> out;
  const toml::node* n = node(name);
  if (n == nullptr) return out;
  const auto* a = n->as_array();
  if (a == nullptr) fail(name, fmt::format("expected an array of tables ([[{}]])", name));
  for (const toml::node& e : *a) {
    const auto* t = e.as_table();
    if (t == nullptr) fail_at(pos_of(e), name, fmt::format("expected an array of tables ([[{}]])", name));
    out.push_back(t);
  }
  return out;
}

void TableReader::finish() const {
  for (const auto& [k, v] : table_) {
    if (asked_.contains(k.str())) continue;
    std::string known;
    for (const auto& a : asked_) known += (known.empty() ? "" : ", ") + a;
    const std::vector<std::string> valid(asked_.begin(), asked_.end());
    throw CampaignError(file_, pos_of(k.source()), key(k.str()),
                        known.empty() ? "unknown key"
                                      : fmt::format("unknown key (expected one of: {}){}", known,
                                                    did_you_mean(k.str(), valid)));
  }
}

} // namespace hilrig::campaign
