#include "models/pls2700/register_map.hpp"

#include <algorithm>

namespace hilrig::models::pls2700 {

RegisterStatus Pls2700Registers::read_input_registers(std::uint16_t address, std::span<std::uint16_t> out) {
  if (out.empty()) {
    return RegisterStatus::IllegalDataValue;
  }
  if (address == kRegSingleTransfer && out.size() == 1 && device_.model().single_transfer) {
    out[0] = device_.single_transfer_word();
    return RegisterStatus::Ok;
  }
  if (static_cast<std::size_t>(address) + out.size() > device_.btr_words()) {
    return RegisterStatus::IllegalDataAddress;
  }
  for (std::size_t k = 0; k < out.size(); ++k) {
    out[k] = device_.btr_word(address + k);
  }
  return RegisterStatus::Ok;
}

RegisterStatus Pls2700Registers::read_holding_registers(std::uint16_t address, std::span<std::uint16_t> out) {
  if (out.empty()) {
    return RegisterStatus::IllegalDataValue;
  }
  const std::size_t end = static_cast<std::size_t>(address) + out.size();
  if (end > kRegErrorByte + 1u) {
    return RegisterStatus::IllegalDataAddress;
  }
  for (std::size_t k = 0; k < out.size(); ++k) {
    const std::size_t reg = address + k;
    out[k] = reg == kRegErrorByte ? device_.error_byte() : last_btw_[reg];
  }
  return RegisterStatus::Ok;
}

RegisterStatus Pls2700Registers::write_holding_registers(std::uint16_t address,
                                                         std::span<const std::uint16_t> values) {
  if (address != kRegBtw) {
    return RegisterStatus::IllegalDataAddress;
  }
  if (values.empty() || values.size() > kMaxBtwWords) {
    return RegisterStatus::IllegalDataValue;
  }
  last_btw_.fill(0);
  std::copy(values.begin(), values.end(), last_btw_.begin());
  device_.write_btw(values); // a programming error is data (the error byte), not an exception
  return RegisterStatus::Ok;
}

} // namespace hilrig::models::pls2700
