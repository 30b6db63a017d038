#pragma once
// Programmable fault outputs (spec §4.13, manual L678-L684, L1070, L1226): the die-protection
// fault outputs, the brake start/stop overrun outputs and the counter overflow outputs take an
// output away from its limit-switch program. Priority, highest first [MODEL §4.13]:
// die protection, brake overrun, counter overflow, then the LS program. Transducer fault and
// forcing sit above all of these and stay with the device (ans1-core).
//
// How the device uses it: each scan, after computing its LS states,
//     out = apply_claims(monitors.claims(), ls_states, ls_programmed);
//   ls_programmed: bit n-1 = output n has setpoints or a timer (L1226: an overflow output
//   with an LS program follows that program only while its counter is at the limit).
#include <cstdint>

namespace hilrig::models::ans1 {

struct OutputClaims {
  std::uint16_t owned_mask = 0;   // outputs driven by a DP or brake monitor, whatever the LS program
  std::uint16_t owned_levels = 0; // their levels (1 = on)
  std::uint16_t gated_mask = 0;   // counter overflow outputs (not owned by a higher claim)
  std::uint16_t gated_levels = 0; // 1 = counter in its overflow state
  std::uint16_t brake_mask = 0;   // the brake overrun outputs among owned_mask (for DA16 w17)
  friend bool operator==(const OutputClaims&, const OutputClaims&) = default;
};

// Builds the claims in priority order: a lower claim never takes an output a higher one holds.
[[nodiscard]] OutputClaims make_claims(std::uint16_t dp_mask, std::uint16_t dp_levels,
                                       std::uint16_t brake_mask, std::uint16_t brake_levels,
                                       std::uint16_t counter_mask, std::uint16_t counter_levels);

// The output states after the claims (bit n-1 = output n).
[[nodiscard]] std::uint16_t apply_claims(const OutputClaims& claims, std::uint16_t ls_states,
                                         std::uint16_t ls_programmed);

// DA16 w17: bit = 0 for a user-defined output (brake overrun, counter overflow) that is in its
// disabled (off) state; 1 otherwise (L2557).
[[nodiscard]] std::uint16_t user_defined_enabled(const OutputClaims& claims);

} // namespace hilrig::models::ans1
