#pragma once
// The 4501 adapter: the virtual AMCI 4501 registration module (models/amci4501) as a
// campaign's DUT. Pins A, B, Z (encoder), START, LATCH (discrete inputs) and CYCLE_OUT
// (the Cycle Output, high while it sinks); the host's 8 output and 8 input words with the
// Transmit/Acknowledge programming handshake on bit 15 of word 0; variants by the model's
// own names (models/amci4501/variants.hpp).

#include "models/amci4501/params.hpp"
#include "rig/duts/dut.hpp"

namespace hilrig::duts {

// The registry entry (name "amci4501").
[[nodiscard]] DutInfo amci4501_info();

// The model's Params (variant left nominal) from a full set of this entry's parameters
// (defaults filled in): what a campaign's [dut.params] and `hilrig serve amci4501 --param` set.
[[nodiscard]] models::amci4501::Params amci4501_params(const DutParams& params);

} // namespace hilrig::duts
