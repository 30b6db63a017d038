#pragma once
// The ANS1 adapter: the virtual ANS1 (models/ans1) as a campaign's DUT. Pins A, B, Z,
// SIN, COS (analog stators), IN1..IN16, OUT1..OUT16; the host's 20 command and 20 status
// words with the Transmit/Acknowledge handshake; variants by the model's own names.

#include "models/ans1/params.hpp"
#include "rig/duts/dut.hpp"

namespace hilrig::duts {

// The registry entry (name "ans1").
[[nodiscard]] DutInfo ans1_info();
// The model's Params from every parameter of ans1_info() (a campaign's or a served one's).
[[nodiscard]] models::ans1::Params ans1_params(const DutParams& values);

} // namespace hilrig::duts
