// Property tests of the host interface with seeded random command blocks: a rejected block
// never changes the device's setup or forces (§5.6 [MODEL]), every block is acknowledged, and
// a random run reaches every error code.
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "host_rig.hpp"

namespace hilrig::models::ans1 {
namespace {

using test::HostRig;

// Word values biased to the edges of the ranges the blocks check.
std::uint16_t pick_value(std::mt19937& rng) {
  static constexpr std::array<std::uint16_t, 12> kEdges{0, 1, 2, 3, 5, 16, 17, 255, 256, 359, 360, 0xFFFF};
  std::uniform_int_distribution<int> kind(0, 3);
  if (kind(rng) == 0) return static_cast<std::uint16_t>(std::uniform_int_distribution<int>(0, 0xFFFF)(rng));
  return kEdges[std::uniform_int_distribution<std::size_t>(0, kEdges.size() - 1)(rng)];
}

HostWords random_block(std::mt19937& rng) {
  HostWords w{};
  std::bernoulli_distribution bit_set(0.25);
  unsigned w0 = static_cast<unsigned>(std::uniform_int_distribution<int>(0, 15)(rng));
  for (int b = 5; b <= 14; ++b) {
    if (bit_set(rng)) w0 |= 1U << b;
  }
  w0 |= kClearErrorsBit; // each block's own result shows in the status word
  w[0] = static_cast<std::uint16_t>(w0);
  for (std::size_t k = 1; k < w.size(); ++k) w[k] = pick_value(rng);
  return w;
}

struct Snapshot {
  Ans1Setup setup;
  std::uint16_t out_enable, out_state, in_enable, in_state;
  bool operator==(const Snapshot&) const = default;
};

Snapshot snapshot(const Ans1& d) {
  return {d.setup(), d.output_force_enable(), d.output_force_state(), d.input_force_enable(),
          d.input_force_state()};
}

TEST(HostProperty, RejectedBlocksChangeNothingAndEveryCodeIsReachable) {
  std::mt19937 rng(20141218); // fixed seed: the manual's date
  HostRig rig;
  std::set<ErrorCode> seen;
  int accepted = 0;
  for (int i = 0; i < 3000; ++i) {
    const HostWords w = random_block(rng);
    const Snapshot before = snapshot(rig.device);
    const HostWords status = rig.transact(w); // checks the handshake (Ack up, then down)
    const ErrorCode code = error_from_status(status[0]);
    seen.insert(code);
    if (code != ErrorCode::None) {
      ASSERT_EQ(snapshot(rig.device), before)
          << "block " << (w[0] & 0xF) << " rejected with " << error_name(code) << " but changed the device";
    } else {
      ++accepted;
    }
  }
  EXPECT_GT(accepted, 100);
  for (ErrorCode c : {ErrorCode::None, ErrorCode::CommandWord, ErrorCode::Parameter, ErrorCode::ReservedBits,
                      ErrorCode::ParameterConflict, ErrorCode::SetpointOverlap}) {
    EXPECT_TRUE(seen.count(c) == 1) << error_name(c) << " never seen";
  }
}

TEST(HostProperty, SetpointPairsRoundTripThroughDataAttribute1) {
  // Random non-overlapping pairs (one per quarter of the cycle) come back word for word.
  std::mt19937 rng(7);
  HostRig rig;
  for (int i = 0; i < 200; ++i) {
    const int output = std::uniform_int_distribution<int>(1, 16)(rng);
    HostWords w{};
    w[0] = 0x3C03; // CB3, apply pairs 1..4
    w[1] = static_cast<std::uint16_t>(output);
    for (int k = 0; k < 4; ++k) {
      const int from = 90 * k + std::uniform_int_distribution<int>(1, 40)(rng);
      const int to = from + std::uniform_int_distribution<int>(1, 40)(rng);
      w[static_cast<std::size_t>(4 * (k + 1))] = static_cast<std::uint16_t>(from);
      w[static_cast<std::size_t>(4 * (k + 1) + 1)] = static_cast<std::uint16_t>(to);
    }
    ASSERT_EQ(rig.send(w), ErrorCode::None);
    const HostWords da1 = rig.select(1, output);
    for (int k = 0; k < 4; ++k) {
      EXPECT_EQ(da1[static_cast<std::size_t>(2 + 4 * k)], w[static_cast<std::size_t>(4 * (k + 1))]);
      EXPECT_EQ(da1[static_cast<std::size_t>(3 + 4 * k)], w[static_cast<std::size_t>(4 * (k + 1) + 1)]);
    }
  }
}

} // namespace
} // namespace hilrig::models::ans1
