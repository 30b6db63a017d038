#include "models/ssi7361/registers.hpp"

#include <algorithm>

namespace hilrig::models::ssi7361 {
namespace {

RegisterStatus check(std::uint16_t address, std::size_t count, std::size_t words) {
  if (count == 0) return RegisterStatus::IllegalDataValue;
  if (address >= words || count > words - address) return RegisterStatus::IllegalDataAddress;
  return RegisterStatus::Ok;
}

} // namespace

RegisterStatus Ssi7361Registers::read_input_registers(std::uint16_t address, std::span<std::uint16_t> out) {
  const RegisterStatus s = check(address, out.size(), kStatusWords);
  if (s == RegisterStatus::Ok) module_.read_status_words(address, out);
  return s;
}

RegisterStatus Ssi7361Registers::read_holding_registers(std::uint16_t address, std::span<std::uint16_t> out) {
  const RegisterStatus s = check(address, out.size(), kCommandWords);
  if (s == RegisterStatus::Ok)
    std::copy_n(module_.command_words().begin() + address, out.size(), out.begin());
  return s;
}

RegisterStatus Ssi7361Registers::write_holding_registers(std::uint16_t address,
                                                         std::span<const std::uint16_t> values) {
  const RegisterStatus s = check(address, values.size(), kCommandWords);
  if (s == RegisterStatus::Ok) module_.write_command_words(address, values);
  return s;
}

} // namespace hilrig::models::ssi7361
