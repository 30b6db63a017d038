#include "drivers/virtual/serial_link.hpp"

#include <gtest/gtest.h>

#include <array>
#include <vector>

using namespace hilrig;
using namespace hilrig::literals;
using hilrig::virt::SerialLink;

namespace {
struct Got {
  std::uint8_t byte;
  Nanos time;
  friend bool operator==(const Got&, const Got&) = default;
};
} // namespace

TEST(SerialFormat, CharTimes) {
  // 9600 8N1: 10 bits / 9600 bit/s = 1.0416667 ms -> 1'041'667 ns.
  EXPECT_EQ(SerialFormat{}.char_time(), 1'041'667_ns);
  // 115200 8E1: 11 bits / 115200 = 95.486 us -> 95'486 ns.
  EXPECT_EQ((SerialFormat{115200, 8, Parity::Even, 1}.char_time()), 95'486_ns);
}

TEST(SerialLink, TenBytesAt9600Take10Point417Ms) {
  Scheduler s;
  SerialLink link(s, "host", SerialFormat{}, nullptr);
  std::vector<Got> got;
  link.end_b().on_byte([&](std::uint8_t b, Nanos t) { got.push_back({b, t}); });
  const std::array<std::uint8_t, 10> bytes{0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  link.end_a().write(bytes);
  s.run_until_idle();
  ASSERT_EQ(got.size(), 10U);
  // Byte k (0-based) ends its stop bit at (k + 1) x 1'041'667 ns.
  for (std::size_t k = 0; k < 10; ++k) {
    EXPECT_EQ(got[k], (Got{static_cast<std::uint8_t>(k), 1'041'667_ns * static_cast<std::int64_t>(k + 1)}));
  }
  EXPECT_EQ(got.back().time, 10'416'670_ns); // 10.417 ms
}

TEST(SerialLink, WritesQueueBehindEachOther) {
  Scheduler s;
  SerialLink link(s, "host", SerialFormat{}, nullptr);
  std::vector<Got> got;
  link.end_b().on_byte([&](std::uint8_t b, Nanos t) { got.push_back({b, t}); });
  const std::array<std::uint8_t, 2> first{0xA1, 0xA2};
  const std::array<std::uint8_t, 1> second{0xB1};
  link.end_a().write(first);
  s.at(500_us, [&] { link.end_a().write(second); }); // mid-byte: waits for 0xA2
  s.run_until_idle();
  EXPECT_EQ(got, (std::vector<Got>{{0xA1, 1'041'667_ns}, {0xA2, 2'083'334_ns}, {0xB1, 3'125'001_ns}}));
}

TEST(SerialLink, BothDirectionsRunAtOnce) {
  Scheduler s;
  TraceRecorder trace;
  SerialLink link(s, "host", SerialFormat{}, &trace);
  std::vector<Got> at_a;
  std::vector<Got> at_b;
  link.end_a().on_byte([&](std::uint8_t b, Nanos t) { at_a.push_back({b, t}); });
  link.end_b().on_byte([&](std::uint8_t b, Nanos t) { at_b.push_back({b, t}); });
  const std::array<std::uint8_t, 1> ping{0x01};
  const std::array<std::uint8_t, 1> pong{0x02};
  link.end_a().write(ping);
  link.end_b().write(pong);
  s.run_until_idle();
  EXPECT_EQ(at_b, (std::vector<Got>{{0x01, 1'041'667_ns}}));
  EXPECT_EQ(at_a, (std::vector<Got>{{0x02, 1'041'667_ns}}));
  ASSERT_EQ(trace.serial_bytes().size(), 2U);
  EXPECT_EQ(trace.serial_bytes()[0].direction, SerialDirection::AtoB);
  EXPECT_EQ(trace.serial_bytes()[1].direction, SerialDirection::BtoA);
  EXPECT_EQ(trace.serial_bytes()[0].link, "host");
}

TEST(SerialLink, CorruptionAndDropHooks) {
  Scheduler s;
  TraceRecorder trace;
  SerialLink link(s, "host", SerialFormat{}, &trace);
  std::vector<Got> got;
  link.end_b().on_byte([&](std::uint8_t b, Nanos t) { got.push_back({b, t}); });
  link.set_corrupt([](SerialDirection, std::uint8_t b) { return b == 0x10 ? std::uint8_t{0x11} : b; });
  link.set_drop([](SerialDirection, std::uint8_t b) { return b == 0x20; });
  const std::array<std::uint8_t, 3> bytes{0x10, 0x20, 0x30};
  link.end_a().write(bytes);
  s.run_until_idle();
  // 0x10 arrives as 0x11; 0x20 is lost but still took its slot, so 0x30 ends at 3 chars.
  EXPECT_EQ(got, (std::vector<Got>{{0x11, 1'041'667_ns}, {0x30, 3'125'001_ns}}));
  ASSERT_EQ(trace.serial_bytes().size(), 2U);
  EXPECT_EQ(trace.serial_bytes()[0].byte, 0x11);
}

TEST(SerialLink, AnEchoFromTheHandlerFollows) {
  Scheduler s;
  SerialLink link(s, "host", SerialFormat{}, nullptr);
  link.end_b().on_byte([&](std::uint8_t b, Nanos) {
    const std::array<std::uint8_t, 1> echo{b};
    link.end_b().write(echo);
  });
  std::vector<Got> got;
  link.end_a().on_byte([&](std::uint8_t b, Nanos t) { got.push_back({b, t}); });
  const std::array<std::uint8_t, 1> bytes{0x55};
  link.end_a().write(bytes);
  s.run_until_idle();
  EXPECT_EQ(got, (std::vector<Got>{{0x55, 2'083'334_ns}}));
}
