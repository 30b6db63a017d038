#pragma once
// The wall-clock facts junit.xml carries for CI servers (and nothing else hilrig writes).

#include <chrono>
#include <string>

namespace hilrig::cli {

// ISO 8601 in UTC to the second: "2026-11-25T17:40:03Z".
[[nodiscard]] std::string iso8601_utc(std::chrono::system_clock::time_point t);
// This machine's name (gethostname), "localhost" when it has none.
[[nodiscard]] std::string host_name();

} // namespace hilrig::cli
