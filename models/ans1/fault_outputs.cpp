#include "models/ans1/fault_outputs.hpp"

namespace hilrig::models::ans1 {

namespace {
[[nodiscard]] std::uint16_t u16(unsigned v) { return static_cast<std::uint16_t>(v & 0xFFFFU); }
} // namespace

OutputClaims make_claims(std::uint16_t dp_mask, std::uint16_t dp_levels, std::uint16_t brake_mask,
                         std::uint16_t brake_levels, std::uint16_t counter_mask,
                         std::uint16_t counter_levels) {
  OutputClaims c;
  const std::uint16_t brake_free = u16(brake_mask & ~dp_mask);
  c.owned_mask = u16(dp_mask | brake_free);
  c.owned_levels = u16((dp_levels & dp_mask) | (brake_levels & brake_free));
  c.brake_mask = brake_free;
  c.gated_mask = u16(counter_mask & ~c.owned_mask);
  c.gated_levels = u16(counter_levels & c.gated_mask);
  return c;
}

std::uint16_t apply_claims(const OutputClaims& claims, std::uint16_t ls_states, std::uint16_t ls_programmed) {
  // Overflow outputs: alone they show the overflow state; with an LS program they follow it
  // only while the counter is at its limit.
  const std::uint16_t gated_ls = u16(claims.gated_mask & ls_programmed);
  const std::uint16_t gated_plain = u16(claims.gated_mask & ~ls_programmed);
  const std::uint16_t gated =
      u16((gated_ls & ls_states & claims.gated_levels) | (gated_plain & claims.gated_levels));
  const std::uint16_t free = u16(~(claims.owned_mask | claims.gated_mask));
  return u16((claims.owned_levels & claims.owned_mask) | gated | (ls_states & free));
}

std::uint16_t user_defined_enabled(const OutputClaims& claims) {
  const std::uint16_t brake_off = u16(claims.brake_mask & ~claims.owned_levels);
  const std::uint16_t counter_off = u16(claims.gated_mask & ~claims.gated_levels);
  return u16(~(brake_off | counter_off));
}

} // namespace hilrig::models::ans1
