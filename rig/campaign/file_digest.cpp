#include "rig/campaign/file_digest.hpp"

#include <array>
#include <cstdint>

#include <fmt/format.h>
#include <nettle/sha2.h>

namespace hilrig::campaign {

// nettle, not OpenSSL's EVP: a digest needs no provider or configuration, and the small
// library loads in a fraction of libcrypto's relocation and start-up time, which every
// `hilrig run` pays (docs/PERFORMANCE.md, "Fixed cost of a run").
std::string sha256_hex(std::string_view bytes) {
  sha256_ctx ctx{};
  sha256_init(&ctx);
  sha256_update(&ctx, bytes.size(), reinterpret_cast<const std::uint8_t*>(bytes.data()));
  std::array<std::uint8_t, SHA256_DIGEST_SIZE> digest{};
  sha256_digest(&ctx, digest.size(), digest.data());
  std::string hex;
  hex.reserve(2 * digest.size());
  for (const std::uint8_t b : digest) hex += fmt::format("{:02x}", b);
  return hex;
}

} // namespace hilrig::campaign
