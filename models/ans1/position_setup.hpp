#pragma once
// The ANS1's global machine configuration (command block 2, spec §4.1/§5.3): the transducer,
// its scaling into Global Machine Position (GMP), the offset and preset, the speed filter and
// the input polarity. A plain struct: the host interface parses CB2 into it and the device
// applies it with Ans1::configure_position().
#include <cstdint>

namespace hilrig::models::ans1 {

enum class SensorType : std::uint8_t {
  Resolver,   // CB2 w1 bit 3 = 0: absolute, 4,096 counts per turn
  Quadrature, // CB2 w1 bit 3 = 1: A-quad-B, always 4X, Z ignored
};

struct PositionSetup {
  // CB2 word 1 bit parameters.
  SensorType sensor = SensorType::Resolver; // bit 3 QuadEnc
  bool slave_mode = false;                  // bit 2: position comes from a master ANS1
  bool count_ccw = false;                   // bit 0 CntDir: GMP increases counter-clockwise (resolver only)
  bool hold_outputs_on_fault = false; // bit 4 HoldOuts: outputs hold (1) or go off (0) on a transducer fault
  bool fault_auto_clear = false; // bit 1 XFltLatch: 1 = fault clears itself, 0 = latched until Clear Errors

  std::uint16_t counts_per_cycle = 4096; // CPC, 2..4096 (w2)
  std::uint16_t full_scale_count = 360;  // FSC, 1..CPC (w3)
  std::int32_t scaled_offset = 0;        // SMO, -(FSC-1)..+(FSC-1) (w4); a preset recomputes it
  std::uint16_t preset_value = 0;        // MPV, 0..FSC-1 (w5)
  std::uint8_t preset_input = 0;         // MPI, 0..16, 0 = none (w6)
  std::uint16_t rpm_filter = 40960;      // w7: k = rpm_filter / 65536 (default k = 0.625)
  std::uint16_t input_active_state = 0;  // w8: bit n-1 = 1 -> input n is active when NO current flows

  friend bool operator==(const PositionSetup&, const PositionSetup&) = default;
};

// CB2 word 1 (and DA0 word 5) packing of the bit parameters.
[[nodiscard]] constexpr std::uint16_t bit_parameters(const PositionSetup& s) {
  return static_cast<std::uint16_t>(
      (s.hold_outputs_on_fault ? 0x10U : 0U) | (s.sensor == SensorType::Quadrature ? 0x08U : 0U) |
      (s.slave_mode ? 0x04U : 0U) | (s.fault_auto_clear ? 0x02U : 0U) | (s.count_ccw ? 0x01U : 0U));
}

constexpr void set_bit_parameters(PositionSetup& s, std::uint16_t word) {
  s.hold_outputs_on_fault = (word & 0x10U) != 0;
  s.sensor = (word & 0x08U) != 0 ? SensorType::Quadrature : SensorType::Resolver;
  s.slave_mode = (word & 0x04U) != 0;
  s.fault_auto_clear = (word & 0x02U) != 0;
  s.count_ccw = (word & 0x01U) != 0;
}

} // namespace hilrig::models::ans1
