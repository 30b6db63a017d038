#include "models/amci4501/registers.hpp"

#include <algorithm>

namespace hilrig::models::amci4501 {

namespace {
RegisterStatus check(std::uint16_t address, std::size_t count) {
  if (count == 0) return RegisterStatus::IllegalDataValue;
  if (address >= kWords || count > kWords - address) return RegisterStatus::IllegalDataAddress;
  return RegisterStatus::Ok;
}
} // namespace

RegisterStatus Amci4501Registers::read_input_registers(std::uint16_t address, std::span<std::uint16_t> out) {
  const RegisterStatus s = check(address, out.size());
  if (s == RegisterStatus::Ok) module_.read_input_words(address, out);
  return s;
}

RegisterStatus Amci4501Registers::read_holding_registers(std::uint16_t address,
                                                         std::span<std::uint16_t> out) {
  const RegisterStatus s = check(address, out.size());
  if (s == RegisterStatus::Ok) std::copy_n(module_.output_words().begin() + address, out.size(), out.begin());
  return s;
}

RegisterStatus Amci4501Registers::write_holding_registers(std::uint16_t address,
                                                          std::span<const std::uint16_t> values) {
  const RegisterStatus s = check(address, values.size());
  if (s == RegisterStatus::Ok) module_.write_output_words(address, values);
  return s;
}

} // namespace hilrig::models::amci4501
