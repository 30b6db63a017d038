#pragma once
// Global Machine Position (spec §4.1): transducer count -> counts in cycle -> scaled count ->
// circular offset. Pure integer arithmetic, as the device compares integer scaled counts.
#include <cstdint>

#include "models/ans1/position_setup.hpp"

namespace hilrig::models::ans1 {

// Non-negative remainder (the device's "mod").
[[nodiscard]] constexpr std::int64_t wrap(std::int64_t value, std::int64_t modulus) {
  const std::int64_t r = value % modulus;
  return r < 0 ? r + modulus : r;
}

// raw (signed transducer count) -> q = raw mod CPC -> s = floor(q * FSC / CPC).
[[nodiscard]] constexpr std::int32_t scaled_count(std::int64_t raw, std::uint16_t cpc, std::uint16_t fsc) {
  const std::int64_t q = wrap(raw, cpc);
  return static_cast<std::int32_t>(q * fsc / cpc);
}

// GMP = (s + SMO) mod FSC, always 0..FSC-1 (L780).
[[nodiscard]] constexpr std::uint16_t global_position(std::int32_t scaled, std::int32_t offset,
                                                      std::uint16_t fsc) {
  return static_cast<std::uint16_t>(wrap(static_cast<std::int64_t>(scaled) + offset, fsc));
}

[[nodiscard]] constexpr std::uint16_t global_position(std::int64_t raw, const PositionSetup& setup) {
  return global_position(scaled_count(raw, setup.counts_per_cycle, setup.full_scale_count),
                         setup.scaled_offset, setup.full_scale_count);
}

// A preset makes GMP equal target by recomputing the offset (L784): SMO = target - s, which is
// within -(FSC-1)..+(FSC-1) because both are in 0..FSC-1.
[[nodiscard]] constexpr std::int32_t preset_offset(std::uint16_t target, std::int32_t scaled) {
  return static_cast<std::int32_t>(target) - scaled;
}

// A limit switch's own position (§4.3): LSpos = (GMP + LSO) mod FSC.
[[nodiscard]] constexpr std::uint16_t ls_position(std::uint16_t gmp, std::int32_t ls_offset,
                                                  std::uint16_t fsc) {
  return global_position(static_cast<std::int32_t>(gmp), ls_offset, fsc);
}

} // namespace hilrig::models::ans1
