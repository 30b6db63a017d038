// The resolver angle stream on its own thread (rig/hardware/resolver_stream.hpp): it sends the
// frame of every period boundary, the same frames the virtual rig's AngleStreamer sends, reads
// the controller before each, and allocates nothing while it plays (the RT loop's proof,
// tests/rt/rt_loop_test.cpp, with the same allocation counter).

#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <string>

#include "core/clock.hpp"
#include "core/scheduler.hpp"
#include "models/resolver_emulator/angle_streamer.hpp"
#include "rig/hardware/resolver_stream.hpp"
#include "tests/rt/allocation_counter.hpp"

namespace hilrig::hardware {
namespace {

// Keeps what it is given in fixed storage: a CAN interface that itself never allocates.
class RecordingCan final : public ResolverCan {
public:
  std::string send(const CanFrame& frame) override {
    if (sent < frames.size()) frames[sent] = frame;
    ++sent;
    return {};
  }
  std::string check() override {
    ++checks;
    return {};
  }
  const std::string& bus() const override { return name_; }
  CanOverruns overruns() const override { return {}; }
  std::array<CanFrame, 64> frames{};
  std::size_t sent = 0;
  std::size_t checks = 0;

private:
  std::string name_ = "can9";
};

// Records what an AngleStreamer sends on the virtual bus.
class VirtualPort final : public CanPort {
public:
  void send(const CanFrame& frame) override { frames.push_back(frame); }
  void on_receive(CanReceiveHandler /*handler*/) override {}
  std::vector<CanFrame> frames;
};

signals::MotionProfile ramp() {
  signals::MotionProfile p(100.0);
  p.accelerate(20'000.0, milliseconds(10)).cruise(milliseconds(20));
  return p;
}

models::resolver_emulator::AngleStreamParams params() {
  models::resolver_emulator::AngleStreamParams p;
  p.period = milliseconds(1);
  p.units_per_turn = 4096.0;
  return p;
}

TEST(ResolverStream, PlaysEveryPeriodWithoutAllocating) {
  const signals::MotionProfile profile = ramp();
  RecordingCan can;
  rig::SpscRing<SentFrame> ring(64);
  std::atomic<bool> stop{false};
  ResolverStreamStats stats;
  const Nanos end = milliseconds(20);
  const Nanos start = MonotonicClock{}.now();

  hilrig::test::arm_allocation_counter();
  const std::string why = play_resolver_stream(profile, params(), end, can, start, ring, stop, stats);
  const std::uint64_t allocations = hilrig::test::disarm_allocation_counter();

  EXPECT_EQ(allocations, 0U);
  EXPECT_EQ(why, "");
  // Boundaries 0, 1, ... 20 ms: each one sent or, when the thread woke a period late, skipped.
  EXPECT_EQ(static_cast<std::int64_t>(stats.sent) + stats.stale, 21);
  EXPECT_EQ(stats.sent, can.sent);
  EXPECT_EQ(stats.ring_overflows, 0U);
  EXPECT_GE(can.checks, can.sent + 1); // before each frame, and once at the end
  SentFrame f{};
  std::size_t n = 0;
  Nanos last{-1};
  while (ring.pop(f)) {
    EXPECT_EQ(f.frame, can.frames[n]) << n;
    EXPECT_GT(f.at, last);
    last = f.at;
    ++n;
  }
  EXPECT_EQ(n, stats.sent);
}

TEST(ResolverStream, BuildsTheFramesTheVirtualRigsStreamerSends) {
  // The stream's frame at boundary k, sequence k, is the AngleStreamer's k-th frame.
  const signals::MotionProfile profile = ramp();
  Scheduler sched;
  VirtualPort port;
  models::resolver_emulator::AngleStreamer streamer(sched, port, profile, params());
  streamer.start(Nanos{0});
  sched.run_until(milliseconds(20));
  ASSERT_EQ(port.frames.size(), 21U);
  for (std::size_t k = 0; k < port.frames.size(); ++k)
    EXPECT_EQ(models::resolver_emulator::angle_frame(profile, params(),
                                                     milliseconds(static_cast<std::int64_t>(k)), k),
              port.frames[k])
        << k;
}

TEST(ResolverStream, EveryBoundaryMoreThanAPeriodLateIsSkippedAsStale) {
  // Started a second in the past, every boundary up to 5 ms is over a period late.
  RecordingCan can;
  rig::SpscRing<SentFrame> ring(64);
  std::atomic<bool> stop{false};
  ResolverStreamStats stats;
  const std::string why = play_resolver_stream(ramp(), params(), milliseconds(5), can,
                                               MonotonicClock{}.now() - seconds(1), ring, stop, stats);
  EXPECT_EQ(why, "");
  EXPECT_EQ(can.sent, 0U);
  EXPECT_EQ(stats.stale, 6);
}

TEST(ResolverStream, AControllerFaultStopsTheStreamAtOnce) {
  class BusOff final : public ResolverCan {
  public:
    std::string send(const CanFrame& /*frame*/) override { return {}; }
    std::string check() override { return "CAN can9: bus-off"; }
    const std::string& bus() const override { return name_; }
    CanOverruns overruns() const override { return {}; }

  private:
    std::string name_ = "can9";
  } can;
  rig::SpscRing<SentFrame> ring(64);
  std::atomic<bool> stop{false};
  ResolverStreamStats stats;
  EXPECT_EQ(play_resolver_stream(ramp(), params(), milliseconds(20), can, MonotonicClock{}.now(), ring, stop,
                                 stats),
            "CAN can9: bus-off");
  EXPECT_EQ(stats.sent, 0U);
}

} // namespace
} // namespace hilrig::hardware
