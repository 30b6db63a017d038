#pragma once
// A register map for the Modbus fuzzers: 1024 holding and 1024 input registers; an access
// beyond them is the illegal-address exception a real board answers.

#include <array>
#include <cstdint>
#include <span>

#include "core/register_map.hpp"

namespace hilrig::fuzz {

class FuzzRegisterMap final : public RegisterMap {
public:
  static constexpr std::size_t kRegisters = 1024;

  RegisterStatus read_input_registers(std::uint16_t address, std::span<std::uint16_t> out) override {
    return copy_out(input_, address, out);
  }
  RegisterStatus read_holding_registers(std::uint16_t address, std::span<std::uint16_t> out) override {
    return copy_out(holding_, address, out);
  }
  RegisterStatus write_holding_registers(std::uint16_t address,
                                         std::span<const std::uint16_t> values) override {
    if (address + values.size() > kRegisters) return RegisterStatus::IllegalDataAddress;
    for (std::size_t i = 0; i < values.size(); ++i) {
      holding_[address + i] = values[i];
      input_[address + i] = static_cast<std::uint16_t>(values[i] ^ 0xA5A5U);
    }
    return RegisterStatus::Ok;
  }

private:
  static RegisterStatus copy_out(const std::array<std::uint16_t, kRegisters>& from, std::uint16_t address,
                                 std::span<std::uint16_t> out) {
    if (address + out.size() > kRegisters) return RegisterStatus::IllegalDataAddress;
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = from[address + i];
    return RegisterStatus::Ok;
  }

  std::array<std::uint16_t, kRegisters> holding_{};
  std::array<std::uint16_t, kRegisters> input_{};
};

} // namespace hilrig::fuzz
