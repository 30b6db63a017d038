#pragma once
// A host programming the ANS1 over any RegisterMap link (a ModbusClient on RTU or TCP) the way
// a PLC does: command words at holding registers 1024 + k, status words at input registers k,
// and the Transmit/Acknowledge handshake (docs/spec/ans1.md §5.1, manual L1705, L2296). Waiting
// for the device is bounded polling of status word 0, never a sleep.
#include <gtest/gtest.h>

#include <cstdint>
#include <initializer_list>
#include <span>
#include <utility>

#include "core/register_map.hpp"
#include "models/ans1/command_block.hpp"
#include "models/ans1/host_interface.hpp"

namespace hilrig::test {

using models::ans1::HostWords;

inline constexpr std::uint16_t kTransmit = 0x8000;    // command word 0 bit 15
inline constexpr std::uint16_t kAcknowledge = 0x8000; // status word 0 bit 15
// Reads of status word 0 before a handshake step is declared lost. Each read is a full link
// round trip, far longer than the 10 us scan the device needs to answer.
inline constexpr int kMaxPolls = 2000;

// Command word 0 from the block number and the listed bits, then (word, value) pairs.
inline HostWords command_block(unsigned number, std::initializer_list<int> bits,
                               std::initializer_list<std::pair<int, int>> words = {}) {
  HostWords w{};
  unsigned w0 = number & 0xFU;
  for (int b : bits) w0 |= 1U << b;
  w[0] = static_cast<std::uint16_t>(w0);
  for (const auto& [k, v] : words) w[static_cast<std::size_t>(k)] = static_cast<std::uint16_t>(v);
  return w;
}

class Ans1LinkHost {
public:
  explicit Ans1LinkHost(RegisterMap& link) : link_(link) {}

  HostWords status() {
    HostWords s{};
    EXPECT_EQ(link_.read_input_registers(models::ans1::kModbusStatusBase, s), RegisterStatus::Ok);
    return s;
  }

  // One full handshake; returns the status words read while Acknowledge is set.
  HostWords transact(HostWords words) {
    words[0] = static_cast<std::uint16_t>(words[0] & ~kTransmit);
    EXPECT_EQ(write(0, words), RegisterStatus::Ok);
    const std::array<std::uint16_t, 1> t{static_cast<std::uint16_t>(words[0] | kTransmit)};
    EXPECT_EQ(write(0, t), RegisterStatus::Ok);
    HostWords s = wait_ack(true);
    const std::array<std::uint16_t, 1> clear{words[0]};
    EXPECT_EQ(write(0, clear), RegisterStatus::Ok);
    wait_ack(false);
    return s;
  }
  // CB1 (spec §5.3, L1723-L1789): select a data attribute block, output and input, and read it.
  HostWords select(int attribute, int output = 1, int input = 1) {
    return transact(command_block(1, {8}, {{1, attribute}, {2, output}, {3, input}}));
  }

private:
  RegisterStatus write(int word, std::span<const std::uint16_t> values) {
    return link_.write_holding_registers(static_cast<std::uint16_t>(models::ans1::kModbusCommandBase + word),
                                         values);
  }
  HostWords wait_ack(bool set) {
    for (int i = 0; i < kMaxPolls; ++i) {
      const HostWords s = status();
      if (((s[0] & kAcknowledge) != 0) == set) {
        return s;
      }
    }
    ADD_FAILURE() << "Acknowledge did not become " << set << " within " << kMaxPolls << " reads";
    return {};
  }

  RegisterMap& link_;
};

} // namespace hilrig::test
