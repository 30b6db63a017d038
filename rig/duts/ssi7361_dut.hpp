#pragma once
// The 7361 adapter: the virtual AMCI 7361 SSI interface module (models/ssi7361) as a
// campaign's DUT. Pins CLK (output: the module is the SSI master) and DATA (input: the rig
// plays the transducer; an unwired DATA idles high, read as all ones like an open input,
// L2178); the host's 7 command words (%Q, %AQ1..6) and 7 status words (%I, %AI1..6) with
// the TRMT/ACK handshake on bit 15 of word 0; variants by the model's own names.

#include "rig/duts/dut.hpp"

namespace hilrig::duts {

// The registry entry (name "ssi7361").
[[nodiscard]] DutInfo ssi7361_info();

} // namespace hilrig::duts
