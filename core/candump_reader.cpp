#include <array>
#include <cstdint>

#include "core/candump.hpp"

namespace hilrig {
namespace {

// Consumes `count` hex digits (either case) from the front of text into v.
bool take_hex(std::string_view& text, std::size_t count, std::uint32_t& v) {
  if (text.size() < count) return false;
  v = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const char c = text[i];
    std::uint32_t d = 0;
    if (c >= '0' && c <= '9')
      d = static_cast<std::uint32_t>(c - '0');
    else if (c >= 'A' && c <= 'F')
      d = static_cast<std::uint32_t>(c - 'A' + 10);
    else if (c >= 'a' && c <= 'f')
      d = static_cast<std::uint32_t>(c - 'a' + 10);
    else
      return false;
    v = (v << 4U) | d;
  }
  text.remove_prefix(count);
  return true;
}

// Consumes 1..max_digits decimal digits.
bool take_decimal(std::string_view& text, std::size_t min_digits, std::size_t max_digits, std::int64_t& v) {
  std::size_t n = 0;
  v = 0;
  while (n < text.size() && n < max_digits && text[n] >= '0' && text[n] <= '9') {
    v = v * 10 + (text[n] - '0');
    ++n;
  }
  if (n < min_digits) return false;
  text.remove_prefix(n);
  return true;
}

bool take(std::string_view& text, char c) {
  if (text.empty() || text.front() != c) return false;
  text.remove_prefix(1);
  return true;
}

bool fd_length(std::size_t n) {
  constexpr std::array<std::size_t, 16> lengths{0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 16, 20, 24, 32, 48, 64};
  for (const std::size_t l : lengths)
    if (l == n) return true;
  return false;
}

// The data bytes: the rest of the text, two hex digits each.
bool take_data(std::string_view text, CanFrame& f) {
  if (text.size() % 2 != 0 || text.size() / 2 > f.data.size()) return false;
  const std::size_t n = text.size() / 2;
  if (f.fd ? !fd_length(n) : n > 8) return false;
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t byte = 0;
    if (!take_hex(text, 2, byte)) return false;
    f.data[i] = static_cast<std::uint8_t>(byte);
  }
  f.len = static_cast<std::uint8_t>(n);
  return true;
}

} // namespace

std::optional<CandumpRecord> read_candump_line(std::string_view line) {
  CandumpRecord r;
  std::int64_t seconds = 0;
  std::int64_t micros = 0;
  if (!take(line, '(') || !take_decimal(line, 1, 10, seconds) || !take(line, '.') ||
      !take_decimal(line, 6, 6, micros) || !take(line, ')') || !take(line, ' '))
    return std::nullopt;
  // Ten digits can be more seconds than a 64-bit nanosecond count holds (found by fuzz_candump).
  constexpr std::int64_t kMaxSeconds = 9'223'372'035;
  if (seconds > kMaxSeconds) return std::nullopt;
  r.time = Nanos{seconds * 1'000'000'000 + micros * 1'000};
  while (!line.empty() && line.front() == ' ') line.remove_prefix(1);
  const std::size_t space = line.find(' ');
  if (space == 0 || space == std::string_view::npos || space > 15) return std::nullopt;
  r.bus = std::string(line.substr(0, space));
  line.remove_prefix(space + 1);

  CanFrame& f = r.frame;
  const std::size_t hash = line.find('#');
  if (hash != 3 && hash != 8) return std::nullopt;
  f.extended = hash == 8;
  if (!take_hex(line, hash, f.id) || f.id > (f.extended ? 0x1FFF'FFFFU : 0x7FFU)) return std::nullopt;
  line.remove_prefix(1);
  if (take(line, '#')) {
    std::uint32_t flags = 0;
    if (!take_hex(line, 1, flags) || flags > 7) return std::nullopt;
    f.fd = true;
    f.brs = (flags & 1U) != 0;
    f.esi = (flags & 2U) != 0;
    r.fdf_flag = (flags & 4U) != 0;
    if (!take_data(line, f)) return std::nullopt;
    return r;
  }
  if (take(line, 'R')) {
    f.rtr = true;
    if (line.empty()) return r;
    std::uint32_t dlc = 0;
    if (line.size() != 1 || !take_hex(line, 1, dlc) || dlc < 1 || dlc > 8) return std::nullopt;
    f.len = static_cast<std::uint8_t>(dlc);
    return r;
  }
  if (!take_data(line, f)) return std::nullopt;
  return r;
}

} // namespace hilrig
