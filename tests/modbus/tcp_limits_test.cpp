// `hilrig serve`'s Modbus TCP server against hostile clients, over real loopback sockets on a
// free port: a frame that is not Modbus (protocol id != 0) is discarded, a truncated PDU gets
// exception 03 and the connection stays, an impossible length closes only that connection,
// silent connections time out, a newcomer at the connection limit replaces the connection
// idle the longest, and a client that sends and never reads is closed at the output bound.
// No sleeps: the server's own timeouts are set small and the tests wait on its events.
// The served device is the unconfigured SMD23E: input word 0 (status word 1) reads 0x6408.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "tests/modbus/raw_tcp_client.hpp"
#include "tests/modbus/serve_thread.hpp"

namespace hilrig::test {
namespace {

using Bytes = std::vector<std::uint8_t>;

const Bytes kReadWord0{4, 0, 0, 0, 1}; // FC 4, input register 0, count 1

// The reply to kReadWord0 with this transaction id: FC 4, 2 bytes, 0x6408.
Bytes word0_reply(std::uint16_t transaction) { return mbap_frame(transaction, 0, 1, {4, 2, 0x64, 0x08}); }

cli::ServeOptions smd23e_with(drivers::modbus::TcpLimits limits) {
  cli::ServeOptions o = smd23e_on_tcp();
  o.tcp_limits = limits;
  return o;
}

TEST(ModbusTcpLimits, ProtocolIdOtherThanZeroIsDiscardedAndTheNextFrameAnswered) {
  ServeThread server(smd23e_on_tcp());
  RawTcpClient c(server.port());
  ASSERT_TRUE(c.connected());
  Bytes both = mbap_frame(1, 0x0001, 1, kReadWord0);
  const Bytes good = mbap_frame(2, 0, 1, kReadWord0);
  both.insert(both.end(), good.begin(), good.end());
  ASSERT_TRUE(c.send(both));
  EXPECT_EQ(c.receive(11), word0_reply(2)); // the first reply is to transaction 2: 1 was dropped
  EXPECT_EQ(server.endpoint().tcp_stats->discarded.load(), 1U);
}

TEST(ModbusTcpLimits, TruncatedPduGetsException3AndTheConnectionStays) {
  ServeThread server(smd23e_on_tcp());
  RawTcpClient c(server.port());
  ASSERT_TRUE(c.connected());
  for (std::size_t keep = 1; keep < kReadWord0.size(); ++keep) {
    const Bytes pdu(kReadWord0.begin(), kReadWord0.begin() + static_cast<std::ptrdiff_t>(keep));
    ASSERT_TRUE(c.send(mbap_frame(7, 0, 1, pdu)));
    EXPECT_EQ(c.receive(9), mbap_frame(7, 0, 1, {0x84, 0x03})) << keep << " PDU bytes";
  }
  ASSERT_TRUE(c.send(mbap_frame(8, 0, 1, kReadWord0)));
  EXPECT_EQ(c.receive(11), word0_reply(8));
}

TEST(ModbusTcpLimits, ImpossibleLengthClosesOnlyThatConnection) {
  ServeThread server(smd23e_on_tcp());
  RawTcpClient other(server.port());
  RawTcpClient c(server.port());
  ASSERT_TRUE(c.connected() && other.connected());
  ASSERT_TRUE(c.send(mbap_frame(1, 0, 1, kReadWord0, 255))); // a 254-byte PDU: over 253
  EXPECT_TRUE(c.closed_by_server());
  ASSERT_TRUE(other.send(mbap_frame(3, 0, 1, kReadWord0)));
  EXPECT_EQ(other.receive(11), word0_reply(3));
  EXPECT_EQ(server.endpoint().tcp_stats->bad_frames.load(), 1U);
}

// The requests that came before an impossible length in the same read are answered, and only
// then is the connection closed (docs/serve.md): their replies were lost with it before.
TEST(ModbusTcpLimits, RequestsBeforeAnImpossibleLengthAreAnsweredThenTheConnectionCloses) {
  ServeThread server(smd23e_on_tcp());
  const auto& stats = *server.endpoint().tcp_stats;
  RawTcpClient c(server.port());
  ASSERT_TRUE(c.connected());
  Bytes stream = mbap_frame(6, 0, 1, kReadWord0);
  const Bytes second = mbap_frame(7, 0, 1, kReadWord0);
  const Bytes bad = mbap_frame(8, 0, 1, {4}, 0x300); // a 767-byte PDU: over 253
  stream.insert(stream.end(), second.begin(), second.end());
  stream.insert(stream.end(), bad.begin(), bad.end());
  ASSERT_TRUE(c.send(stream)); // one send: the server reads all three frames at once
  Bytes replies = word0_reply(6);
  const Bytes reply7 = word0_reply(7);
  replies.insert(replies.end(), reply7.begin(), reply7.end());
  EXPECT_EQ(c.receive(22), replies);
  EXPECT_TRUE(c.closed_by_server());
  EXPECT_EQ(stats.bad_frames.load(), 1U);
  wait_for_open(stats, 0);
  EXPECT_EQ(stats.buffered_bytes.load(), 0U);
}

TEST(ModbusTcpLimits, SilentConnectionIsClosedAfterTheIdleTimeout) {
  ServeThread server(smd23e_with({.max_connections = 3, .idle_timeout = milliseconds(20)}));
  const auto& stats = *server.endpoint().tcp_stats;
  {
    RawTcpClient holders[3]{RawTcpClient(server.port()), RawTcpClient(server.port()),
                            RawTcpClient(server.port())};
    for (auto& h : holders) {
      EXPECT_TRUE(h.closed_by_server());
    }
  }
  EXPECT_EQ(stats.timed_out.load(), 3U);
  wait_for_open(stats, 0);
  RawTcpClient c(server.port());
  ASSERT_TRUE(c.send(mbap_frame(4, 0, 1, kReadWord0)));
  EXPECT_EQ(c.receive(11), word0_reply(4));
}

TEST(ModbusTcpLimits, NewcomerAtTheLimitReplacesTheLongestIdle) {
  // Up to the limit nobody is replaced; one past it, the oldest silent connection goes.
  for (const std::size_t limit : {1U, 2U, 3U, 4U}) {
    ServeThread server(smd23e_with({.max_connections = limit}));
    const auto& stats = *server.endpoint().tcp_stats;
    std::vector<std::unique_ptr<RawTcpClient>> holders;
    for (std::size_t i = 0; i < limit; ++i) {
      holders.push_back(std::make_unique<RawTcpClient>(server.port()));
      wait_for_open(stats, i + 1);
    }
    EXPECT_EQ(stats.replaced.load(), 0U) << limit;
    RawTcpClient newcomer(server.port());
    ASSERT_TRUE(newcomer.send(mbap_frame(5, 0, 1, kReadWord0)));
    EXPECT_EQ(newcomer.receive(11), word0_reply(5)) << limit;
    EXPECT_EQ(stats.replaced.load(), 1U) << limit;
    EXPECT_TRUE(holders.front()->closed_by_server()) << limit;
    for (std::size_t i = 1; i < limit; ++i) { // the younger ones are still served
      ASSERT_TRUE(holders[i]->send(mbap_frame(6, 0, 1, kReadWord0)));
      EXPECT_EQ(holders[i]->receive(11), word0_reply(6)) << limit << " holder " << i;
    }
  }
}

TEST(ModbusTcpLimits, ClientThatNeverReadsIsClosedAtTheOutputBound) {
  ServeThread server(smd23e_with({.max_output_bytes = 4096}));
  const auto& stats = *server.endpoint().tcp_stats;
  auto polite = std::make_unique<RawTcpClient>(server.port());
  RawTcpClient flooder(server.port());
  ASSERT_TRUE(polite->connected() && flooder.connected());
  Bytes burst;
  for (int i = 0; i < 100; ++i) {
    const Bytes f = mbap_frame(static_cast<std::uint16_t>(i), 0, 1, kReadWord0);
    burst.insert(burst.end(), f.begin(), f.end());
  }
  // Bounded: the server closes it long before 100,000 bursts (12 MB of requests).
  int bursts = 0;
  while (bursts < 100'000 && flooder.send(burst)) {
    ++bursts;
  }
  EXPECT_LT(bursts, 100'000);
  EXPECT_EQ(stats.overflowed.load(), 1U) << bursts << " bursts sent, timed out " << stats.timed_out.load();
  ASSERT_TRUE(polite->send(mbap_frame(9, 0, 1, kReadWord0)));
  EXPECT_EQ(polite->receive(11), word0_reply(9))
      << "open " << stats.open.load() << " timed out " << stats.timed_out.load() << " bad "
      << stats.bad_frames.load();
  polite.reset();
  wait_for_open(stats, 0);
  EXPECT_EQ(stats.buffered_bytes.load(), 0U); // nothing held for anyone gone
}

} // namespace
} // namespace hilrig::test
