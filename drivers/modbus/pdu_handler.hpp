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

// What the read half of FC 23 (Read/Write Multiple Registers) answers: a trait of the device
// served, set in `hilrig serve`'s device table (rig/cli/serve_devices.cpp).
enum class Fc23Read : std::uint8_t {
  // "The write operation is performed before the read" (Modbus Application Protocol v1.1b3,
  // §6.17): the read sees the write and whatever the device did in answer to it.
  AfterWrite,
  // The write is performed first too, but the device answers from a buffer filled before it:
  // the registers just written read as written, every other register as it was before the
  // write, and the device's response to the new data comes with the next read (the SMD23E,
  // its manual L2076).
  ResponseFromBeforeWrite,
};

struct PduResult {
  RegisterStatus status = RegisterStatus::Ok; // not Ok: answer with this exception code
  std::vector<std::uint8_t> response;         // the response PDU when status is Ok
};

[[nodiscard]] PduResult handle_pdu(RegisterMap& map, std::span<const std::uint8_t> request,
                                   Fc23Read fc23_read = Fc23Read::AfterWrite);

} // namespace hilrig::drivers::modbus
