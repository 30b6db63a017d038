// Soak: 50 polite libmodbus clients × 1,000 reads each against one served SMD23E while a
// flooder sends and never reads and idle holders fill every connection slot first. Every
// polite request must be answered with the right value, the flooder closed at its output
// bound, exactly the longest-idle holders replaced, and the server's bookkeeping (open
// connections, buffered reply bytes) back at zero once everyone has left — a count, not
// an RSS threshold. Loopback only, a free port, loops bounded by their counts.
#include <gtest/gtest.h>
#include <modbus/modbus.h>

#include <array>
#include <atomic>
#include <latch>
#include <memory>
#include <thread>
#include <vector>

#include "tests/modbus/raw_tcp_client.hpp"
#include "tests/modbus/serve_thread.hpp"

namespace hilrig::test {
namespace {

constexpr int kPolite = 50;
constexpr int kRequests = 1'000;
constexpr std::size_t kLimit = 64;

// One polite client: connects, reads input registers 0..9 kRequests times, counts the
// answers whose status word 1 is the unconfigured SMD23E's 0x6408. After its first answer it
// waits until every polite client has one, so all are in before any leaves (and the count
// of holders replaced is exact).
int polite_client(std::uint16_t port, std::latch& all_in) {
  modbus_t* c = modbus_new_tcp("127.0.0.1", port);
  if (c == nullptr || modbus_connect(c) != 0) {
    modbus_free(c);
    all_in.count_down(); // never in: the others must not wait for it
    return 0;
  }
  modbus_set_response_timeout(c, 10, 0); // a failure bound, not a measurement
  int answered = 0;
  std::array<std::uint16_t, 10> in{};
  for (int i = 0; i < kRequests; ++i) {
    in[0] = 0;
    if (modbus_read_input_registers(c, 0, 10, in.data()) == 10 && in[0] == 0x6408) {
      ++answered;
    }
    if (i == 0) {
      all_in.arrive_and_wait();
    }
  }
  modbus_close(c);
  modbus_free(c);
  return answered;
}

TEST(ModbusTcpSoak, FiftyClientsAreAllAnsweredBesideAFlooderAndIdleHolders) {
  cli::ServeOptions o = smd23e_on_tcp();
  o.tcp_limits.max_connections = kLimit;
  o.tcp_limits.max_output_bytes = 4096;
  // The idle timeout is tested in tcp_limits_test; here it is only a failure bound, far above
  // what the soak takes even under ASan on a busy machine (the holders are idle throughout).
  o.tcp_limits.idle_timeout = seconds(600);
  ServeThread server(o);
  const auto& stats = *server.endpoint().tcp_stats;

  // Idle holders take every slot before anyone else arrives.
  std::vector<std::unique_ptr<RawTcpClient>> holders;
  for (std::size_t i = 0; i < kLimit; ++i) {
    holders.push_back(std::make_unique<RawTcpClient>(server.port()));
    wait_for_open(stats, i + 1);
  }

  std::atomic<int> flooder_bursts{0};
  std::latch flooder_in(1);
  std::thread flooder([&] {
    RawTcpClient f(server.port());
    // One answered request proves it is in; from then on it sends and never reads.
    const bool in = f.send(mbap_frame(0, 0, 1, {4, 0, 0, 0, 1})) && f.receive(11).size() == 11;
    flooder_in.count_down();
    if (!in) {
      return;
    }
    std::vector<std::uint8_t> burst;
    for (int i = 0; i < 100; ++i) {
      const auto frame = mbap_frame(static_cast<std::uint16_t>(i), 0, 1, {4, 0, 0, 0, 10});
      burst.insert(burst.end(), frame.begin(), frame.end());
    }
    while (flooder_bursts.load() < 100'000 && f.send(burst)) {
      ++flooder_bursts;
    }
  });
  flooder_in.wait();
  std::atomic<int> answered{0};
  std::latch all_in(kPolite);
  std::vector<std::thread> polite;
  for (int i = 0; i < kPolite; ++i) {
    polite.emplace_back([&] { answered += polite_client(server.port(), all_in); });
  }
  for (auto& t : polite) {
    t.join();
  }
  flooder.join();

  EXPECT_EQ(answered.load(), kPolite * kRequests);
  EXPECT_LT(flooder_bursts.load(), 100'000);
  EXPECT_EQ(stats.overflowed.load(), 1U)
      << flooder_bursts.load() << " bursts sent, timed out " << stats.timed_out.load();
  EXPECT_EQ(stats.replaced.load(), static_cast<std::uint64_t>(kPolite + 1)); // one holder per newcomer
  EXPECT_EQ(stats.timed_out.load(), 0U);
  EXPECT_GE(stats.requests.load(), static_cast<std::uint64_t>(kPolite * kRequests));

  holders.clear();
  wait_for_open(stats, 0);
  EXPECT_EQ(stats.buffered_bytes.load(), 0U);
  EXPECT_EQ(stats.connections.load(), kLimit + kPolite + 1);
}

} // namespace
} // namespace hilrig::test
