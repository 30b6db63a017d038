#pragma once
// The 7361's host words as a core RegisterMap, so the Modbus server (drivers/modbus) can
// serve the model. 0-based PDU addresses (README.md, "Register map"):
//   input registers   0..6 = %I, %AI1..%AI6   (FC 4)
//   holding registers 0..6 = %Q, %AQ1..%AQ6   (FC 3 reads back, FC 6/16 writes)
// A write of several holding registers is one transaction: a TRMT 0->1 edge in %Q acts on
// the %AQ words written with it. Outside 0..6: Illegal Data Address; no registers asked
// for: Illegal Data Value.

#include "core/register_map.hpp"
#include "models/ssi7361/ssi7361.hpp"

namespace hilrig::models::ssi7361 {

class Ssi7361Registers final : public RegisterMap {
public:
  explicit Ssi7361Registers(Ssi7361& module) : module_(module) {}

  RegisterStatus read_input_registers(std::uint16_t address, std::span<std::uint16_t> out) override;
  RegisterStatus read_holding_registers(std::uint16_t address, std::span<std::uint16_t> out) override;
  RegisterStatus write_holding_registers(std::uint16_t address,
                                         std::span<const std::uint16_t> values) override;

private:
  Ssi7361& module_;
};

} // namespace hilrig::models::ssi7361
