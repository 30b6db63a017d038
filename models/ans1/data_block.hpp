#pragma once
// Data attribute blocks (spec §5.5, manual L2317-L2663): what status words 1..19 carry for the
// selected block 0..8 (setup echoes) or 16..20 (live machine, counter, die, brake and shift
// register data). Word 0 (status) is HostInterface's. Pure reads of the device and monitors.
#include <cstdint>

#include "models/ans1/command_block.hpp"

namespace hilrig::models::ans1 {

class Ans1;

inline constexpr std::uint16_t kModuleId = 83;     // DA0 w13: ASCII 'S' (L2334)
inline constexpr std::uint16_t kProductCode = 39;  // DA0 w14 (L2335)
inline constexpr std::uint16_t kMajorRevision = 1; // DA0 w15 [MODEL: not stated]
inline constexpr std::uint16_t kMinorRevision = 0; // DA0 w16 [MODEL: not stated]

// Fills words 1..19 of `words` for the selection (word 0 untouched). 32-bit values put the
// high word first (L2220). Signed values are two's complement.
void compose_data_block(const DataSelection& selection, const Ans1& device, std::uint8_t active_program,
                        HostWords& words);

} // namespace hilrig::models::ans1
