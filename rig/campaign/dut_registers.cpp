#include "rig/campaign/dut_registers.hpp"

#include <optional>

namespace hilrig::campaign {

namespace {

// The first word of [address, address + count) within `words` registers at base, or nullopt
// when any of it falls outside.
std::optional<std::size_t> first_word(std::uint16_t address, std::size_t count, std::uint16_t base,
                                      std::size_t words) {
  if (count == 0 || address < base) return std::nullopt;
  const std::size_t first = static_cast<std::size_t>(address - base);
  if (first + count > words) return std::nullopt;
  return first;
}

} // namespace

DutRegisters::DutRegisters(duts::Dut& dut, const HostRegisters& at, std::mutex& turn)
    : dut_(dut), at_(at), turn_(turn), commands_(at.command_words, 0) {}

RegisterStatus DutRegisters::read_input_registers(std::uint16_t address, std::span<std::uint16_t> out) {
  const auto first = first_word(address, out.size(), at_.status_base, at_.status_words);
  if (!first) return RegisterStatus::IllegalDataAddress;
  const std::scoped_lock lock(turn_);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = dut_.host_read(*first + i);
  return RegisterStatus::Ok;
}

RegisterStatus DutRegisters::read_holding_registers(std::uint16_t address, std::span<std::uint16_t> out) {
  const auto first = first_word(address, out.size(), at_.command_base, at_.command_words);
  if (!first) return RegisterStatus::IllegalDataAddress;
  const std::scoped_lock lock(turn_);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = commands_[*first + i];
  return RegisterStatus::Ok;
}

RegisterStatus DutRegisters::write_holding_registers(std::uint16_t address,
                                                     std::span<const std::uint16_t> values) {
  const auto first = first_word(address, values.size(), at_.command_base, at_.command_words);
  if (!first) return RegisterStatus::IllegalDataAddress;
  const std::scoped_lock lock(turn_);
  for (std::size_t i = 0; i < values.size(); ++i) {
    dut_.host_write(*first + i, values[i]);
    commands_[*first + i] = values[i];
  }
  return RegisterStatus::Ok;
}

} // namespace hilrig::campaign
