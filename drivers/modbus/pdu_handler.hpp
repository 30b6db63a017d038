#pragma once
// Answers one Modbus request PDU (function code + data) from a RegisterMap: the protocol
// logic of a Modbus server, free of sockets so it can be tested byte for byte.
// Function codes served: 1, 2, 3, 4, 5, 6, 15, 16, 22, 23 (the SMD23E's list, spec §6.1).
// Bit access (FC 1, 2, 5, 15) is a view on the registers: bit n = register n/16, bit n%16
// (LSB first), so coil 16,384 is holding register 1024 bit 0 and discrete input 0 is input
// register 0 bit 0.

#include <cstdint>
#include <span>
#include <vector>

#include "core/register_map.hpp"

namespace hilrig::drivers::modbus {

struct PduResult {
  RegisterStatus status = RegisterStatus::Ok; // not Ok: answer with this exception code
  std::vector<std::uint8_t> response;         // the response PDU when status is Ok
};

[[nodiscard]] PduResult handle_pdu(RegisterMap& map, std::span<const std::uint8_t> request);

} // namespace hilrig::drivers::modbus
