#pragma once
// Whether a setup's programmed positions fit a Full Scale Count. Every position a program
// block takes is 0..FSC-1: the setpoints (L1890-L1891; the stitch distances as CB3 checks
// them), the LS offset within +-(FSC-1) and the LS preset value (L1867-L1868), the ANDing
// window (L2005-L2006), the die protection windows (L2056-L2063), the shift register window
// and shift position (L2139-L2141) and the production cycle increment position (L2158); and a
// stitched pair holds two Ons and an Off (L868) without overlapping another (L1898).
//
// The manual does not say what becomes of them when FSC changes. [MODEL]: the board never runs
// a position outside 0..FSC-1. A CB2 whose new FSC one would not fit is refused with 1011 (as
// one that the programmed SMO or MPV would not fit is), so is a CB15 Load of a program that
// does not fit the FSC in force, and at power-up such a stored program does not run
// (HostInterface::power_up).
#include <cstdint>

#include "models/ans1/setup.hpp"

namespace hilrig::models::ans1 {

// The program parts of `setup` (CB3-CB7, CB9, CB10); the CB2 position setup is not read.
[[nodiscard]] bool positions_fit(const Ans1Setup& setup, std::uint16_t fsc);

} // namespace hilrig::models::ans1
