#pragma once
// The SHA-256 of a campaign file's bytes, as written into results.json: shards merge only
// when they ran the same revision of the file.

#include <string>
#include <string_view>

namespace hilrig::campaign {

// Lower-case hex, 64 characters.
[[nodiscard]] std::string sha256_hex(std::string_view bytes);

} // namespace hilrig::campaign
