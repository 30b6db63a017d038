#pragma once
// The 4501's SLC I/O image as a core RegisterMap, so the Modbus server (drivers/modbus)
// can serve the model. 0-based PDU addresses (README.md, "Register map"):
//   input registers   0..7 = I:s.0 .. I:s.7  (FC 4; 0 = status word)
//   holding registers 0..7 = O:s.0 .. O:s.7  (FC 3 reads back, FC 6/16 writes; 0 = control)
// A write of several holding registers is one transaction: a Transmit 0->1 in word 0 acts
// on the setpoint/timeout words written with it. Outside 0..7: Illegal Data Address; no
// registers asked for: Illegal Data Value.

#include "core/register_map.hpp"
#include "models/amci4501/amci4501.hpp"

namespace hilrig::models::amci4501 {

class Amci4501Registers final : public RegisterMap {
public:
  explicit Amci4501Registers(Amci4501& module) : module_(module) {}

  RegisterStatus read_input_registers(std::uint16_t address, std::span<std::uint16_t> out) override;
  RegisterStatus read_holding_registers(std::uint16_t address, std::span<std::uint16_t> out) override;
  RegisterStatus write_holding_registers(std::uint16_t address,
                                         std::span<const std::uint16_t> values) override;

private:
  Amci4501& module_;
};

} // namespace hilrig::models::amci4501
