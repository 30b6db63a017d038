// The Rate of Change at power-up (digest §3). The rate is "the amount of change ... between
// updates" of the Data Value read from the transducer, refreshed every Rate Update Time
// (seeds/004_2d8564fc60a2b9d4.txt:1269-1270, default 100 ms); ROVErr is set when it exceeds
// 64,108,863 counts/s (L2024). Before the module has read two frames there is no change to
// measure: the value "before the first frame" is no position, so the first windows report no
// rate (0) and no ROVErr, whatever position the first frame carries.
//
// With no transducer attached the module reads every bit as 1 (raw 1FFFFFFh = 33,554,431,
// L683-684, L2173-2180) and that value does not change: rate 0, no status bit (digest §3
// "No status bit is set").

#include <gtest/gtest.h>

#include <vector>

#include "ssi7361_rig.hpp"

namespace hilrig::models::ssi7361::test {
namespace {

constexpr std::int64_t kOverflowLimit = 64'108'863; // L2024

// Samples the rate and %I every 500 us up to `until`; returns the largest |rate| seen and
// whether ROVErr was ever set.
struct Seen {
  std::int64_t max_rate = 0;
  bool overflow = false;
  std::uint16_t any_bits = 0;
};
Seen watch(Rig& rig, Nanos until) {
  Seen s;
  while (rig.now() < until) {
    rig.run_for(500_us);
    const std::int64_t r = rig.rate();
    s.max_rate = std::max(s.max_rate, r < 0 ? -r : r);
    s.any_bits = static_cast<std::uint16_t>(s.any_bits | rig.status_bits());
    s.overflow = s.overflow || (rig.status_bits() & ibit::kRateOverflow) != 0;
  }
  return s;
}

TEST(Ssi7361PowerUpRate, NoTransducerReadsAllOnesWithNoRateAndNoStatus) {
  // L683-684: 1FFFFFFh with no transducer; defaults M = 1, N = 24 (M-21) so the Data Value is
  // 24 ones = 16,777,215. First frame at several phases of the 500 us frame period.
  for (Nanos first : {0_ns, 137_us, 499_us}) {
    Params p;
    p.first_frame = first;
    Rig rig(p); // DATA idles high, nothing drives it
    const Seen s = watch(rig, 1_s);
    EXPECT_EQ(rig.raw(), 0x1FF'FFFFu) << first.count();
    EXPECT_EQ(rig.dv(), 16'777'215) << first.count();
    EXPECT_EQ(s.max_rate, 0) << first.count();
    EXPECT_EQ(s.any_bits, 0) << first.count(); // no status bit at all
  }
}

TEST(Ssi7361PowerUpRate, AStillTransducerAnywhereGivesNoRateFromPowerUp) {
  // Positions around the one whose jump from 0 in the default 100 ms window would cross the
  // ROVErr limit (6,410,886 x 10 = 64,108,860 <= limit < 64,108,870), and the extremes.
  for (std::uint32_t position : {1u, 6'410'886u, 6'410'887u, 16'777'215u}) {
    for (Nanos first : {0_ns, 250_us}) {
      Params p;
      p.first_frame = first;
      Rig rig(p);
      rig.word = position << 1; // stream bits 1..24 (M = 1, N = 24) of a 25-bit word
      rig.attach_word_sensor();
      const Seen s = watch(rig, 450_ms);
      EXPECT_EQ(rig.dv(), static_cast<std::int32_t>(position));
      EXPECT_EQ(s.max_rate, 0) << position << " first frame " << first.count();
      EXPECT_FALSE(s.overflow) << position << " first frame " << first.count();
    }
  }
}

TEST(Ssi7361PowerUpRate, FirstRateOnceAWindowStartsAndEndsWithAFrame) {
  // A ramp of 1 count per ms from power-up (RUT 100 ms): the window 0..100 ms starts before
  // any frame, so no rate then; the window 100..200 ms measures the frames read last before
  // 100 ms (99.5 ms: 99) and 200 ms (199.5 ms: 199): 100 counts / 100 ms = 1000 counts/s.
  Rig rig;
  rig.attach_sensor(signals::ssi7361_frame(1, 24),
                    [](Nanos t) { return static_cast<std::uint32_t>(t / 1_ms); });
  rig.run_until(150_ms);
  EXPECT_EQ(rig.rate(), 0);
  EXPECT_EQ(rig.status_bits(), 0);
  rig.run_until(199_ms);
  EXPECT_EQ(rig.rate(), 0);
  rig.run_until(200_ms);
  EXPECT_EQ(rig.rate(), 1000);
}

TEST(Ssi7361PowerUpRate, ShortRutGetsItsFirstRateFromTwoFrames) {
  // RUT 1 ms programmed at once: frames every 500 us, so from the second window on a window
  // holds two frames; a still transducer at 16,000,000 (x 1000 per s would be 1.6e10) never
  // shows a rate or ROVErr.
  Rig rig;
  rig.word = 16'000'000u << 1;
  rig.attach_word_sensor();
  ASSERT_EQ(rig.program(qbit::kRut, {.rut = 1}), kAck);
  const Seen s = watch(rig, 20_ms);
  EXPECT_EQ(s.max_rate, 0);
  EXPECT_FALSE(s.overflow);
}

TEST(Ssi7361PowerUpRate, RateFromPowerUpVariantShowsTheFalseOverflow) {
  // The variant keeps the old first window (DV 0 -> first frame): 16,777,215 x 10 per s in the
  // default 100 ms window, far above the limit, with no transducer at all.
  Params p;
  p.variant = Variant::RateFromPowerUp;
  Rig rig(p);
  const Seen s = watch(rig, 150_ms);
  EXPECT_GT(s.max_rate, kOverflowLimit);
  EXPECT_TRUE(s.overflow);
}

} // namespace
} // namespace hilrig::models::ssi7361::test
