#include "drivers/virtual/analog_channel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace hilrig;
using namespace hilrig::literals;
using hilrig::virt::AnalogChannel;

TEST(AnalogChannel, ReadsZeroUntilDriven) {
  AnalogChannel ch("res.sin");
  EXPECT_EQ(ch.name(), "res.sin");
  EXPECT_EQ(ch.sample(1_ms), 0.0);
}

TEST(AnalogChannel, SamplesTheWaveformAtAnyInstant) {
  AnalogChannel ch("res.sin");
  // A 1 kHz sine of amplitude 2: at 250 us it is at its crest, at 500 us back at zero.
  ch.set_waveform([](Nanos t) { return 2.0 * std::sin(2.0 * std::numbers::pi * 1000.0 * t.seconds()); });
  const AnalogInput& in = ch;
  EXPECT_NEAR(in.sample(0_us), 0.0, 1e-12);
  EXPECT_NEAR(in.sample(250_us), 2.0, 1e-12);
  EXPECT_NEAR(in.sample(500_us), 0.0, 1e-12);
  EXPECT_NEAR(in.sample(750_us), -2.0, 1e-12);
}
