#pragma once
// A status word's bits: (observed word & mask) equals a value. For status words that
// carry many flags (a move's error bits beside its motion bits), where word_equals on the
// whole word would judge flags the test does not mean to.

#include <cstdint>
#include <span>

#include "rig/checks/words.hpp"

namespace hilrig::checks {

// "<name>" = the chosen observation's (word & mask) against value; no such observation is a
// failure ("missing word"). spec.lower/upper are ignored.
[[nodiscard]] CheckResult check_word_bits(std::span<const Observation> observations, const WordSpec& spec,
                                          std::uint16_t mask, std::uint16_t value);

} // namespace hilrig::checks
