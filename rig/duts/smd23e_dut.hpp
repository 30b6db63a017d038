#pragma once
// The SMD23E adapter: the virtual AMCI SMD23E integrated stepper (models/smd23e) as a
// campaign's DUT. Pins IN1..IN3 (the discrete inputs, High = current flows) and two shaft
// sensor outputs the rig observes the motor with from the outside: STEP has one edge
// (either level) for every step the shaft turns, DIR is High while those steps are CW and
// Low while they are CCW (Low at power-up). The host's 10 output words (holding registers
// 1024..1033) and 10 input words (input registers 0..9), register style with no handshake:
// words 1..9 are staged and a write of word 0 sends the whole block as one Modbus write
// (FC 16), as a PLC does. Variants: "nominal" and the model's fault names.

#include "models/smd23e/params.hpp"
#include "rig/duts/dut.hpp"

namespace hilrig::duts {

inline constexpr const char* kSmd23eStepPin = "STEP";
inline constexpr const char* kSmd23eDirPin = "DIR";
inline constexpr const char* kSmd23eEncoderAPin = "ENC_A";
inline constexpr const char* kSmd23eEncoderBPin = "ENC_B";

// The registry entry (name "smd23e").
[[nodiscard]] DutInfo smd23e_info();
// The model's Params from every parameter of smd23e_info() (a campaign's or a served one's);
// the fault variant is set apart, by name.
[[nodiscard]] models::smd23e::Params smd23e_params(const DutParams& values);

} // namespace hilrig::duts
