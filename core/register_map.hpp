#pragma once
// A Modbus-style register device, independent of any backend: a model implements it, a
// driver (e.g. the Modbus TCP server) serves it. Addresses are 0-based PDU addresses.
// Each access either succeeds or names the Modbus exception the device answers with.

#include <cstdint>
#include <span>

namespace hilrig {

// Modbus exception codes (Modbus Application Protocol v1.1b3, §7); Ok = success.
enum class RegisterStatus : std::uint8_t {
  Ok = 0,
  IllegalFunction = 1,
  IllegalDataAddress = 2,
  IllegalDataValue = 3,
  DeviceFailure = 4,
};

class RegisterMap {
public:
  virtual ~RegisterMap() = default;
  // Reads out.size() consecutive input registers (FC 4) starting at address.
  virtual RegisterStatus read_input_registers(std::uint16_t address, std::span<std::uint16_t> out) = 0;
  // Reads out.size() consecutive holding registers (FC 3) starting at address.
  virtual RegisterStatus read_holding_registers(std::uint16_t address, std::span<std::uint16_t> out) = 0;
  // Writes values to consecutive holding registers (FC 6/16) as one transaction.
  virtual RegisterStatus write_holding_registers(std::uint16_t address,
                                                 std::span<const std::uint16_t> values) = 0;
};

} // namespace hilrig
