#pragma once
// From the raw 25-bit frame to the Data Value, and the Rate of Change (digest §2.3, §3).
// Pure functions; the device model calls them at every frame and every rate update.
//
//   field  = (raw >> (26 - M - N)) & (2^N - 1)
//   field ^= 2^N - 1                     Data Logic Negative (before Gray, A14)
//   field  = gray_to_binary(field)       Data Type Gray (over the field only, A16)
//   x      = 2^N - field                 Count Direction Negative (A12), else field
//   DV     = x * MUL / DIV + LO          truncating (A15), 64-bit

#include <cstdint>

#include "models/ssi7361/params.hpp"
#include "models/ssi7361/setup.hpp"

namespace hilrig::models::ssi7361 {

inline constexpr std::uint32_t kRawMask = 0x01FF'FFFF; // 25 bits

[[nodiscard]] std::uint32_t extract_field(std::uint32_t raw, unsigned msb, unsigned bits);

// The field after Data Logic, Data Type and Count Direction: the value that is scaled.
[[nodiscard]] std::int64_t position_counts(std::uint32_t raw, const Setup& setup, const Params& params);

// x * MUL / DIV, truncating toward zero.
[[nodiscard]] std::int64_t scale(std::int64_t x, std::uint16_t multiplier, std::uint16_t divisor);

// The Data Value for a raw frame with the linear offset LO.
[[nodiscard]] std::int64_t data_value(std::uint32_t raw, const Setup& setup, std::int64_t offset,
                                      const Params& params);

// The offset that makes the Data Value equal to the preset for this raw frame.
[[nodiscard]] std::int64_t preset_offset(std::uint32_t raw, const Setup& setup, const Params& params);

// RoC = delta * 1000 / RUT, in counts per second.
[[nodiscard]] std::int64_t rate_of_change(std::int64_t delta, std::uint16_t rut_ms, RateRounding rounding);

// A 64-bit result into the signed 32-bit word the module reports (saturating, A22).
[[nodiscard]] std::int32_t saturate_i32(std::int64_t v);

} // namespace hilrig::models::ssi7361
