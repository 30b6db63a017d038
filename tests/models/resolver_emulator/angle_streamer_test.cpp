// The angle streamer's search for a frame whose own transport delay is the delay it was built
// for (AngleStreamer::lead_by_transport) reads the shaft once per delay it tries and finds each
// (delay, code) frame's own delay once. Checked here against the search as documented, written
// out the slow way: every candidate's shaft read, frame built and delay asked again, in the
// documented order (the last frame's delay, then each frame's own delay, three steps for each
// code from the one at or above the shaft up to 15 codes above; then every possible delay for
// each code; the first exact match, else the first nearest miss).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <iostream>
#include <map>
#include <set>
#include <vector>

#include "core/scheduler.hpp"
#include "models/resolver_emulator/angle_streamer.hpp"
#include "signals/resolver_frames.hpp"

namespace hilrig::models::resolver_emulator {
namespace {

using namespace hilrig::literals;

class CapturePort final : public CanPort {
public:
  void send(const CanFrame& frame) override { sent.push_back(frame); }
  void on_receive(CanReceiveHandler handler) override { (void)handler; }
  std::vector<CanFrame> sent;
};

// A shaft under constant acceleration, in counts of 4096 a turn.
ShaftSample shaft_at(Nanos t) {
  const double s = t.seconds();
  return ShaftSample{4096.0 * (0.37 + 13.1 * s + 40.0 * s * s), 4096.0 * (13.1 + 80.0 * s)};
}

// A transport that hangs on the frame's bytes, as the bus's does on its stuff bits: one of
// `spread` values 2 us apart from 100 us (+ 1 us when `odd` says so for that frame: then no
// possible delay, which are whole 2 us steps, matches it; the delay tried next may), and up to
// `jitter` - 1 ns more (then few frames match the delay they were built for).
struct FakeTransport {
  std::uint32_t spread;
  std::uint32_t odd_every;  // 0: never odd
  std::uint32_t jitter = 1; // and 0 .. jitter - 1 ns more
  [[nodiscard]] Nanos operator()(const CanFrame& f) const {
    std::uint32_t h = 2166136261U;
    for (std::size_t i = 0; i < f.len; ++i) h = (h ^ f.data[i]) * 16777619U;
    const bool odd = odd_every != 0 && (h >> 20U) % odd_every == 0;
    return 100_us + 2_us * static_cast<std::int64_t>(h % spread) + (odd ? 1_us : Nanos{0}) +
           Nanos{static_cast<std::int64_t>((h >> 8U) % jitter)};
  }
};

// The search as documented, the slow way, for the n-th frame sent at t.
CanFrame searched(Nanos t, std::uint64_t n, const AngleStreamParams& params, const FakeTransport& transport,
                  const std::vector<Nanos>& possible, Nanos& last_delay, std::set<Nanos>& delays) {
  constexpr double kCode = 1.0 / 16'777'216.0;
  CanFrame nearest;
  Nanos miss = Nanos::max();
  const auto build = [&](Nanos delay, int nudge) {
    delays.insert(delay);
    ShaftSample shaft = shaft_at(t + params.lead + delay);
    shaft.position =
        (std::ceil(shaft.position / params.units_per_turn / kCode) + nudge) * kCode * params.units_per_turn;
    const CanFrame frame = angle_frame(shaft, params, n);
    const Nanos own = transport(frame);
    const Nanos off = own > delay ? own - delay : delay - own;
    if (off < miss) {
      nearest = frame;
      miss = off;
      last_delay = delay;
    }
    return own;
  };
  for (int nudge = 0; nudge < 16 && miss != Nanos{0}; ++nudge) {
    Nanos delay = last_delay;
    for (int step = 0; step < 3 && miss != Nanos{0}; ++step) delay = build(delay, nudge);
  }
  for (int nudge = 0; nudge < 16 && miss != Nanos{0}; ++nudge)
    for (std::size_t i = 0; i < possible.size() && miss != Nanos{0}; ++i) (void)build(possible[i], nudge);
  return nearest;
}

TEST(AngleStreamer, TheTransportSearchSendsTheFramesOfTheDocumentedSearch) {
  std::uint64_t misses = 0; // frames sent as the nearest miss
  for (const FakeTransport transport : {FakeTransport{3, 0}, FakeTransport{9, 0}, FakeTransport{25, 0},
                                        FakeTransport{9, 4}, FakeTransport{25, 1}, FakeTransport{25, 1, 7}}) {
    SCOPED_TRACE(testing::Message() << transport.spread << " " << transport.odd_every << " "
                                    << transport.jitter);
    std::vector<Nanos> possible;
    for (std::int64_t k = 0; k < 25; ++k) possible.push_back(100_us + 2_us * k);
    AngleStreamParams params;
    params.units_per_turn = 4096.0;
    params.lead = 3_us;
    Scheduler scheduler;
    CapturePort port;
    std::map<std::int64_t, int> reads; // shaft reads per frame (its send time)
    Nanos now{0};
    AngleStreamer streamer(
        scheduler, port,
        [&](Nanos t) {
          ++reads[now.count()];
          return shaft_at(t);
        },
        params);
    std::uint64_t calls = 0;
    streamer.lead_by_transport(
        [&](const CanFrame& f) {
          ++calls;
          return transport(f);
        },
        possible);
    streamer.start(Nanos{0});
    constexpr int kFrames = 300;
    for (int k = 0; k < kFrames; ++k) {
      now = 1_ms * k;
      scheduler.run_until(now);
    }
    ASSERT_EQ(port.sent.size(), std::size_t{kFrames});
    Nanos last_delay = possible.front();
    std::uint64_t exact = 0;
    for (int k = 0; k < kFrames; ++k) {
      std::set<Nanos> delays;
      const CanFrame want =
          searched(1_ms * k, static_cast<std::uint64_t>(k), params, transport, possible, last_delay, delays);
      ASSERT_EQ(port.sent[static_cast<std::size_t>(k)], want) << "frame " << k;
      if (transport(want) == last_delay) ++exact;
      // The shaft read once per delay tried.
      EXPECT_EQ(reads[(1_ms * k).count()], static_cast<int>(delays.size())) << "frame " << k;
    }
    // Each (delay, code) frame asked once: at most 16 codes x 25 delays a frame.
    EXPECT_LE(calls, std::uint64_t{kFrames} * 16 * 25);
    // The draw has exact matches, and (below) frames sent as the nearest miss.
    EXPECT_GT(exact, 0U);
    misses += kFrames - exact;
  }
  std::cout << "frames sent as the nearest miss: " << misses << "\n";
  EXPECT_GT(misses, 100U);
}

} // namespace
} // namespace hilrig::models::resolver_emulator
