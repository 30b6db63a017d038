#pragma once
// The virtual ANS1's host words as a core RegisterMap, so any host-link driver (the Modbus
// RTU/TCP servers) can serve them. The map is the ANS1E's at stack address 0 (README "Host
// register map", L1699-L1701, L2288-L2290):
//   input registers 0..19 (FC 4)          status words 0..19 (kModbusStatusBase + k)
//   holding registers 1024..1043 (FC 3/6/16) command words 0..19 (kModbusCommandBase + k)
// Anything else is IllegalDataAddress [MODEL: the manual names no other registers]. A write
// of several words lands between two scans, so the device sees them as one block.
#include <cstdint>
#include <span>

#include "core/register_map.hpp"
#include "models/ans1/ans1.hpp"

namespace hilrig::models::ans1 {

class Ans1RegisterMap final : public RegisterMap {
public:
  explicit Ans1RegisterMap(Ans1& device) : device_(device) {}

  RegisterStatus read_input_registers(std::uint16_t address, std::span<std::uint16_t> out) override;
  RegisterStatus read_holding_registers(std::uint16_t address, std::span<std::uint16_t> out) override;
  RegisterStatus write_holding_registers(std::uint16_t address,
                                         std::span<const std::uint16_t> values) override;

private:
  Ans1& device_;
};

} // namespace hilrig::models::ans1
