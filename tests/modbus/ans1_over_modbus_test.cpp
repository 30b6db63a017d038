// The virtual ANS1 served in real time by `hilrig serve ans1`, programmed by the rig's own
// Modbus client (drivers/hostlink ModbusClient) through its command words with the
// Transmit/Acknowledge handshake, over Modbus RTU on a pty pair and over Modbus TCP.
// Expected status words come from docs/spec/ans1.md:
//   §5.3 CB3 (lines 705-727; manual L1842-L1898): w1 output, pair k in words 4k..4k+3
//        (From, To, OnStitch, OffStitch), applied by bits 10 (pair 1) .. 13 (pair 4);
//   §5.3 CB1 (line 642; L1723-L1789): bit 8 applies w1 data block, w2 output, w3 input;
//   §5.4 status word 0 (line 926): 15 Ack, 11..8 error code, 4..0 data block number;
//   §5.5 DA1 (line 945; L2345-L2369): w1 output, pairs 1-4 in words 2-5, 6-9, 10-13, 14-17;
//   §5.5 DA0 (line 944; L2317-L2343): w6 CPC 4096, w7 FSC 360 (defaults, spec line 224, L779),
//        w13 module ID 83, w14 product code 39.
#include <gtest/gtest.h>

#include <poll.h>

#include <memory>

#include "drivers/hostlink/modbus_client.hpp"
#include "tests/modbus/ans1_link_host.hpp"
#include "tests/modbus/serve_thread.hpp"

namespace hilrig::test {
namespace {

// Status word 0 without Heartbeat (bit 14, time-driven) and Resolver Fault (bit 12: the
// served ANS1 has no resolver attached): Ack, Hardware Fault, error code, forced, block.
constexpr std::uint16_t kStableStatusBits = 0xAFDF;

std::unique_ptr<hostlink::ModbusClient> rtu_client(const cli::ServeEndpoint& e) {
  hostlink::RtuSettings s;
  s.device = e.serial_path;
  s.format = {19200, 8, Parity::Even, 1}; // the server's default framing
  s.unit = 1;
  return hostlink::ModbusClient::rtu(s);
}

std::unique_ptr<hostlink::ModbusClient> tcp_client(const cli::ServeEndpoint& e) {
  hostlink::TcpSettings s;
  s.port = e.port;
  return hostlink::ModbusClient::tcp(s);
}

// Output 7: pair 1 = 10..20, pair 2 = 100..200 (no stitches, no overlap), then DA1 for
// output 7. Returns the DA1 status words.
HostWords program_setpoints_and_read_back(RegisterMap& link) {
  Ans1LinkHost host(link);
  const HostWords cb3 =
      host.transact(command_block(3, {10, 11}, {{1, 7}, {4, 10}, {5, 20}, {8, 100}, {9, 200}}));
  EXPECT_EQ(cb3[0] & 0x0F00, 0) << "CB3 rejected, error code " << ((cb3[0] >> 8) & 0xF);
  return host.select(1, 7);
}

void expect_da1_for_output7(const HostWords& s) {
  EXPECT_EQ(s[0] & 0x8F1F, 0x8001) << "Ack, no error, data block 1";
  const HostWords expected{0, 7, 10, 20, 0, 0, 100, 200, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  for (std::size_t k = 1; k < expected.size(); ++k) {
    EXPECT_EQ(s[k], expected[k]) << "status word " << k;
  }
}

TEST(Ans1OverModbusRtu, FreshDeviceReportsGlobalSetup) {
  ServeThread server(ans1_on_pty());
  auto client = rtu_client(server.endpoint());
  HostWords s{};
  ASSERT_EQ(client->read_input_registers(0, s), RegisterStatus::Ok);
  EXPECT_EQ(s[0] & 0x001F, 0) << "data block 0 after power-up";
  EXPECT_EQ(s[6], 4096);
  EXPECT_EQ(s[7], 360);
  EXPECT_EQ(s[13], 83);
  EXPECT_EQ(s[14], 39);
}

TEST(Ans1OverModbusRtu, ProgramsSetpointPairsAndReadsThemBack) {
  ServeThread server(ans1_on_pty());
  auto client = rtu_client(server.endpoint());
  expect_da1_for_output7(program_setpoints_and_read_back(*client));
  // The command words read back as written (FC 3 on 1024..), Transmit cleared by the handshake.
  std::array<std::uint16_t, 2> cmd{};
  ASSERT_EQ(client->read_holding_registers(1024, cmd), RegisterStatus::Ok);
  EXPECT_EQ(cmd[0], 0x0101); // CB1 with bit 8
  EXPECT_EQ(cmd[1], 1);      // data block 1
}

TEST(Ans1OverModbusRtu, OverlappingPairsAreRejectedWithSetpointOverlap) {
  // §5.6 (spec line 970, L2309): overlapping pairs are Setpoint Overlap Error 1100; a rejected
  // block applies nothing (line 985).
  ServeThread server(ans1_on_pty());
  auto client = rtu_client(server.endpoint());
  Ans1LinkHost host(*client);
  const HostWords s = host.transact(command_block(3, {10, 11}, {{1, 7}, {4, 10}, {5, 20}, {8, 15}, {9, 30}}));
  EXPECT_EQ((s[0] >> 8) & 0xF, 0b1100);
  const HostWords da1 = host.select(1, 7);
  EXPECT_EQ(da1[2], 0);
  EXPECT_EQ(da1[3], 0);
}

TEST(Ans1OverModbusRtu, ModelRunsInRealTimeBetweenRequests) {
  // Heartbeat (status word 0 bit 14, spec §5.4 line 926) toggles every 500 ms of device time:
  // it only changes if the server advances the model with the clock. Bounded: 5,000 reads
  // with a 1 ms pause between them.
  ServeThread server(ans1_on_pty());
  auto client = rtu_client(server.endpoint());
  std::array<std::uint16_t, 1> w{};
  ASSERT_EQ(client->read_input_registers(0, w), RegisterStatus::Ok);
  const std::uint16_t first = w[0] & 0x4000;
  bool toggled = false;
  for (int i = 0; i < 5000 && !toggled; ++i) {
    ::poll(nullptr, 0, 1);
    ASSERT_EQ(client->read_input_registers(0, w), RegisterStatus::Ok);
    toggled = (w[0] & 0x4000) != first;
  }
  EXPECT_TRUE(toggled);
}

TEST(Ans1OverModbus, TcpGivesTheSameStatusWordsAsRtu) {
  HostWords over_rtu{};
  HostWords over_tcp{};
  {
    ServeThread server(ans1_on_pty());
    auto client = rtu_client(server.endpoint());
    over_rtu = program_setpoints_and_read_back(*client);
  }
  {
    ServeThread server(ans1_on_tcp());
    auto client = tcp_client(server.endpoint());
    over_tcp = program_setpoints_and_read_back(*client);
  }
  expect_da1_for_output7(over_tcp);
  EXPECT_EQ(over_tcp[0] & kStableStatusBits, over_rtu[0] & kStableStatusBits);
  for (std::size_t k = 1; k < over_rtu.size(); ++k) {
    EXPECT_EQ(over_tcp[k], over_rtu[k]) << "status word " << k;
  }
}

} // namespace
} // namespace hilrig::test
