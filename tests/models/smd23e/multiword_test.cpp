// The 1000-based multi-word format (spec §6.3) against the manual's worked examples.
#include <gtest/gtest.h>

#include <random>

#include "models/smd23e/multiword.hpp"

namespace hilrig::models::smd23e {
namespace {

TEST(Smd23eMultiWord, M01SplitsTwelve) { EXPECT_EQ(encode_multiword(12), (MultiWord{0, 12})); }

TEST(Smd23eMultiWord, M02Splits12345) { EXPECT_EQ(encode_multiword(12'345), (MultiWord{12, 345})); }

TEST(Smd23eMultiWord, M03Splits1234567) {
  EXPECT_EQ(encode_multiword(1'234'567), (MultiWord{0x04D2, 0x0237})); // (1234, 567)
}

TEST(Smd23eMultiWord, M04NegativeValuesCarryTheSignInBothWords) {
  // −7,654,321 = (−7654, −321); 65536 − 7654 = 0xE21A, 65536 − 321 = 0xFEBF.
  EXPECT_EQ(encode_multiword(-7'654'321), (MultiWord{0xE21A, 0xFEBF}));
  EXPECT_EQ(decode_multiword(0xE21A, 0xFEBF), -7'654'321);
}

TEST(Smd23eMultiWord, M24RegisterExtremes) {
  EXPECT_EQ(encode_multiword(-32'768'000), (MultiWord{0x8000, 0x0000}));
  EXPECT_EQ(encode_multiword(32'767'999), (MultiWord{0x7FFF, 0x03E7}));
  EXPECT_EQ(decode_multiword(0x8000, 0x0000), -32'768'000);
  EXPECT_EQ(decode_multiword(0x7FFF, 0x03E7), 32'767'999);
}

// [MODEL] (README): a value past either end of the registers' range (L876, L2910) is reported
// as that end; at the end and one inside it is exact.
TEST(Smd23eMultiWord, ValuesPastTheRegisterEndsReadAsTheEnds) {
  EXPECT_EQ(encode_multiword(32'767'998), (MultiWord{0x7FFF, 998}));
  EXPECT_EQ(encode_multiword(32'767'999), (MultiWord{0x7FFF, 999}));
  EXPECT_EQ(encode_multiword(32'768'000), (MultiWord{0x7FFF, 999}));
  EXPECT_EQ(encode_multiword(-32'767'999), (MultiWord{0x8001, as_word(-999)}));
  EXPECT_EQ(encode_multiword(-32'768'000), (MultiWord{0x8000, 0}));
  EXPECT_EQ(encode_multiword(-32'768'001), (MultiWord{0x8000, 0}));
}

TEST(Smd23eMultiWord, RejectsLowerWordAbove999AndMixedSigns) {
  EXPECT_FALSE(decode_multiword(1, 1000).has_value());        // M-25's (1, 1000)
  EXPECT_FALSE(decode_multiword(1, as_word(-1)).has_value()); // (+1, −1)
  EXPECT_FALSE(decode_multiword(as_word(-1), 1).has_value()); // (−1, +1)
  EXPECT_EQ(decode_multiword(0, as_word(-999)), -999);        // zero upper word takes either sign
}

TEST(Smd23eMultiWord, RoundTripsEveryValueInRange) {
  std::mt19937 rng(2313); // fixed seed
  std::uniform_int_distribution<std::int32_t> value(-32'768'000, 32'767'999);
  for (int i = 0; i < 100'000; ++i) {
    const std::int32_t v = value(rng);
    const MultiWord w = encode_multiword(v);
    ASSERT_EQ(decode_multiword(w.upper, w.lower), v) << v;
  }
}

} // namespace
} // namespace hilrig::models::smd23e
