#pragma once
// The wall-clock facts junit.xml carries for CI servers (and nothing else hilrig writes).

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace hilrig::cli {

// ISO 8601 in UTC to the second: "2026-11-25T17:40:03Z".
[[nodiscard]] std::string iso8601_utc(std::chrono::system_clock::time_point t);
// The latest epoch taken: 2099-12-31T23:59:59Z. The clocks count nanoseconds in 64 bits, which
// end in 2262 (can.log's times are the epoch plus the campaign's virtual time).
inline constexpr std::int64_t kMaxEpoch = 4'102'444'799;
// A campaign's wall-clock start given instead of now, in whole seconds since 1970-01-01 UTC
// (`--epoch`, or SOURCE_DATE_EPOCH, the reproducible-builds convention): decimal digits only,
// 0 .. kMaxEpoch. Empty for anything else.
[[nodiscard]] std::optional<std::int64_t> parse_epoch(std::string_view text);
// What parse_epoch accepts, for an error message.
[[nodiscard]] std::string epoch_range();
// The campaign's wall-clock start: `epoch` when given, else now, to the second.
[[nodiscard]] std::chrono::system_clock::time_point wall_start(std::optional<std::int64_t> epoch);

// This machine's name (gethostname), "localhost" when it has none.
[[nodiscard]] std::string host_name();

} // namespace hilrig::cli
