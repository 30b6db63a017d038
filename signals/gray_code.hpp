#pragma once
// Reflected binary (Gray) code over an N-bit field, as absolute encoders send it and as
// the 7361 decodes it: b[N-1] = g[N-1]; b[i] = b[i+1] ^ g[i] (ssi7361.md §2.3 step 2).

#include <cstdint>

namespace hilrig::signals {

[[nodiscard]] constexpr std::uint32_t binary_to_gray(std::uint32_t binary) { return binary ^ (binary >> 1); }

// Prefix XOR from the MSB down; bits above the field must be zero in the input.
[[nodiscard]] constexpr std::uint32_t gray_to_binary(std::uint32_t gray) {
  std::uint32_t b = gray;
  for (unsigned shift = 1; shift < 32; shift <<= 1) b ^= b >> shift;
  return b;
}

// Mask of the low `bits` bits (bits in 0..32).
[[nodiscard]] constexpr std::uint32_t low_mask(unsigned bits) {
  return bits >= 32 ? 0xFFFF'FFFFu : ((1u << bits) - 1u);
}

} // namespace hilrig::signals
