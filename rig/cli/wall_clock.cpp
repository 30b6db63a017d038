#include "rig/cli/wall_clock.hpp"

#include <unistd.h>

#include <array>
#include <charconv>
#include <ctime>

#include <fmt/format.h>

namespace hilrig::cli {

std::string iso8601_utc(std::chrono::system_clock::time_point t) {
  const std::time_t seconds = std::chrono::system_clock::to_time_t(t);
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  std::array<char, 32> text{};
  const std::size_t n = std::strftime(text.data(), text.size(), "%Y-%m-%dT%H:%M:%SZ", &utc);
  return {text.data(), n};
}

std::optional<std::int64_t> parse_epoch(std::string_view text) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string_view::npos) return std::nullopt;
  std::int64_t v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc{} || end != text.data() + text.size() || v > kMaxEpoch) return std::nullopt;
  return v;
}

std::string epoch_range() {
  return fmt::format("whole seconds since 1970-01-01T00:00:00Z, 0 .. {} (2099-12-31T23:59:59Z)", kMaxEpoch);
}

std::chrono::system_clock::time_point wall_start(std::optional<std::int64_t> epoch) {
  if (epoch) return std::chrono::system_clock::time_point{std::chrono::seconds{*epoch}};
  return std::chrono::floor<std::chrono::seconds>(std::chrono::system_clock::now());
}

std::string host_name() {
  std::array<char, 256> name{};
  if (gethostname(name.data(), name.size() - 1) != 0 || name[0] == '\0') return "localhost";
  return name.data();
}

} // namespace hilrig::cli
