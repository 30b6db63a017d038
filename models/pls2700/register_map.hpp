#pragma once
// The 2700's block transfers as a core RegisterMap, for the Modbus host link (the rig's
// stand-in for a PLC-5 and its 1771 chassis). Word by word (README.md):
//   input registers (FC 4)   0..4  the BTR: position 1, tach 1, status (1-ch: 3 words) or
//                                   position 1, tach 1, position 2, tach 2, status (2-ch: 5)
//                            16    the single-transfer position word (2731-04 only)
//   holding registers (FC 16) 0..63 the BTW: one write of n words at address 0 is one BTW of
//                                   n words (length exact, L1269); FC 3 reads back the last BTW
//                            64    (read only) the programming error byte after the last BTW
#include <array>
#include <cstdint>

#include "core/register_map.hpp"
#include "models/pls2700/pls2700.hpp"

namespace hilrig::models::pls2700 {

inline constexpr std::uint16_t kRegSingleTransfer = 16;
inline constexpr std::uint16_t kRegBtw = 0;
inline constexpr std::uint16_t kRegErrorByte = 64;

class Pls2700Registers final : public RegisterMap {
public:
  explicit Pls2700Registers(Pls2700& device) : device_(device) {}
  RegisterStatus read_input_registers(std::uint16_t address, std::span<std::uint16_t> out) override;
  RegisterStatus read_holding_registers(std::uint16_t address, std::span<std::uint16_t> out) override;
  RegisterStatus write_holding_registers(std::uint16_t address,
                                         std::span<const std::uint16_t> values) override;

private:
  Pls2700& device_;
  std::array<std::uint16_t, kMaxBtwWords> last_btw_{};
};

} // namespace hilrig::models::pls2700
