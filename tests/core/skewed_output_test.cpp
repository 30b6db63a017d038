// An output driver whose turn-off and turn-on delays differ: every ON pulse reaches the pin
// longer by the skew (shorter for a negative one), every gap shorter by it, and a pulse or gap
// narrower than the skew never reaches the pin.

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "core/scheduler.hpp"
#include "core/skewed_output.hpp"

namespace hilrig {
namespace {

using namespace hilrig::literals;

// The pin: every level it is set to, with the time.
class RecordingPin final : public LineOutput {
public:
  explicit RecordingPin(Scheduler& s) : s_(s) {}
  void set(Level level) override {
    if (level != level_) edges.push_back(Edge{s_.now(), level});
    level_ = level;
  }
  [[nodiscard]] Level driven() const override { return level_; }
  std::vector<Edge> edges;

private:
  Scheduler& s_;
  Level level_ = Level::Low;
};

// Commands `level` on `out` at each time, then runs the scheduler to the end.
std::vector<Edge> play(Nanos skew, const std::vector<Edge>& commands, Level on = Level::High) {
  Scheduler s;
  RecordingPin pin(s);
  if (on == Level::Low) pin.set(Level::High); // off
  pin.edges.clear();
  SkewedOutput out(s, pin, on, skew);
  for (const Edge& c : commands) s.at(c.time, [&out, level = c.level] { out.set(level); });
  s.run_until_idle();
  return pin.edges;
}

TEST(SkewedOutput, NoSkewPassesEveryChangeAtOnce) {
  const std::vector<Edge> cmd{{10_us, Level::High}, {20_us, Level::Low}, {21_us, Level::High}};
  EXPECT_EQ(play(Nanos{0}, cmd), cmd);
}

TEST(SkewedOutput, ASlowTurnOffStretchesThePulseByTheSkew) {
  const auto pin = play(3_us, {{10_us, Level::High}, {20_us, Level::Low}});
  EXPECT_EQ(pin, (std::vector<Edge>{{10_us, Level::High}, {23_us, Level::Low}}));
}

TEST(SkewedOutput, ASlowTurnOnShortensThePulseByTheSkew) {
  const auto pin = play(Nanos{-3'000}, {{10_us, Level::High}, {20_us, Level::Low}});
  EXPECT_EQ(pin, (std::vector<Edge>{{13_us, Level::High}, {20_us, Level::Low}}));
}

// An output on while its pin is low (a sinking output wired active low): "on" is the low level.
TEST(SkewedOutput, TheOnLevelMayBeLow) {
  const auto pin = play(3_us, {{10_us, Level::Low}, {20_us, Level::High}}, Level::Low);
  EXPECT_EQ(pin, (std::vector<Edge>{{10_us, Level::Low}, {23_us, Level::High}}));
}

TEST(SkewedOutput, AGapNarrowerThanTheSkewNeverReachesThePin) {
  const auto pin =
      play(5_us, {{0_us, Level::High}, {10_us, Level::Low}, {15_us, Level::High}, {30_us, Level::Low}});
  // The turn-off at 10 would complete at 15, when the output turns on again: it never does.
  EXPECT_EQ(pin, (std::vector<Edge>{{0_us, Level::High}, {35_us, Level::Low}}));
}

TEST(SkewedOutput, APulseNarrowerThanANegativeSkewNeverReachesThePin) {
  const auto pin = play(Nanos{-5'000}, {{10_us, Level::High}, {15_us, Level::Low}});
  EXPECT_TRUE(pin.empty());
}

// Property: for random pulse trains whose pulses and gaps are all wider than |skew|, the pin
// carries every pulse, each (skew) longer and each gap (skew) shorter, the rising edges where
// the board commanded them (skew >= 0) or skew later (skew < 0).
TEST(SkewedOutput, EveryPulseIsTheCommandedWidthPlusTheSkew) {
  std::mt19937_64 rng(21);
  for (int trial = 0; trial < 200; ++trial) {
    const Nanos skew{std::uniform_int_distribution<std::int64_t>(-50'000, 50'000)(rng)};
    const std::int64_t room = std::abs(skew.count()) + 1;
    std::vector<Edge> cmd;
    Nanos t{1'000};
    Level level = Level::High;
    for (int k = 0; k < 20; ++k) {
      cmd.push_back(Edge{t, level});
      t += Nanos{room + std::uniform_int_distribution<std::int64_t>(0, 100'000)(rng)};
      level = !level;
    }
    const auto pin = play(skew, cmd);
    ASSERT_EQ(pin.size(), cmd.size()) << "skew " << skew.count();
    for (std::size_t i = 0; i < cmd.size(); ++i) {
      const bool on = cmd[i].level == Level::High;
      const Nanos late = on ? (skew < Nanos{0} ? -skew : Nanos{0}) : (skew > Nanos{0} ? skew : Nanos{0});
      EXPECT_EQ(pin[i].time, cmd[i].time + late) << "skew " << skew.count() << " edge " << i;
      EXPECT_EQ(pin[i].level, cmd[i].level);
    }
    for (std::size_t i = 0; i + 1 < cmd.size(); i += 2)
      EXPECT_EQ(pin[i + 1].time - pin[i].time, cmd[i + 1].time - cmd[i].time + skew);
  }
}

} // namespace
} // namespace hilrig
