#include "rig/campaign/toml_file.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <cstddef>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

#include <fmt/format.h>

#include "rig/campaign/campaign_error.hpp"
#include "rig/campaign/limits.hpp"
#include "rig/campaign/toml_reader.hpp"

namespace hilrig::campaign {

namespace {

namespace fs = std::filesystem;

std::string kind_of(fs::file_type type) {
  switch (type) {
  case fs::file_type::directory:
    return "a directory";
  case fs::file_type::fifo:
    return "a FIFO";
  case fs::file_type::character:
  case fs::file_type::block:
    return "a device";
  case fs::file_type::socket:
    return "a socket";
  default:
    return "not a regular file";
  }
}

bool bare_key_char(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
}

// The index just past the string that starts at i (a TOML basic, literal or multi-line
// string), or text.size() when it is not closed (toml++ reports that).
std::size_t past_string(std::string_view text, std::size_t i) {
  const char quote = text[i];
  const bool multi = text.substr(i, 3) == std::string_view(quote == '"' ? "\"\"\"" : "'''");
  std::size_t j = i + (multi ? 3 : 1);
  while (j < text.size()) {
    if (quote == '"' && text[j] == '\\') {
      j += 2;
      continue;
    }
    if (multi ? text.substr(j, 3) == text.substr(i, 3) : text[j] == quote) return j + (multi ? 3 : 1);
    if (!multi && text[j] == '\n') return j;
    ++j;
  }
  return text.size();
}

// Refuses a dotted key or header of more than kMaxKeyParts parts: counts the dots of each run of
// key parts (bare or quoted, dots between them, blanks around the dots). A float's dot is one
// part boundary in its own run, so values never come near the bound.
void check_key_parts(std::string_view text, const std::string& file_name) {
  std::size_t parts = 1;
  std::uint32_t line = 1;
  std::size_t line_start = 0;
  std::size_t run_start = 0;
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '"' || c == '\'') {
      const std::size_t end = past_string(text, i);
      for (std::size_t k = i; k < end; ++k)
        if (text[k] == '\n') {
          ++line;
          line_start = k + 1;
        }
      i = end;
      continue;
    }
    if (c == '.') {
      if (parts == 1) run_start = i;
      if (++parts > limits::kMaxKeyParts)
        throw CampaignError(
            file_name, SourcePos{line, static_cast<std::uint32_t>(run_start - line_start + 1)}, "toml",
            fmt::format("a dotted key or table name of at most {} parts", limits::kMaxKeyParts));
    } else if (c == '#') {
      while (i < text.size() && text[i] != '\n') ++i;
      continue;
    } else if (c == '\n') {
      ++line;
      line_start = i + 1;
      parts = 1;
    } else if (!bare_key_char(c) && c != ' ' && c != '\t') {
      parts = 1;
    }
    ++i;
  }
}

} // namespace

namespace {

// Well-formed UTF-8, as the JSON writer of results.json checks it (it is what refused such a
// path after a run): the same rule, not a second validator.
bool valid_utf8(const std::string& s) {
  try {
    (void)nlohmann::json(s).dump();
    return true;
  } catch (const nlohmann::json::type_error&) {
    return false;
  }
}

} // namespace

std::string read_toml_text(const std::string& path, std::string_view what) {
  // The path is written into results.json, junit.xml and report.html, which are UTF-8.
  if (!valid_utf8(path))
    throw CampaignError(path, SourcePos{}, "file",
                        fmt::format("a {} whose path is valid UTF-8 (the outputs name it): rename it", what));
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status))
    throw CampaignError(
        path, SourcePos{}, "file",
        fmt::format("a readable {} (cannot open it: {})", what, ec ? ec.message() : std::strerror(ENOENT)));
  if (!fs::is_regular_file(status))
    throw CampaignError(path, SourcePos{}, "file",
                        fmt::format("a regular {} ({} is {})", what, path, kind_of(status.type())));
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw CampaignError(path, SourcePos{}, "file", fmt::format("a readable {} (cannot open it)", what));
  // Read at most one byte past the cap: the file may grow between stat and read. In chunks, so a
  // campaign of a few KiB costs a few KiB (not a zeroed 1 MiB buffer, a page fault per page).
  const std::size_t most = static_cast<std::size_t>(limits::kMaxFileBytes) + 1;
  std::string text;
  char chunk[16384];
  while (text.size() < most && in) {
    in.read(chunk, static_cast<std::streamsize>(std::min(sizeof chunk, most - text.size())));
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
  }
  if (text.size() > limits::kMaxFileBytes)
    throw CampaignError(path, SourcePos{}, "file",
                        fmt::format("a {} of at most {} bytes", what, limits::kMaxFileBytes));
  return text;
}

toml::table parse_toml(std::string_view text, const std::string& file_name) {
  check_key_parts(text, file_name);
  try {
    return toml::parse(text, std::string_view(file_name));
  } catch (const toml::parse_error& e) {
    throw CampaignError(file_name, pos_of(e.source()), "toml", std::string(e.description()));
  }
}

} // namespace hilrig::campaign
