#include "core/candump.hpp"
#include "core/trace.hpp"

#include <gtest/gtest.h>

#include <sstream>

using namespace hilrig;
using namespace hilrig::literals;

namespace {
CanFrame frame(std::uint32_t id, std::initializer_list<std::uint8_t> bytes) {
  CanFrame f;
  f.id = id;
  f.len = static_cast<std::uint8_t>(bytes.size());
  std::size_t i = 0;
  for (std::uint8_t b : bytes) f.data[i++] = b;
  return f;
}
} // namespace

// Expected lines are written by hand from can-utils: candump.c logs
// "(%010lu.%06lu) %*s %s" and lib.c's sprint_canframe() prints the ID as %03X / %08X,
// '#', then the data as %02X each; a remote frame as 'R' plus a non-zero DLC digit; an FD
// frame as '##', one hex digit of canfd_frame.flags (BRS=1, ESI=2), then the data.
TEST(Candump, ClassicStandardFrame) {
  EXPECT_EQ(candump_line(Nanos{12'345'678'901}, "can0", frame(0x123, {0xDE, 0xAD, 0xBE, 0xEF})),
            "(0000000012.345678) can0 123#DEADBEEF");
}

TEST(Candump, ZeroTimeAndEmptyPayload) {
  EXPECT_EQ(candump_line(0_ns, "vcan0", frame(0x7, {})), "(0000000000.000000) vcan0 007#");
}

TEST(Candump, ExtendedIdIsEightHexDigits) {
  CanFrame f = frame(0xABC, {0x01, 0x02});
  f.extended = true;
  EXPECT_EQ(candump_line(1_s, "can1", f), "(0000000001.000000) can1 00000ABC#0102");
  f.id = 0x18FF50E5;
  EXPECT_EQ(candump_frame_text(f), "18FF50E5#0102");
}

TEST(Candump, RemoteFrames) {
  CanFrame f = frame(0x7FF, {});
  f.rtr = true;
  EXPECT_EQ(candump_frame_text(f), "7FF#R");
  f.len = 2;
  EXPECT_EQ(candump_frame_text(f), "7FF#R2");
}

TEST(Candump, FdFramesCarryTheFlagsNibble) {
  CanFrame f = frame(0x123, {0x11, 0x22, 0x33});
  f.fd = true;
  EXPECT_EQ(candump_frame_text(f), "123##0112233");
  f.brs = true;
  EXPECT_EQ(candump_frame_text(f), "123##1112233");
  f.esi = true;
  f.extended = true;
  EXPECT_EQ(candump_line(Nanos{1'000'999}, "can0", f), "(0000000000.001000) can0 00000123##3112233");
  // As a Linux 6.0+ kernel reports it: CANFD_FDF (4) set too.
  EXPECT_EQ(candump_frame_text(f, true), "00000123##7112233");
  CanFrame classic = frame(0x123, {0x11});
  EXPECT_EQ(candump_frame_text(classic, true), "123#11"); // no flags on classic frames
}

TEST(Candump, WriterPadsBusNamesToTheLongestAsCandumpDoes) {
  TraceRecorder t;
  t.can("can0", 1500_us, frame(0x100, {0xAA}));
  t.can("vcan10", 2_ms, frame(0x200, {}));
  std::ostringstream out;
  write_candump(t, out);
  EXPECT_EQ(out.str(), "(0000000000.001500)   can0 100#AA\n"
                       "(0000000000.002000) vcan10 200#\n");
}

TEST(Candump, WriterOptionsShiftTimeAndSetFdf) {
  TraceRecorder t;
  CanFrame f = frame(0x123, {0x11, 0x22, 0x33});
  f.fd = true;
  f.brs = true;
  t.can("can0", 1500_us, f);
  std::ostringstream out;
  write_candump(t, out, CandumpOptions{true, Nanos{1'436'509'052'000'000'000}});
  // 1436509052 s + 1.5 ms; flags BRS (1) | FDF (4) = 5.
  EXPECT_EQ(out.str(), "(1436509052.001500) can0 123##5112233\n");
}
