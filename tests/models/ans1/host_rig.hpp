#pragma once
// A host on the ANS1's 20 command and 20 status words, for the host-interface tests: it writes
// command blocks with the manual's handshake (L1705, L2296) and reads status words, exactly as
// a PLC or the Modbus host link would. The device is the real virtual ANS1 on a scheduler; its
// own HostInterface (Ans1::host()) serves the words at every device scan.
#include <cstdint>
#include <initializer_list>
#include <utility>

#include <gtest/gtest.h>

#include "core/scheduler.hpp"
#include "models/ans1/ans1.hpp"
#include "models/ans1/host_interface.hpp"

namespace hilrig::models::ans1::test {

// Builds a command block: word 0 from the block number and the listed bits, then (word, value)
// pairs. Transmit is left to the handshake.
inline HostWords block(unsigned number, std::initializer_list<int> bits_set,
                       std::initializer_list<std::pair<int, int>> words = {}) {
  HostWords w{};
  unsigned w0 = number & 0xFU;
  for (int b : bits_set) w0 |= 1U << b;
  w[0] = static_cast<std::uint16_t>(w0);
  for (const auto& [k, v] : words) w[static_cast<std::size_t>(k)] = static_cast<std::uint16_t>(v);
  return w;
}

struct HostRig {
  static constexpr int kScansToAcknowledge = 2; // executing scan, responding scan
  Scheduler scheduler;
  Ans1 device;
  HostInterface& host;

  explicit HostRig(Variant variant = Variant::Correct)
      : device(scheduler, Params{}, variant), host(device.host()) {}

  // Lets the device run one scan (the host interface acts at the end of each scan).
  void step() { scheduler.run_until(scheduler.now() + device.scan_period()); }

  // One full handshake; returns the status words read while Acknowledge is set.
  HostWords transact(HostWords words) {
    words[0] = static_cast<std::uint16_t>(words[0] & ~kTransmitBit);
    host.write_block(words);
    step();
    EXPECT_EQ(host.read(0) & kAcknowledgeBit, 0) << "Ack before Transmit";
    host.write(0, static_cast<std::uint16_t>(words[0] | kTransmitBit));
    // Polled as a host does: one scan executes the block, the next responds with Acknowledge.
    for (int scan = 0; scan < kScansToAcknowledge && (host.read(0) & kAcknowledgeBit) == 0; ++scan) step();
    const HostWords status = host.status();
    EXPECT_NE(status[0] & kAcknowledgeBit, 0) << "no Ack after Transmit";
    host.write(0, words[0]);
    step();
    EXPECT_EQ(host.read(0) & kAcknowledgeBit, 0) << "Ack stays after Transmit cleared";
    return status;
  }
  // Sends a block and returns the error code the status word shows.
  ErrorCode send(const HostWords& words) { return error_from_status(transact(words)[0]); }
  // CB1: select a data attribute block (and output / input point) and read it.
  HostWords select(int attribute, int output = 1, int input = 1) {
    return transact(block(1, {8}, {{1, attribute}, {2, output}, {3, input}}));
  }
  // Runs the device to the ms-th next whole millisecond of virtual time, so that what a test
  // changes between calls is seen from the next 1 ms monitor tick on.
  void run_ms(std::int64_t ms) {
    const std::int64_t now_ms = scheduler.now() / milliseconds(1);
    scheduler.run_until(milliseconds(now_ms + ms));
  }
  // Slave mode takes the position straight from set_slave_position(): the host tests need
  // exact positions, not a resolver.
  void use_slave_position() { EXPECT_EQ(send(block(2, {7}, {{1, 0x04}})), ErrorCode::None); }
};

} // namespace hilrig::models::ans1::test
