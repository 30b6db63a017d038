#pragma once
// Everything a host can program into the ANS1, as one value: the global configuration (CB2),
// the 16 limit-switch outputs (CB3-CB6), the shift register (CB9) and the monitors (CB7, CB8,
// CB10, CB11). The host interface decodes command blocks into a new Ans1Setup, stores programs
// as Ans1Setups, and applies them to the device; a default Ans1Setup is the factory setup.
#include <array>

#include "models/ans1/monitor_setup.hpp"
#include "models/ans1/output_setup.hpp"
#include "models/ans1/position_setup.hpp"

namespace hilrig::models::ans1 {

struct Ans1Setup {
  PositionSetup position{};
  std::array<OutputSetup, kOutputCount> outputs{};
  ShiftRegisterSetup shift_register{};
  MonitorSetup monitors{};
  friend bool operator==(const Ans1Setup&, const Ans1Setup&) = default;

  [[nodiscard]] OutputSetup& output(int n) { return outputs[static_cast<std::size_t>(n - 1)]; }
  [[nodiscard]] const OutputSetup& output(int n) const { return outputs[static_cast<std::size_t>(n - 1)]; }
};

} // namespace hilrig::models::ans1
