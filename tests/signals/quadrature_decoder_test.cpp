// QuadratureDecoder: X1/X2/X4 counting over whole cycles both ways, illegal transitions
// and the index latch. Expected counts follow the state table 00 -> 10 -> 11 -> 01 -> 00
// (A leading B is forward): per cycle X4 counts 4, X2 counts A's 2 edges, X1 counts 1.

#include "signals/quadrature_decoder.hpp"

#include <gtest/gtest.h>

#include <array>
#include <utility>

using namespace hilrig::signals;

namespace {
constexpr std::array<std::pair<bool, bool>, 4> kForward{
    {{true, false}, {true, true}, {false, true}, {false, false}}};
constexpr std::array<std::pair<bool, bool>, 4> kBackward{
    {{false, true}, {true, true}, {true, false}, {false, false}}};

std::int64_t run_cycles(QuadratureDecoder& d, int cycles, bool forward) {
  for (int c = 0; c < cycles; ++c)
    for (int i = 0; i < 4; ++i) {
      // Backward walks the table the other way: 00 -> 01 -> 11 -> 10 -> 00.
      const auto [a, b] = (forward ? kForward : kBackward)[static_cast<std::size_t>(i)];
      d.update(a, b);
    }
  return d.count();
}
} // namespace

TEST(QuadratureDecoder, X4CountsEveryEdgeBothWays) {
  QuadratureDecoder d(CountMode::X4);
  EXPECT_EQ(d.update(true, false), 1);
  EXPECT_EQ(d.update(true, true), 1);
  EXPECT_EQ(d.update(true, true), 0); // no change, no count
  EXPECT_EQ(d.update(true, false), -1);
  EXPECT_EQ(d.count(), 1);
  QuadratureDecoder e(CountMode::X4);
  EXPECT_EQ(run_cycles(e, 3, true), 12);
  EXPECT_EQ(run_cycles(e, 5, false), -8);
}

TEST(QuadratureDecoder, X2CountsTheEdgesOfA) {
  QuadratureDecoder d(CountMode::X2);
  EXPECT_EQ(d.update(true, false), 1);  // A rises
  EXPECT_EQ(d.update(true, true), 0);   // B rises
  EXPECT_EQ(d.update(false, true), 1);  // A falls
  EXPECT_EQ(d.update(false, false), 0); // B falls
  EXPECT_EQ(run_cycles(d, 2, true), 6);
  EXPECT_EQ(run_cycles(d, 3, false), 0);
}

TEST(QuadratureDecoder, X1CountsOncePerCycle) {
  QuadratureDecoder d(CountMode::X1);
  EXPECT_EQ(run_cycles(d, 7, true), 7);
  EXPECT_EQ(run_cycles(d, 10, false), -3);
  // A wiggling on one edge (forward then back) nets nothing.
  QuadratureDecoder w(CountMode::X1);
  EXPECT_EQ(w.update(true, false), 1);
  EXPECT_EQ(w.update(false, false), -1);
  EXPECT_EQ(w.count(), 0);
}

TEST(QuadratureDecoder, BothChannelsChangingIsIllegalAndNotCounted) {
  QuadratureDecoder d(CountMode::X4);
  EXPECT_EQ(d.update(true, true), 0);   // 00 -> 11
  EXPECT_EQ(d.update(false, false), 0); // 11 -> 00
  EXPECT_EQ(d.illegal_transitions(), 2U);
  EXPECT_EQ(d.count(), 0);
  EXPECT_EQ(d.update(true, false), 1); // decoding resumes from the new state
}

TEST(QuadratureDecoder, APulsesAloneNetZero) {
  // The 4501 counts nothing when only A pulses (spec 2.1): X4 gives +1/-1 alternately.
  QuadratureDecoder d(CountMode::X4);
  for (int i = 0; i < 10; ++i) {
    d.update(true, false);
    d.update(false, false);
  }
  EXPECT_EQ(d.count(), 0);
  EXPECT_EQ(d.illegal_transitions(), 0U);
}

TEST(QuadratureDecoder, IndexLatchesAndOptionallyResets) {
  QuadratureDecoder d(CountMode::X4);
  run_cycles(d, 2, true);
  d.index(true);
  EXPECT_EQ(d.index_pulses(), 1U);
  EXPECT_EQ(d.index_count(), 8);
  EXPECT_EQ(d.count(), 8);
  d.index(true); // still high: not a new pulse
  d.index(false);
  EXPECT_EQ(d.index_pulses(), 1U);

  QuadratureDecoder r(CountMode::X4);
  r.reset_on_index = true;
  run_cycles(r, 3, true);
  r.index(true);
  EXPECT_EQ(r.index_count(), 12);
  EXPECT_EQ(r.count(), 0);
  run_cycles(r, 1, true);
  EXPECT_EQ(r.count(), 4);
}
