// Rate of Change (digest §3): Δ(DV) over one Rate Update Time, per second, held between
// updates; ROVErr above 64,108,863 counts/s. Examples M-08..M-12.
//
// The transducers here are ramps value(t) = floor(k * t / d) latched at each F1. Frames are
// 500 us apart and every RUT below is a multiple of 500 us, so the frames read last before
// two successive updates are exactly RUT apart and Δ is exact: floor(y + RUT*k/d) - floor(y).

#include <gtest/gtest.h>

#include <vector>

#include "ssi7361_rig.hpp"

namespace hilrig::models::ssi7361::test {
namespace {

// A full 25-bit field (M = 1, N = 25, 1/1) so DV = the value the ramp sends, and `rut`.
void setup_rate(Rig& rig, std::uint16_t rut) {
  ASSERT_EQ(rig.program(qbit::kFormat | qbit::kRut, {.format = format_word(1, 25), .rut = rut}), kAck);
}

// A ramp of `counts` every `every`.
std::function<std::uint32_t(Nanos)> ramp(std::int64_t counts, Nanos every) {
  return [=](Nanos t) { return static_cast<std::uint32_t>(t.count() * counts / every.count()); };
}

void attach_ramp(Rig& rig, std::int64_t counts, Nanos every) {
  rig.attach_sensor(signals::ssi7361_frame(1, 25), ramp(counts, every));
}

TEST(Ssi7361Rate, M09_FiftyCountsIn200msIs250PerSecond) {
  Rig rig;
  attach_ramp(rig, 1, 4_ms); // +50 per 200 ms
  rig.run_until(1_ms);
  setup_rate(rig, 200); // window restarts at 1 ms: updates at 201, 401, ... ms
  rig.run_until(200_ms);
  EXPECT_EQ(rig.rate(), 0); // not updated yet
  rig.run_until(201_ms);
  EXPECT_EQ(rig.rate(), 250); // 50 * 1000 / 200
  rig.run_until(550_ms);
  EXPECT_EQ(rig.rate(), 250);
}

TEST(Ssi7361Rate, M10_GranularityForRut1_10_100ms) {
  struct Case {
    std::uint16_t rut;
    std::int32_t expected;
  };
  for (const Case c : {Case{1, 3000}, Case{10, 300}, Case{100, 30}}) {
    Rig rig;
    attach_ramp(rig, 3, milliseconds(c.rut)); // Δ = 3 per window
    rig.run_until(1_ms);
    setup_rate(rig, c.rut);
    rig.run_for(milliseconds(3 * c.rut) + 100_us);
    EXPECT_EQ(rig.rate(), c.expected) << "RUT " << c.rut;
  }
}

TEST(Ssi7361Rate, M11_OneCountPer24msTruncatesTo41) {
  Rig rig;
  attach_ramp(rig, 1, 24_ms);
  rig.run_until(1_ms);
  setup_rate(rig, 24);
  rig.run_for(100_ms);
  EXPECT_EQ(rig.rate(), 41); // 1000 / 24 = 41.67, truncated [MODEL]
}

TEST(Ssi7361Rate, M11_RoundedTo42WhenParameterised) {
  Params p;
  p.rate_rounding = RateRounding::Nearest; // the manual's printed 42 (A9)
  Rig rig(p);
  attach_ramp(rig, 1, 24_ms);
  rig.run_until(1_ms);
  setup_rate(rig, 24);
  rig.run_for(100_ms);
  EXPECT_EQ(rig.rate(), 42);
}

// M-12: a 15-bit encoder (M = 11, N = 15: the low 15 bits) rolls over inside one 24 ms
// window (updates at 25, 49, 73 ms after programming at 1 ms; the roll at 30 ms).
void roll_over(std::uint32_t before, std::uint32_t after, std::int32_t spike) {
  Rig rig;
  rig.attach_sensor(signals::ssi7361_frame(1, 25), [=](Nanos t) { return t < 30_ms ? before : after; });
  rig.run_until(1_ms);
  ASSERT_EQ(rig.program(qbit::kFormat | qbit::kRut, {.format = format_word(11, 15), .rut = 24}), kAck);
  rig.run_until(40_ms);
  EXPECT_EQ(rig.rate(), 0); // update at 25 ms: no change
  rig.run_until(60_ms);
  EXPECT_EQ(rig.rate(), spike);                          // update at 49 ms: the roll-over
  EXPECT_EQ(rig.status_bits() & ibit::kRateOverflow, 0); // below 64,108,863
  rig.run_until(80_ms);
  EXPECT_EQ(rig.rate(), 0); // exactly one window (A11)
}

TEST(Ssi7361Rate, M12_RollOverSpikeLastsOneWindow) {
  // 32,767 * 1000 / 24 = 1,365,291.67 -> 1,365,291 (the manual's 1,365,333 is A10).
  roll_over(32'767, 0, -1'365'291); // forward: Δ = -32,767
  roll_over(0, 32'767, 1'365'291);  // backward: Δ = +32,767
}

TEST(Ssi7361Rate, M08_Rut500msUpdatesAtMostEvery500ms) {
  Rig rig; // checkout: no transducer, constant data
  rig.run_until(1_ms);
  ASSERT_EQ(rig.program(62, {.format = 266, .multiplier = 1000, .divisor = 1024, .preset = 0, .rut = 500}),
            kAck);
  rig.run_until(2_s);
  EXPECT_EQ(rig.rate(), 0);

  // With an accelerating transducer (value = t^2 in ms^2) every update gives a new rate:
  // record when the RoC words change, polling every millisecond.
  Rig moving;
  moving.attach_sensor(signals::ssi7361_frame(1, 25), [](Nanos t) {
    const std::int64_t ms = t.count() / 1'000'000;
    return static_cast<std::uint32_t>(ms * ms);
  });
  moving.run_until(1_ms);
  ASSERT_EQ(moving.program(qbit::kFormat | qbit::kRut, {.format = format_word(1, 25), .rut = 500}), kAck);
  std::vector<Nanos> changes;
  std::int32_t last = moving.rate();
  for (int ms = 2; ms <= 2100; ++ms) {
    moving.run_until(milliseconds(ms));
    if (moving.rate() != last) changes.push_back(moving.now());
    last = moving.rate();
  }
  EXPECT_EQ(changes, (std::vector<Nanos>{501_ms, 1001_ms, 1501_ms, 2001_ms}));
}

TEST(Ssi7361Rate, M21_DefaultRut100msFromPowerUp) {
  Rig rig;
  // Defaults M = 1, N = 24: the sensor's 24-bit value sits in stream bits 1..24.
  rig.attach_sensor(signals::ssi7361_frame(1, 24), ramp(1, 1_ms));
  rig.run_until(150_ms);
  // Window 0..100 ms started before any frame: no rate (power_up_rate_test.cpp).
  EXPECT_EQ(rig.rate(), 0);
  rig.run_until(199_ms);
  EXPECT_EQ(rig.rate(), 0);
  rig.run_until(200_ms);
  EXPECT_EQ(rig.rate(), 1000); // 199 - 99 = 100 in 100 ms (default RUT, L1269-1270)
  rig.run_until(299_ms);
  EXPECT_EQ(rig.rate(), 1000); // held between updates (L1269)
}

TEST(Ssi7361Rate, ProgrammingRutRestartsTheWindow) {
  Rig rig;
  rig.attach_sensor(signals::ssi7361_frame(1, 24), ramp(1, 1_ms));
  rig.run_until(130_ms);
  ASSERT_EQ(rig.program(qbit::kRut, {.rut = 100}), kAck); // same RUT, new window at 130 ms
  rig.run_until(229_ms);
  EXPECT_EQ(rig.rate(), 0); // no update at 200 ms (and none from the frameless first window)
  rig.run_until(230_ms);
  EXPECT_EQ(rig.rate(), 1000); // 229 - 129
}

TEST(Ssi7361Rate, PresetInsideAWindowGivesOneSpike) {
  Rig rig;
  rig.attach_word_sensor();
  rig.run_until(150_ms); // constant 0; updates every 100 ms
  ASSERT_EQ(rig.program(qbit::kPresetValue | qbit::kApplyPreset, {.preset = 5000}), kAck);
  rig.run_until(200_ms);
  EXPECT_EQ(rig.rate(), 50'000); // 5000 * 1000 / 100: not suppressed [MODEL]
  rig.run_until(300_ms);
  EXPECT_EQ(rig.rate(), 0);

  Params p;
  p.preset_restarts_rate_window = true;
  Rig quiet(p);
  quiet.attach_word_sensor();
  quiet.run_until(150_ms);
  ASSERT_EQ(quiet.program(qbit::kPresetValue | qbit::kApplyPreset, {.preset = 5000}), kAck);
  quiet.run_until(260_ms);
  EXPECT_EQ(quiet.rate(), 0);
}

TEST(Ssi7361Rate, OverflowBitAboveTheLimitClearsAtTheNextUpdate) {
  Rig rig;
  rig.attach_word_sensor();
  rig.run_until(1_ms);
  setup_rate(rig, 1); // updates at 2, 3, ... ms
  rig.run_until(10_ms);
  rig.word = 100'000; // latched from the frame at 10.5 ms
  rig.run_until(11_ms + 500_us);
  // 100,000 counts in 1 ms = 100,000,000 counts/s > 64,108,863: ROVErr (%I bit 06).
  EXPECT_EQ(rig.rate(), 100'000'000);
  EXPECT_EQ(rig.status()[status::kRateLow], 0xE100); // 0x05F5E100
  EXPECT_EQ(rig.status()[status::kRateHigh], 0x05F5);
  EXPECT_EQ(rig.status_bits(), ibit::kRateOverflow);
  rig.run_until(12_ms + 500_us);
  EXPECT_EQ(rig.rate(), 0);
  EXPECT_EQ(rig.status_bits(), 0); // in range again (A20 [MODEL])
  rig.word = 0;                    // the same jump backwards (read at 13.2 ms, so in the 13..14 ms window)
  rig.run_until(14_ms + 500_us);
  EXPECT_EQ(rig.rate(), -100'000'000);
  EXPECT_EQ(rig.status_bits(), ibit::kRateOverflow);
}

TEST(Ssi7361Rate, OverflowThresholdIsExclusive) {
  // 64,108 counts/ms = 64,108,000/s: in range; 64,109 counts/ms = 64,109,000/s > limit.
  for (const std::uint32_t jump : {64'108u, 64'109u}) {
    Rig rig;
    rig.attach_word_sensor();
    rig.run_until(1_ms);
    setup_rate(rig, 1);
    rig.run_until(10_ms);
    rig.word = jump;
    rig.run_until(11_ms + 500_us);
    EXPECT_EQ(rig.status_bits(), jump == 64'109u ? ibit::kRateOverflow : 0) << jump;
  }
}

TEST(Ssi7361Rate, OverflowLimitIsAParameter) {
  Params p;
  p.rate_overflow_limit = 67'108'863; // 2^26 - 1, if 64,108,863 is a typo (A3)
  Rig rig(p);
  rig.attach_word_sensor();
  rig.run_until(1_ms);
  setup_rate(rig, 1);
  rig.run_until(10_ms);
  rig.word = 65'000;
  rig.run_until(11_ms + 500_us);
  EXPECT_EQ(rig.rate(), 65'000'000);
  EXPECT_EQ(rig.status_bits(), 0);
}

} // namespace
} // namespace hilrig::models::ssi7361::test
