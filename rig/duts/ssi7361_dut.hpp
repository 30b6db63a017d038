#pragma once
// The 7361 adapter: the virtual AMCI 7361 SSI interface module (models/ssi7361) as a
// campaign's DUT. Pins CLK (output: the module is the SSI master) and DATA (input: the rig
// plays the transducer; an unwired DATA idles high, read as all ones like an open input,
// L2178); the host's 7 command words (%Q, %AQ1..6) and 7 status words (%I, %AI1..6) with
// the TRMT/ACK handshake on bit 15 of word 0; variants by the model's own names.

#include "models/ssi7361/params.hpp"
#include "rig/duts/dut.hpp"

namespace hilrig::duts {

// The registry entry (name "ssi7361").
[[nodiscard]] DutInfo ssi7361_info();

// The model's Params (variant left nominal) from a full set of this entry's parameters
// (defaults filled in): what a campaign's [dut.params] and `hilrig serve ssi7361 --param` set.
[[nodiscard]] models::ssi7361::Params ssi7361_params(const DutParams& params);

} // namespace hilrig::duts
