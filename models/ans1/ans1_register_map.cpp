#include "models/ans1/ans1_register_map.hpp"

#include "models/ans1/host_interface.hpp"

namespace hilrig::models::ans1 {

namespace {

// The first host word of [address, address + count) within a block of kHostWords registers
// at base, or -1 when any of it falls outside.
int first_word(std::uint16_t address, std::size_t count, int base) {
  const int first = static_cast<int>(address) - base;
  if (count == 0 || first < 0 || first + static_cast<int>(count) > kHostWords) {
    return -1;
  }
  return first;
}

} // namespace

RegisterStatus Ans1RegisterMap::read_input_registers(std::uint16_t address, std::span<std::uint16_t> out) {
  const int first = first_word(address, out.size(), kModbusStatusBase);
  if (first < 0) {
    return RegisterStatus::IllegalDataAddress;
  }
  const HostWords status = device_.host().status();
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i] = status[static_cast<std::size_t>(first) + i];
  }
  return RegisterStatus::Ok;
}

RegisterStatus Ans1RegisterMap::read_holding_registers(std::uint16_t address, std::span<std::uint16_t> out) {
  const int first = first_word(address, out.size(), kModbusCommandBase);
  if (first < 0) {
    return RegisterStatus::IllegalDataAddress;
  }
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i] = device_.host().command(first + static_cast<int>(i));
  }
  return RegisterStatus::Ok;
}

RegisterStatus Ans1RegisterMap::write_holding_registers(std::uint16_t address,
                                                        std::span<const std::uint16_t> values) {
  const int first = first_word(address, values.size(), kModbusCommandBase);
  if (first < 0) {
    return RegisterStatus::IllegalDataAddress;
  }
  for (std::size_t i = 0; i < values.size(); ++i) {
    device_.host().write(first + static_cast<int>(i), values[i]);
  }
  return RegisterStatus::Ok;
}

} // namespace hilrig::models::ans1
