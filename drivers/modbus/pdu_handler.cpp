#include "drivers/modbus/pdu_handler.hpp"

#include <algorithm>
#include <array>

namespace hilrig::drivers::modbus {

namespace {

constexpr std::size_t kMaxRegs = 125; // registers in one read response (Modbus spec §6.3)

std::uint16_t be16(std::span<const std::uint8_t> p, std::size_t at) {
  return static_cast<std::uint16_t>((p[at] << 8U) | p[at + 1]);
}

void put16(std::vector<std::uint8_t>& out, std::uint16_t v) {
  out.push_back(static_cast<std::uint8_t>(v >> 8U));
  out.push_back(static_cast<std::uint8_t>(v & 0xFFU));
}

PduResult fail(RegisterStatus s) { return {s, {}}; }

// Register range covering bits [address, address + count).
struct BitSpan {
  std::uint16_t first_reg;
  std::size_t regs;
};
BitSpan bit_span(std::uint32_t address, std::uint32_t count) {
  const std::uint32_t first = address / 16U;
  const std::uint32_t last = (address + count - 1U) / 16U;
  return {static_cast<std::uint16_t>(first), static_cast<std::size_t>(last - first + 1U)};
}

bool bit_of(std::span<const std::uint16_t> regs, std::uint32_t first_reg, std::uint32_t bit) {
  return ((static_cast<unsigned>(regs[bit / 16U - first_reg]) >> (bit % 16U)) & 1U) != 0;
}

PduResult read_bits(RegisterMap& map, std::span<const std::uint8_t> req, bool coils) {
  if (req.size() != 5) {
    return fail(RegisterStatus::IllegalDataValue);
  }
  const std::uint16_t address = be16(req, 1);
  const std::uint16_t count = be16(req, 3);
  if (count < 1 || count > 2000) {
    return fail(RegisterStatus::IllegalDataValue);
  }
  if (std::uint32_t{address} + count > 0x10000U) {
    return fail(RegisterStatus::IllegalDataAddress);
  }
  const BitSpan span = bit_span(address, count);
  std::array<std::uint16_t, 126> regs{};
  const std::span<std::uint16_t> view(regs.data(), span.regs);
  const RegisterStatus s = coils ? map.read_holding_registers(span.first_reg, view)
                                 : map.read_input_registers(span.first_reg, view);
  if (s != RegisterStatus::Ok) {
    return fail(s);
  }
  PduResult r;
  r.response.push_back(req[0]);
  r.response.push_back(static_cast<std::uint8_t>((count + 7U) / 8U));
  std::uint8_t byte = 0;
  for (std::uint32_t i = 0; i < count; ++i) {
    if (bit_of(view, span.first_reg, address + i)) {
      byte = static_cast<std::uint8_t>(byte | (1U << (i % 8U)));
    }
    if (i % 8U == 7U || i + 1 == count) {
      r.response.push_back(byte);
      byte = 0;
    }
  }
  return r;
}

PduResult read_registers(RegisterMap& map, std::span<const std::uint8_t> req, bool holding) {
  if (req.size() != 5) {
    return fail(RegisterStatus::IllegalDataValue);
  }
  const std::uint16_t address = be16(req, 1);
  const std::uint16_t count = be16(req, 3);
  if (count < 1 || count > kMaxRegs) {
    return fail(RegisterStatus::IllegalDataValue);
  }
  if (std::uint32_t{address} + count > 0x10000U) {
    return fail(RegisterStatus::IllegalDataAddress);
  }
  std::array<std::uint16_t, kMaxRegs> regs{};
  const std::span<std::uint16_t> view(regs.data(), count);
  const RegisterStatus s =
      holding ? map.read_holding_registers(address, view) : map.read_input_registers(address, view);
  if (s != RegisterStatus::Ok) {
    return fail(s);
  }
  PduResult r;
  r.response.push_back(req[0]);
  r.response.push_back(static_cast<std::uint8_t>(count * 2U));
  for (std::uint16_t v : view) {
    put16(r.response, v);
  }
  return r;
}

// Writes bits through a read-modify-write of the registers that hold them.
RegisterStatus write_bits(RegisterMap& map, std::uint16_t address, std::uint16_t count,
                          std::span<const std::uint8_t> packed) {
  const BitSpan span = bit_span(address, count);
  std::array<std::uint16_t, 126> regs{};
  const std::span<std::uint16_t> view(regs.data(), span.regs);
  if (const RegisterStatus s = map.read_holding_registers(span.first_reg, view); s != RegisterStatus::Ok) {
    return s;
  }
  for (std::uint32_t i = 0; i < count; ++i) {
    const bool on = ((static_cast<unsigned>(packed[i / 8U]) >> (i % 8U)) & 1U) != 0;
    const std::uint32_t bit = address + i;
    std::uint16_t& reg = view[bit / 16U - span.first_reg];
    const auto mask = static_cast<std::uint16_t>(1U << (bit % 16U));
    reg = static_cast<std::uint16_t>(on ? (reg | mask) : (reg & ~mask));
  }
  return map.write_holding_registers(span.first_reg, view);
}

// The registers of `read` (from read_address) that the write just set take the written values.
void overlay_written(std::span<std::uint16_t> read, std::uint16_t read_address,
                     std::span<const std::uint16_t> written, std::uint16_t write_address) {
  for (std::size_t i = 0; i < read.size(); ++i) {
    const std::size_t address = read_address + i;
    if (address >= write_address && address < write_address + written.size()) {
      read[i] = written[address - write_address];
    }
  }
}

PduResult echo(std::span<const std::uint8_t> req, std::size_t n) {
  return {RegisterStatus::Ok,
          std::vector<std::uint8_t>(req.begin(), req.begin() + static_cast<std::ptrdiff_t>(n))};
}

} // namespace

PduResult handle_pdu(RegisterMap& map, std::span<const std::uint8_t> req, Fc23Read fc23_read) {
  if (req.empty()) {
    return fail(RegisterStatus::IllegalFunction);
  }
  switch (req[0]) {
  case 1:
    return read_bits(map, req, true);
  case 2:
    return read_bits(map, req, false);
  case 3:
    return read_registers(map, req, true);
  case 4:
    return read_registers(map, req, false);
  case 5: {
    if (req.size() != 5) {
      return fail(RegisterStatus::IllegalDataValue);
    }
    const std::uint16_t value = be16(req, 3);
    if (value != 0xFF00 && value != 0x0000) {
      return fail(RegisterStatus::IllegalDataValue);
    }
    const std::array<std::uint8_t, 1> packed{static_cast<std::uint8_t>(value != 0 ? 1 : 0)};
    if (const RegisterStatus s = write_bits(map, be16(req, 1), 1, packed); s != RegisterStatus::Ok) {
      return fail(s);
    }
    return echo(req, 5);
  }
  case 6: {
    if (req.size() != 5) {
      return fail(RegisterStatus::IllegalDataValue);
    }
    const std::array<std::uint16_t, 1> v{be16(req, 3)};
    if (const RegisterStatus s = map.write_holding_registers(be16(req, 1), v); s != RegisterStatus::Ok) {
      return fail(s);
    }
    return echo(req, 5);
  }
  case 15: {
    if (req.size() < 6) {
      return fail(RegisterStatus::IllegalDataValue);
    }
    const std::uint16_t address = be16(req, 1);
    const std::uint16_t count = be16(req, 3);
    if (count < 1 || count > 1968 || req[5] != (count + 7U) / 8U || req.size() != 6U + req[5]) {
      return fail(RegisterStatus::IllegalDataValue);
    }
    if (std::uint32_t{address} + count > 0x10000U) {
      return fail(RegisterStatus::IllegalDataAddress);
    }
    if (const RegisterStatus s = write_bits(map, address, count, req.subspan(6)); s != RegisterStatus::Ok) {
      return fail(s);
    }
    return echo(req, 5);
  }
  case 16: {
    if (req.size() < 6) {
      return fail(RegisterStatus::IllegalDataValue);
    }
    const std::uint16_t address = be16(req, 1);
    const std::uint16_t count = be16(req, 3);
    if (count < 1 || count > 123 || req[5] != count * 2U || req.size() != 6U + req[5]) {
      return fail(RegisterStatus::IllegalDataValue);
    }
    if (std::uint32_t{address} + count > 0x10000U) {
      return fail(RegisterStatus::IllegalDataAddress);
    }
    std::array<std::uint16_t, 123> values{};
    for (std::size_t i = 0; i < count; ++i) {
      values[i] = be16(req, 6 + 2 * i);
    }
    if (const RegisterStatus s = map.write_holding_registers(address, std::span(values.data(), count));
        s != RegisterStatus::Ok) {
      return fail(s);
    }
    return echo(req, 5);
  }
  case 22: {
    if (req.size() != 7) {
      return fail(RegisterStatus::IllegalDataValue);
    }
    const std::uint16_t address = be16(req, 1);
    std::array<std::uint16_t, 1> reg{};
    if (const RegisterStatus s = map.read_holding_registers(address, reg); s != RegisterStatus::Ok) {
      return fail(s);
    }
    const std::uint16_t and_mask = be16(req, 3);
    const std::uint16_t or_mask = be16(req, 5);
    reg[0] = static_cast<std::uint16_t>((reg[0] & and_mask) | (or_mask & ~and_mask));
    if (const RegisterStatus s = map.write_holding_registers(address, reg); s != RegisterStatus::Ok) {
      return fail(s);
    }
    return echo(req, 7);
  }
  case 23: {
    if (req.size() < 10) {
      return fail(RegisterStatus::IllegalDataValue);
    }
    const std::uint16_t read_address = be16(req, 1);
    const std::uint16_t read_count = be16(req, 3);
    const std::uint16_t write_address = be16(req, 5);
    const std::uint16_t write_count = be16(req, 7);
    if (read_count < 1 || read_count > kMaxRegs || write_count < 1 || write_count > 121 ||
        req[9] != write_count * 2U || req.size() != 10U + req[9]) {
      return fail(RegisterStatus::IllegalDataValue);
    }
    if (std::uint32_t{read_address} + read_count > 0x10000U ||
        std::uint32_t{write_address} + write_count > 0x10000U) {
      return fail(RegisterStatus::IllegalDataAddress);
    }
    // The read half is read before the write too, so that a read the map refuses refuses the
    // whole request before anything is written.
    std::array<std::uint16_t, kMaxRegs> regs{};
    const std::span<std::uint16_t> view(regs.data(), read_count);
    if (const RegisterStatus s = map.read_holding_registers(read_address, view); s != RegisterStatus::Ok) {
      return fail(s);
    }
    std::array<std::uint16_t, 121> values{};
    for (std::size_t i = 0; i < write_count; ++i) {
      values[i] = be16(req, 10 + 2 * i);
    }
    if (const RegisterStatus s =
            map.write_holding_registers(write_address, std::span(values.data(), write_count));
        s != RegisterStatus::Ok) {
      return fail(s);
    }
    if (fc23_read == Fc23Read::AfterWrite) {
      if (const RegisterStatus s = map.read_holding_registers(read_address, view); s != RegisterStatus::Ok) {
        return fail(s);
      }
    } else {
      overlay_written(view, read_address, std::span(values.data(), write_count), write_address);
    }
    PduResult r;
    r.response.push_back(req[0]);
    r.response.push_back(static_cast<std::uint8_t>(read_count * 2U));
    for (std::uint16_t v : view) {
      put16(r.response, v);
    }
    return r;
  }
  default:
    return fail(RegisterStatus::IllegalFunction);
  }
}

} // namespace hilrig::drivers::modbus
