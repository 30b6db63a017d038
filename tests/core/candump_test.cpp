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

// ---- reading a log back ---------------------------------------------------------------------

// Lines as can-utils writes them (the forms above) read back to their frames.
TEST(CandumpReader, ReadsEveryFormTheWriterWrites) {
  auto r = read_candump_line("(0000000012.345678) can0 123#DEADBEEF");
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->time, Nanos{12'345'678'000});
  EXPECT_EQ(r->bus, "can0");
  EXPECT_EQ(r->frame, frame(0x123, {0xDE, 0xAD, 0xBE, 0xEF}));
  r = read_candump_line("(0000000000.000001)  vcan12 12345678#R2");
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->bus, "vcan12"); // padding before the name is not part of it
  EXPECT_TRUE(r->frame.extended && r->frame.rtr);
  EXPECT_EQ(r->frame.len, 2);
  r = read_candump_line("(0000000001.000000) can0 7FF##5" + std::string(24, 'a'));
  ASSERT_TRUE(r.has_value());
  EXPECT_TRUE(r->frame.fd && r->frame.brs && !r->frame.esi && r->fdf_flag);
  EXPECT_EQ(r->frame.len, 12);
  EXPECT_EQ(r->frame.data[11], 0xAA);
}

TEST(CandumpReader, RefusesWhatIsNotALogLine) {
  for (const char* bad : {"",
                          "(0000000012.34567) can0 123#",                      // the micros are 6 digits
                          "(0000000012.345678) can0 1234#00",                  // a 4-digit ID
                          "(0000000012.345678) can0 800#00",                   // above 11 bits
                          "(0000000012.345678) can0 20000000#00",              // above 29 bits
                          "(0000000012.345678) can0 123#001",                  // half a byte
                          "(0000000012.345678) can0 123#000102030405060708",   // 9 bytes classic
                          "(0000000012.345678) can0 123##0000102030405060708", // 9 bytes FD
                          "(0000000012.345678) can0 123##8",                   // flags beyond FDF|ESI|BRS
                          "(0000000012.345678) can0 123#R9",                   // remote DLC beyond 8
                          "(0000000012.345678) can0 123#R0",                   // DLC 0 is written as no digit
                          "(0000000012.345678) can0 123#ZZ",
                          "(0000000012.345678) averyveryverylongname 123#00", // beyond IFNAMSIZ
                          "(0000000012.345678) can0"}) {
    EXPECT_FALSE(read_candump_line(bad).has_value()) << bad;
  }
  EXPECT_TRUE(read_candump_line("(12.345678) can0 123#").has_value()); // the seconds may be short
  // The most seconds 64-bit nanoseconds hold, and one more (it overflowed: found by fuzz_candump).
  const auto last = read_candump_line("(9223372035.999999) can0 123#");
  ASSERT_TRUE(last.has_value());
  EXPECT_EQ(last->time, Nanos{9'223'372'035'999'999'000});
  EXPECT_FALSE(read_candump_line("(9223372036.000000) can0 123#").has_value());
  EXPECT_FALSE(read_candump_line("(9466084800.000250) can0 123#").has_value());
}

// Property: every frame the writer can write reads back equal (seeded, every kind of frame).
TEST(CandumpReader, RoundTripsEveryFrameTheWriterWrites) {
  std::uint64_t state = 0x9E3779B97F4A7C15ULL;
  auto next = [&state] {
    state ^= state << 13U;
    state ^= state >> 7U;
    state ^= state << 17U;
    return static_cast<std::uint32_t>(state);
  };
  constexpr std::uint8_t kFdLengths[] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 16, 20, 24, 32, 48, 64};
  for (int i = 0; i < 5000; ++i) {
    CandumpRecord r;
    r.time = Nanos{static_cast<std::int64_t>(next() % 100'000) * 1'000'000'007 / 1000 * 1000};
    r.bus = next() % 2 == 0 ? "can0" : "vcan1";
    CanFrame& f = r.frame;
    f.extended = next() % 3 == 0;
    f.id = next() & (f.extended ? 0x1FFF'FFFFU : 0x7FFU);
    f.fd = next() % 3 == 0;
    if (f.fd) {
      f.brs = next() % 2 == 0;
      f.esi = next() % 5 == 0;
      r.fdf_flag = next() % 2 == 0;
      f.len = kFdLengths[next() % 16];
    } else {
      f.rtr = next() % 6 == 0;
      f.len = static_cast<std::uint8_t>(next() % 9);
    }
    if (!f.rtr)
      for (std::size_t b = 0; b < f.len; ++b) f.data[b] = static_cast<std::uint8_t>(next());
    const std::string line = candump_line(r.time, r.bus, f, 6, r.fdf_flag);
    const auto back = read_candump_line(line);
    ASSERT_TRUE(back.has_value()) << line;
    EXPECT_EQ(*back, r) << line;
  }
}
