// The Modbus server's protocol logic, byte for byte (Modbus Application Protocol v1.1b3),
// against a plain register map: 10 input registers at 0, 10 holding registers at 1024.
#include <gtest/gtest.h>

#include <array>
#include <span>
#include <vector>

#include "drivers/modbus/pdu_handler.hpp"
#include "tests/modbus/plain_map.hpp"

namespace hilrig::drivers::modbus {
namespace {

using Bytes = std::vector<std::uint8_t>;

PduResult ask(RegisterMap& m, const Bytes& req) { return handle_pdu(m, req); }

TEST(ModbusPdu, ReadInputRegisters) {
  PlainMap m;
  m.input[0] = 0x6408;
  m.input[1] = 0x0807;
  const PduResult r = ask(m, {4, 0x00, 0x00, 0x00, 0x02});
  ASSERT_EQ(r.status, RegisterStatus::Ok);
  EXPECT_EQ(r.response, (Bytes{4, 4, 0x64, 0x08, 0x08, 0x07}));
}

TEST(ModbusPdu, WriteMultipleThenReadHolding) {
  PlainMap m;
  // FC16 at 1024 (0x0400), 2 registers, 4 bytes: 0x8000, 0x0001.
  const PduResult w = ask(m, {16, 0x04, 0x00, 0x00, 0x02, 4, 0x80, 0x00, 0x00, 0x01});
  ASSERT_EQ(w.status, RegisterStatus::Ok);
  EXPECT_EQ(w.response, (Bytes{16, 0x04, 0x00, 0x00, 0x02}));
  EXPECT_EQ(m.writes, 1); // one transaction
  const PduResult r = ask(m, {3, 0x04, 0x00, 0x00, 0x02});
  EXPECT_EQ(r.response, (Bytes{3, 4, 0x80, 0x00, 0x00, 0x01}));
}

TEST(ModbusPdu, WriteSingleRegisterEchoes) {
  PlainMap m;
  const Bytes req{6, 0x04, 0x01, 0x12, 0x34};
  EXPECT_EQ(ask(m, req).response, req);
  EXPECT_EQ(m.holding[1], 0x1234);
}

TEST(ModbusPdu, MaskWrite) {
  PlainMap m;
  m.holding[0] = 0x0012;
  // Spec example: (0x12 AND 0xF2) OR (0x25 AND NOT 0xF2) = 0x17.
  const Bytes req{22, 0x04, 0x00, 0x00, 0xF2, 0x00, 0x25};
  EXPECT_EQ(ask(m, req).response, req);
  EXPECT_EQ(m.holding[0], 0x0017);
}

// A device that answers a write: holding register 1024 written v sets 1025 to v + 1.
class AnsweringMap final : public RegisterMap {
public:
  PlainMap plain;
  RegisterStatus read_input_registers(std::uint16_t a, std::span<std::uint16_t> out) override {
    return plain.read_input_registers(a, out);
  }
  RegisterStatus read_holding_registers(std::uint16_t a, std::span<std::uint16_t> out) override {
    return plain.read_holding_registers(a, out);
  }
  RegisterStatus write_holding_registers(std::uint16_t a, std::span<const std::uint16_t> v) override {
    const RegisterStatus s = plain.write_holding_registers(a, v);
    if (s == RegisterStatus::Ok && a == 1024) {
      plain.holding[1] = static_cast<std::uint16_t>(v[0] + 1);
    }
    return s;
  }
};

// FC 23 reading 1024×2 and writing 1024×1 = 0x2222.
const Bytes kReadTwoWriteOne{23, 0x04, 0x00, 0x00, 0x02, 0x04, 0x00, 0x00, 0x01, 2, 0x22, 0x22};

TEST(ModbusPdu, ReadWriteMultipleWritesBeforeItReads) {
  AnsweringMap m;
  m.plain.holding[0] = 0x1111;
  m.plain.holding[1] = 0x1112;
  // "The write operation is performed before the read" (§6.17): the read sees the write and
  // the device's answer to it.
  const PduResult r = handle_pdu(m, kReadTwoWriteOne, Fc23Read::AfterWrite);
  ASSERT_EQ(r.status, RegisterStatus::Ok);
  EXPECT_EQ(r.response, (Bytes{23, 4, 0x22, 0x22, 0x22, 0x23}));
  EXPECT_EQ(handle_pdu(m, kReadTwoWriteOne).response, r.response); // the protocol's order by default
}

TEST(ModbusPdu, ReadWriteMultipleCanAnswerWithTheResponseFromBeforeTheWrite) {
  AnsweringMap m;
  m.plain.holding[0] = 0x1111;
  m.plain.holding[1] = 0x1112;
  // The SMD23E's buffered answer (its manual, L2076): the register written reads as written,
  // the device's answer to it (1025) as before; the answer comes with the next read.
  const PduResult r = handle_pdu(m, kReadTwoWriteOne, Fc23Read::ResponseFromBeforeWrite);
  ASSERT_EQ(r.status, RegisterStatus::Ok);
  EXPECT_EQ(r.response, (Bytes{23, 4, 0x22, 0x22, 0x11, 0x12}));
  EXPECT_EQ(m.plain.holding[0], 0x2222);
  EXPECT_EQ(ask(m, {3, 0x04, 0x00, 0x00, 0x02}).response, (Bytes{3, 4, 0x22, 0x22, 0x22, 0x23}));
}

TEST(ModbusPdu, ReadWriteMultipleWithARefusedReadWritesNothing) {
  for (const Fc23Read order : {Fc23Read::AfterWrite, Fc23Read::ResponseFromBeforeWrite}) {
    PlainMap m;
    // Read 1034×1 (one past the holding registers), write 1024×1.
    const Bytes req{23, 0x04, 0x0A, 0x00, 0x01, 0x04, 0x00, 0x00, 0x01, 2, 0x22, 0x22};
    EXPECT_EQ(handle_pdu(m, req, order).status, RegisterStatus::IllegalDataAddress);
    EXPECT_EQ(m.writes, 0);
  }
}

TEST(ModbusPdu, CoilsAreBitsOfTheHoldingRegisters) {
  PlainMap m;
  // Coil 16,384 + 1 = register 1024 bit 1 (spec §6.1 [D]).
  const Bytes on{5, 0x40, 0x01, 0xFF, 0x00};
  EXPECT_EQ(ask(m, on).response, on);
  EXPECT_EQ(m.holding[0], 0x0002);
  // Write coils 16,384…16,399 as 0x8000 (only bit 15): bytes LSB first.
  EXPECT_EQ(ask(m, {15, 0x40, 0x00, 0x00, 0x10, 2, 0x00, 0x80}).status, RegisterStatus::Ok);
  EXPECT_EQ(m.holding[0], 0x8000);
  EXPECT_EQ(ask(m, {1, 0x40, 0x0F, 0x00, 0x02}).response, (Bytes{1, 1, 0x01})); // bits 15, 16
}

TEST(ModbusPdu, DiscreteInputsAreBitsOfTheInputRegisters) {
  PlainMap m;
  m.input[1] = 0x0005; // input bits 16 and 18
  EXPECT_EQ(ask(m, {2, 0x00, 0x10, 0x00, 0x03}).response, (Bytes{2, 1, 0x05}));
}

TEST(ModbusPdu, UnknownFunctionIsIllegalFunction) {
  PlainMap m;
  EXPECT_EQ(ask(m, {0x41}).status, RegisterStatus::IllegalFunction);
  EXPECT_EQ(ask(m, {7}).status, RegisterStatus::IllegalFunction); // not in the SMD23E's list
}

TEST(ModbusPdu, AddressOutsideTheMapIsIllegalDataAddress) {
  PlainMap m;
  EXPECT_EQ(ask(m, {4, 0x00, 0x09, 0x00, 0x02}).status, RegisterStatus::IllegalDataAddress);
  EXPECT_EQ(ask(m, {3, 0x00, 0x0A, 0x00, 0x01}).status, RegisterStatus::IllegalDataAddress);
  EXPECT_EQ(ask(m, {6, 0x04, 0x0A, 0x00, 0x01}).status, RegisterStatus::IllegalDataAddress);
  EXPECT_EQ(m.writes, 0);
}

TEST(ModbusPdu, WrongQuantityOrLengthIsIllegalDataValue) {
  PlainMap m;
  EXPECT_EQ(ask(m, {3, 0x04, 0x00, 0x00, 0x00}).status, RegisterStatus::IllegalDataValue); // 0 registers
  EXPECT_EQ(ask(m, {4, 0x00, 0x00, 0x00, 0x7E}).status, RegisterStatus::IllegalDataValue); // 126
  EXPECT_EQ(ask(m, {16, 0x04, 0x00, 0x00, 0x02, 2, 0, 1}).status, RegisterStatus::IllegalDataValue); // bytes
  EXPECT_EQ(ask(m, {3, 0x04, 0x00}).status, RegisterStatus::IllegalDataValue);             // truncated
  EXPECT_EQ(ask(m, {5, 0x40, 0x00, 0x12, 0x34}).status, RegisterStatus::IllegalDataValue); // coil value
  EXPECT_EQ(m.writes, 0);
}

} // namespace
} // namespace hilrig::drivers::modbus
