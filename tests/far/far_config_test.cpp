// The far-side config (rig/far/far_config.hpp): pins on gpio-sim lines and the resolver node;
// every mistake is reported at its file:line:column and key.
#include <gtest/gtest.h>

#include <string>

#include "rig/far/far_config.hpp"

namespace hilrig::test {
namespace {

using campaign::CampaignError;

TEST(FarConfig, ReadsPinsAndTheResolverNode) {
  const far::FarConfig c = far::parse_far_config(R"([[pin]]
board = "A"
offset = 0

[[pin]]
board = "OUT1"
offset = 8

[resolver]
channel = 2
frame_period = "2ms"
timeout_periods = 50
ratio = 0.95
)",
                                                 "far.toml");
  ASSERT_EQ(c.pins.size(), 2U);
  EXPECT_EQ(c.pins[0].board, "A");
  EXPECT_EQ(c.pins[0].offset, 0U);
  EXPECT_EQ(c.pins[1].board, "OUT1");
  EXPECT_EQ(c.pins[1].offset, 8U);
  EXPECT_EQ(c.pins[1].where.line, 5U);
  ASSERT_TRUE(c.resolver.has_value());
  EXPECT_EQ(c.resolver->sin_pin, "SIN");
  EXPECT_EQ(c.resolver->cos_pin, "COS");
  EXPECT_EQ(c.resolver->channel, 2);
  EXPECT_EQ(c.resolver->frame_period, milliseconds(2));
  EXPECT_EQ(c.resolver->timeout_periods, 50U);
  EXPECT_DOUBLE_EQ(c.resolver->ratio, 0.95);
  // Not written: the ANS1 model's reference (5 kHz, amplitude 1).
  EXPECT_DOUBLE_EQ(c.resolver->excitation_hz, 5000.0);
  EXPECT_DOUBLE_EQ(c.resolver->amplitude, 1.0);
}

// The error's key and line, and that the message starts with file:line.
void expect_error(const std::string& text, const std::string& key, std::uint32_t line) {
  try {
    (void)far::parse_far_config(text, "far.toml");
    ADD_FAILURE() << "accepted:\n" << text;
  } catch (const CampaignError& e) {
    EXPECT_EQ(e.key(), key) << e.what();
    EXPECT_EQ(e.where().line, line) << e.what();
    EXPECT_EQ(std::string(e.what()).rfind("far.toml:" + std::to_string(line) + ":", 0), 0U) << e.what();
  }
}

TEST(FarConfig, MistakesNameTheirPlace) {
  expect_error("[[pin]]\nboard = \"A\"\noffset = -1\n", "pin[0].offset", 3);
  expect_error("[[pin]]\nboard = \"A\"\noffset = 0\nofset = 1\n", "pin[0].ofset", 4);
  expect_error("[[pin]]\nboard = \"A\"\noffset = 0\n[[pin]]\nboard = \"A\"\noffset = 1\n", "pin[1].board", 4);
  expect_error("[[pin]]\nboard = \"A\"\noffset = 0\n[[pin]]\nboard = \"B\"\noffset = 0\n", "pin[1].offset",
               4);
  expect_error("[resolver]\nchannel = 16\n", "resolver.channel", 2);
  expect_error("[resolver]\nexcitation_hz = 10000\n", "resolver.excitation_hz", 2);
  expect_error("[resolver]\nframe_period = 1\n", "resolver.frame_period", 2);
  expect_error("[[pin]]\nboard = \"SIN\"\noffset = 0\n[resolver]\n", "pin.board", 1);
  expect_error("# nothing\n", "pin", 1);
  expect_error("[[pin]]\nboard = \"A\"\noffset = \n", "toml", 3);
}

TEST(FarConfig, AMissingFileIsBadInput) {
  EXPECT_THROW((void)far::load_far_config("no-such-dir/far.toml"), CampaignError);
}

} // namespace
} // namespace hilrig::test
