#pragma once
// Internal to the command-block decoder: word access helpers and the per-block decoders, each
// in the file of its group (command_block.cpp: CB0/1/2/15, command_block_outputs.cpp: CB3-6,
// command_block_monitors.cpp: CB7-11). Each returns ErrorCode::None and edits out.setup /
// out.actions, or returns the error (the caller then discards its edits).
#include <cstdint>
#include <initializer_list>

#include "models/ans1/command_block.hpp"

namespace hilrig::models::ans1::command_fields {

[[nodiscard]] constexpr bool has(std::uint16_t word, int bit) {
  return ((static_cast<unsigned>(word) >> static_cast<unsigned>(bit)) & 1U) != 0;
}
[[nodiscard]] constexpr std::int16_t as_signed(std::uint16_t word) { return static_cast<std::int16_t>(word); }
[[nodiscard]] constexpr bool in_range(int value, int lo, int hi) { return value >= lo && value <= hi; }
[[nodiscard]] constexpr std::uint32_t join32(std::uint16_t high, std::uint16_t low) {
  return (static_cast<std::uint32_t>(high) << 16) | low; // high word first (L2220)
}
// Bits 14..5 of word 0 a block may use; any other bit there is a Reserved Bits Error.
[[nodiscard]] constexpr bool reserved_bits_set(std::uint16_t word0, std::uint16_t allowed) {
  return (word0 & 0x7FE0U & ~allowed) != 0;
}
[[nodiscard]] constexpr std::uint16_t bits(std::initializer_list<int> list) {
  unsigned m = 0;
  for (int b : list) m |= 1U << static_cast<unsigned>(b);
  return static_cast<std::uint16_t>(m);
}

ErrorCode decode_return_data(const HostWords& w, DecodedBlock& out);                          // CB1
ErrorCode decode_global(const HostWords& w, DecodedBlock& out);                               // CB2
ErrorCode decode_setpoints(const HostWords& w, DecodedBlock& out);                            // CB3
ErrorCode decode_adjust(const HostWords& w, DecodedBlock& out);                               // CB4
ErrorCode decode_timing(const HostWords& w, DecodedBlock& out);                               // CB5
ErrorCode decode_enabling(const HostWords& w, DecodedBlock& out);                             // CB6
ErrorCode decode_die_protection(const HostWords& w, DecodedBlock& out);                       // CB7
ErrorCode decode_brake(const HostWords& w, DecodedBlock& out);                                // CB8
ErrorCode decode_shift_register(const HostWords& w, DecodedBlock& out);                       // CB9
ErrorCode decode_production_cycle(const HostWords& w, DecodedBlock& out);                     // CB10
ErrorCode decode_counters(const HostWords& w, DecodedBlock& out);                             // CB11
ErrorCode decode_save_restore(const HostWords& w, const HostContext& ctx, DecodedBlock& out); // CB15

} // namespace hilrig::models::ans1::command_fields
