#pragma once
// The board side of a Modbus host link to a virtual DUT: the DUT adapter's host words as a
// RegisterMap at the addresses `hilrig serve` gives the device (command word k = holding
// register command_base + k, status word k = input register status_base + k; anything else
// is IllegalDataAddress). Served by an RtuServer on another thread, so every access first
// takes `turn`: the simulation thread holds it except while one of its host transactions is
// in flight (lockstep), and the DUT is touched at the paused virtual time.

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <span>
#include <vector>

#include "core/register_map.hpp"
#include "rig/duts/dut.hpp"

namespace hilrig::campaign {

// Where a device's host words sit in its Modbus register map.
struct HostRegisters {
  std::uint16_t command_base = 0; // holding register of command (output) word 0
  std::size_t command_words = 0;
  std::uint16_t status_base = 0; // input register of status (input) word 0
  std::size_t status_words = 0;
};

class DutRegisters final : public RegisterMap {
public:
  // The DUT and the mutex outlive the map.
  DutRegisters(duts::Dut& dut, const HostRegisters& at, std::mutex& turn);

  RegisterStatus read_input_registers(std::uint16_t address, std::span<std::uint16_t> out) override;
  // The command words as last written (the DUT adapter has no read-back of its own).
  RegisterStatus read_holding_registers(std::uint16_t address, std::span<std::uint16_t> out) override;
  RegisterStatus write_holding_registers(std::uint16_t address,
                                         std::span<const std::uint16_t> values) override;

private:
  duts::Dut& dut_;
  HostRegisters at_;
  std::mutex& turn_;
  std::vector<std::uint16_t> commands_;
};

} // namespace hilrig::campaign
