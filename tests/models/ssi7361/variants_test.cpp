// Each fault variant differs from the correct model on some input a campaign can give,
// seen only through the lines and host words.

#include <gtest/gtest.h>

#include "ssi7361_rig.hpp"

namespace hilrig::models::ssi7361::test {
namespace {

Params with(Variant v) {
  Params p;
  p.variant = v;
  return p;
}

TEST(Ssi7361Variants, NamesRoundTrip) {
  for (const auto& v : kVariantNames) {
    EXPECT_EQ(variant_from_string(v.name), v.variant);
    EXPECT_EQ(to_string(v.variant), v.name);
  }
  EXPECT_EQ(variant_from_string("nominal"), Variant::Correct);
  EXPECT_FALSE(variant_from_string("no_such_variant").has_value());
}

// Binary 0110 in a 4-bit field: 6 when read as binary, 4 when taken as Gray.
std::int32_t read_binary_six(Variant v) {
  Rig rig(with(v));
  rig.attach_word_sensor();
  EXPECT_EQ(rig.program(qbit::kFormat, {.format = format_word(22, 4)}), kAck);
  rig.send(6);
  return rig.dv();
}

TEST(Ssi7361Variants, GraySwappedTakesBinaryAsGray) {
  EXPECT_EQ(read_binary_six(Variant::Correct), 6);
  EXPECT_EQ(read_binary_six(Variant::GraySwapped), 4);
}

std::uint32_t read_alternating(Variant v) {
  Rig rig(with(v));
  rig.attach_word_sensor();
  rig.send(0x1555555);
  return rig.raw();
}

TEST(Ssi7361Variants, SampleWrongEdgeReadsEachBitOnePlaceLate) {
  EXPECT_EQ(read_alternating(Variant::Correct), 0x1555555u);
  // At F_k DATA still holds bit k-1 (bit 1 reads the low of the latch): word >> 1.
  EXPECT_EQ(read_alternating(Variant::SampleWrongEdge), 0x0AAAAAAu);
}

std::int32_t checkout_preset(Variant v) {
  Rig rig(with(v));
  rig.run_for(1_ms);
  EXPECT_EQ(rig.program(62 | qbit::kApplyPreset,
                        {.format = 266, .multiplier = 1000, .divisor = 1024, .preset = 125'420, .rut = 500}),
            kAck);
  return rig.dv();
}

TEST(Ssi7361Variants, OffsetBeforeScalingMissesThePreset) {
  EXPECT_EQ(checkout_preset(Variant::Correct), 125'420); // M-05
  // LO = 124,421 scaled with the field: (1023 + 124,421) * 1000 / 1024 = 122,503.9.
  EXPECT_EQ(checkout_preset(Variant::OffsetBeforeScaling), 122'503);
}

std::int32_t ramp_rate(Variant v) {
  Rig rig(with(v));
  rig.attach_sensor(signals::ssi7361_frame(1, 24),
                    [](Nanos t) { return static_cast<std::uint32_t>(t.count() / 1'000'000); });
  rig.run_until(250_ms);
  return rig.rate();
}

TEST(Ssi7361Variants, RateNotUpdatedStaysZero) {
  EXPECT_EQ(ramp_rate(Variant::Correct), 1000); // 100 counts per 100 ms (see rate_test)
  EXPECT_EQ(ramp_rate(Variant::RateNotUpdated), 0);
}

std::uint16_t two_errors(Variant v) {
  Rig rig(with(v));
  return rig.program(qbit::kFormat | qbit::kRut, {.format = format_word(1, 1), .rut = 0});
}

TEST(Ssi7361Variants, ErrorOrderReversedReportsTheLaterError) {
  EXPECT_EQ(two_errors(Variant::Correct), kAck | ibit::kFormatError);
  EXPECT_EQ(two_errors(Variant::ErrorOrderReversed), kAck | ibit::kRutError);
}

} // namespace
} // namespace hilrig::models::ssi7361::test
