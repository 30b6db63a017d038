#pragma once
// A plain register map for the protocol tests: 10 input registers at 0, 10 holding registers
// at 1024, nothing else.

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>

#include "core/register_map.hpp"

namespace hilrig::drivers::modbus {

class PlainMap final : public RegisterMap {
public:
  std::array<std::uint16_t, 10> input{};
  std::array<std::uint16_t, 10> holding{};
  int writes = 0;

  RegisterStatus read_input_registers(std::uint16_t a, std::span<std::uint16_t> out) override {
    if (a + out.size() > 10) {
      return RegisterStatus::IllegalDataAddress;
    }
    std::copy_n(input.begin() + a, out.size(), out.begin());
    return RegisterStatus::Ok;
  }
  RegisterStatus read_holding_registers(std::uint16_t a, std::span<std::uint16_t> out) override {
    if (a < 1024 || a + out.size() > 1034) {
      return RegisterStatus::IllegalDataAddress;
    }
    std::copy_n(holding.begin() + (a - 1024), out.size(), out.begin());
    return RegisterStatus::Ok;
  }
  RegisterStatus write_holding_registers(std::uint16_t a, std::span<const std::uint16_t> v) override {
    if (a < 1024 || a + v.size() > 1034) {
      return RegisterStatus::IllegalDataAddress;
    }
    std::copy(v.begin(), v.end(), holding.begin() + (a - 1024));
    ++writes;
    return RegisterStatus::Ok;
  }
};

} // namespace hilrig::drivers::modbus
