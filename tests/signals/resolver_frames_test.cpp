// Front-end CAN frames: hand-computed payloads, encode -> decode round trips, and the
// DBC file checked line by line against the C++ layout.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "signals/resolver_frames.hpp"

namespace hilrig::signals {
namespace {

using namespace hilrig::literals;

// put_raw and get_raw move a byte's part of the signal at a time; on random signals (any start
// bit and length 1..64, over random frame bytes) they do what moving one bit at a time does
// (Intel order: bit i of the signal is bit (start + i) % 8 of byte (start + i) / 8), and
// leave every other bit of the frame as it was.
TEST(RawSignal, RandomSignalsMatchMovingThemBitByBit) {
  std::mt19937_64 rng(27112026);
  for (int k = 0; k < 20'000; ++k) {
    CanFrame frame;
    for (std::uint8_t& b : frame.data) b = static_cast<std::uint8_t>(rng());
    const auto length = static_cast<unsigned>(1 + rng() % 64);
    const auto start = static_cast<unsigned>(rng() % (512 - length + 1));
    const std::uint64_t raw = rng();
    std::uint64_t want_read = 0;
    for (unsigned i = 0; i < length; ++i)
      want_read |= std::uint64_t{(unsigned{frame.data[(start + i) / 8]} >> ((start + i) % 8)) & 1U} << i;
    ASSERT_EQ(get_raw(frame, start, length), want_read) << k;
    CanFrame want = frame;
    for (unsigned i = 0; i < length; ++i) {
      const auto mask = static_cast<std::uint8_t>(1U << ((start + i) % 8));
      std::uint8_t& b = want.data[(start + i) / 8];
      b = static_cast<std::uint8_t>(((raw >> i) & 1U) != 0 ? b | mask : b & ~mask);
    }
    put_raw(frame, start, length, raw);
    ASSERT_EQ(frame, want) << k;
  }
}

TEST(ResolverAngleFrame, HandComputedPayload) {
  // angle 0.5 turn -> 0x800000 (bytes 00 00 80); speed -1 turn/s -> -4096 = 0xFFF000 in 24
  // bits (bytes 00 F0 FF); sequence 5 and valid in byte 6 -> 0x15; channel 2 in byte 7.
  ResolverAngleFrame f;
  f.angle_turns = 0.5;
  f.speed_turns_per_s = -1.0;
  f.sequence = 5;
  f.valid = true;
  f.channel = 2;
  const CanFrame c = encode(f);
  EXPECT_EQ(c.id, 0x120u);
  EXPECT_EQ(c.len, 8u);
  const std::uint8_t expected[8] = {0x00, 0x00, 0x80, 0x00, 0xF0, 0xFF, 0x15, 0x02};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(c.data[static_cast<std::size_t>(i)], expected[i]) << "byte " << i;
}

TEST(ResolverAngleFrame, HandComputedPayloadWithBothOpenFlags) {
  // angle 0.25 turn -> 0x400000 (bytes 00 00 40); speed 1 turn/s -> 4096 = 0x001000 (bytes
  // 00 10 00); byte 6: sequence 10 (bits 48..51) 0x0A, valid 0, sin_open (bit 53) 0x20,
  // cos_open (bit 54) 0x40 -> 0x6A; channel 15 in byte 7.
  ResolverAngleFrame f;
  f.angle_turns = 0.25;
  f.speed_turns_per_s = 1.0;
  f.sequence = 10;
  f.valid = false;
  f.sin_open = true;
  f.cos_open = true;
  f.channel = 15;
  const CanFrame c = encode(f);
  const std::uint8_t expected[8] = {0x00, 0x00, 0x40, 0x00, 0x10, 0x00, 0x6A, 0x0F};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(c.data[static_cast<std::size_t>(i)], expected[i]) << "byte " << i;
}

// encode() writes the whole payload at once; each signal is where the message's table puts it:
// the frame put_raw builds signal by signal from that table, on seeded values.
TEST(ResolverAngleFrame, EncodeIsEachSignalPutAtItsStartBit) {
  std::mt19937_64 rng(1127);
  const DbcMessage& m = resolver_angle_message();
  for (int i = 0; i < 2000; ++i) {
    ResolverAngleFrame f;
    const std::uint64_t angle = rng() & 0xFF'FFFFu;
    const auto speed = static_cast<std::int64_t>(rng() % 16'777'216U) - 8'388'608;
    f.angle_turns = static_cast<double>(angle) / 16'777'216.0;
    f.speed_turns_per_s = static_cast<double>(speed) / 4096.0;
    f.sequence = static_cast<std::uint8_t>(rng() % 16);
    f.valid = (rng() & 1U) != 0;
    f.sin_open = (rng() & 1U) != 0;
    f.cos_open = (rng() & 1U) != 0;
    f.channel = static_cast<std::uint8_t>(rng() % 16);
    const std::uint64_t raws[7] = {angle,
                                   static_cast<std::uint64_t>(speed) & 0xFF'FFFFu,
                                   f.sequence,
                                   f.valid ? 1U : 0U,
                                   f.sin_open ? 1U : 0U,
                                   f.cos_open ? 1U : 0U,
                                   f.channel};
    ASSERT_EQ(m.signals.size(), 7U);
    CanFrame want;
    want.id = kResolverAngleId;
    want.len = 8;
    for (std::size_t k = 0; k < 7; ++k) put_raw(want, m.signals[k].start_bit, m.signals[k].length, raws[k]);
    ASSERT_EQ(encode(f), want) << i;
  }
}

// The same for the edge report, with timestamps over all 48 bits.
TEST(EdgeReportFrame, EncodeIsEachSignalPutAtItsStartBit) {
  std::mt19937_64 rng(1128);
  const DbcMessage& m = edge_report_message();
  for (int i = 0; i < 2000; ++i) {
    EdgeReportFrame e;
    e.line = static_cast<std::uint8_t>(rng());
    e.level = level_of((rng() & 1U) != 0);
    e.sequence = static_cast<std::uint8_t>(rng() % 128);
    const std::uint64_t t = rng() >> 16U;
    e.timestamp = Nanos{static_cast<std::int64_t>(t)};
    const std::uint64_t raws[5] = {e.line, is_high(e.level) ? 1U : 0U, e.sequence, t >> 32U,
                                   t & 0xFFFF'FFFFu};
    ASSERT_EQ(m.signals.size(), 5U);
    CanFrame want;
    want.id = kEdgeReportId;
    want.len = 8;
    for (std::size_t k = 0; k < 5; ++k) put_raw(want, m.signals[k].start_bit, m.signals[k].length, raws[k]);
    ASSERT_EQ(encode(e), want) << i;
  }
}

TEST(ResolverAngleFrame, AngleWrapsIntoOneTurn) {
  ResolverAngleFrame f;
  f.angle_turns = -0.25; // = 0.75 turn
  EXPECT_DOUBLE_EQ(decode_resolver_angle(encode(f))->angle_turns, 0.75);
  f.angle_turns = 3.0 - 1e-12; // rounds to a full turn -> 0
  EXPECT_DOUBLE_EQ(decode_resolver_angle(encode(f))->angle_turns, 0.0);
  f.speed_turns_per_s = 1e6; // clamps to the largest speed
  EXPECT_DOUBLE_EQ(decode_resolver_angle(encode(f))->speed_turns_per_s, 2048.0 - 1.0 / 4096.0);
}

TEST(ResolverAngleFrame, SeededRoundTrip) {
  std::mt19937 rng(288);
  std::uniform_real_distribution<double> angle(0.0, 1.0);
  std::uniform_real_distribution<double> speed(-2000.0, 2000.0);
  for (int i = 0; i < 1000; ++i) {
    ResolverAngleFrame f;
    f.angle_turns = angle(rng);
    f.speed_turns_per_s = speed(rng);
    f.sequence = static_cast<std::uint8_t>(rng() % 16);
    f.channel = static_cast<std::uint8_t>(rng() % 16);
    f.valid = (rng() & 1u) != 0;
    f.sin_open = (rng() & 1u) != 0;
    f.cos_open = (rng() & 1u) != 0;
    const auto d = decode_resolver_angle(encode(f));
    ASSERT_TRUE(d.has_value());
    const double a_err = d->angle_turns - f.angle_turns;
    EXPECT_LE(std::fabs(a_err - std::round(a_err)), 0.5 / 16'777'216.0);
    EXPECT_LE(std::fabs(d->speed_turns_per_s - f.speed_turns_per_s), 0.5 / 4096.0);
    EXPECT_EQ(d->sequence, f.sequence);
    EXPECT_EQ(d->channel, f.channel);
    EXPECT_EQ(d->valid, f.valid);
    EXPECT_EQ(d->sin_open, f.sin_open);
    EXPECT_EQ(d->cos_open, f.cos_open);
    EXPECT_EQ(encode(*d), encode(f)); // a decoded frame re-encodes to the same bytes
  }
}

TEST(EdgeReportFrame, HandComputedPayload) {
  // 5 s = 5,000,000,000 ns = 0x1_2A05_F200: time_hi 1 (bytes 01 00), time_ns bytes 00 F2 05 2A.
  // line 3; level High (bit 8) and sequence 9 (bits 9..15) -> byte 1 = 1 | 9 << 1 = 0x13.
  EdgeReportFrame e;
  e.line = 3;
  e.level = Level::High;
  e.sequence = 9;
  e.timestamp = 5_s;
  const CanFrame c = encode(e);
  EXPECT_EQ(c.id, 0x130u);
  const std::uint8_t expected[8] = {0x03, 0x13, 0x01, 0x00, 0x00, 0xF2, 0x05, 0x2A};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(c.data[static_cast<std::size_t>(i)], expected[i]) << "byte " << i;
}

TEST(EdgeReportFrame, SeededRoundTripAndRange) {
  std::mt19937_64 rng(304);
  for (int i = 0; i < 1000; ++i) {
    EdgeReportFrame e;
    e.line = static_cast<std::uint8_t>(rng() % 256);
    e.level = level_of((rng() & 1u) != 0);
    e.sequence = static_cast<std::uint8_t>(rng() % 128);
    e.timestamp = Nanos{static_cast<std::int64_t>(rng() >> 16)}; // 48 bits
    const auto d = decode_edge_report(encode(e));
    ASSERT_TRUE(d.has_value());
    EXPECT_EQ(d->line, e.line);
    EXPECT_EQ(d->level, e.level);
    EXPECT_EQ(d->sequence, e.sequence);
    EXPECT_EQ(d->timestamp, e.timestamp);
  }
  EdgeReportFrame bad;
  bad.timestamp = Nanos{std::int64_t{1} << 48};
  EXPECT_THROW((void)encode(bad), std::out_of_range);
  bad.timestamp = Nanos{-1};
  EXPECT_THROW((void)encode(bad), std::out_of_range);
}

TEST(FrontendFrames, DecodersRejectOtherFrames) {
  CanFrame c = encode(ResolverAngleFrame{});
  EXPECT_FALSE(decode_edge_report(c).has_value());
  c.len = 7;
  EXPECT_FALSE(decode_resolver_angle(c).has_value());
  c = encode(ResolverAngleFrame{});
  c.extended = true;
  EXPECT_FALSE(decode_resolver_angle(c).has_value());
}

TEST(FrontendFrames, SignalsFitAndDoNotOverlap) {
  for (const DbcMessage* m : {&resolver_angle_message(), &edge_report_message()}) {
    std::uint64_t used = 0;
    for (const DbcSignal& s : m->signals) {
      ASSERT_LE(s.start_bit + s.length, m->dlc * 8u) << s.name;
      const std::uint64_t mask = (s.length == 64 ? ~0ull : ((1ull << s.length) - 1)) << s.start_bit;
      EXPECT_EQ(used & mask, 0u) << s.name;
      used |= mask;
    }
  }
}

// ---- The DBC file -------------------------------------------------------------------

struct ParsedSignal {
  DbcSignal sig;
  std::string name, unit, receiver;
};
struct ParsedMessage {
  std::uint32_t id = 0;
  std::string name, sender;
  unsigned dlc = 0;
  std::vector<ParsedSignal> signals;
};

std::string read_dbc() {
  std::ifstream in(HILRIG_SOURCE_DIR "/rt-config/can/hilrig-frontend.dbc");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::map<std::uint32_t, ParsedMessage> parse_dbc(const std::string& text) {
  const std::regex bo(R"(^BO_ (\d+) (\w+): (\d+) (\w+)\s*$)");
  const std::regex sg(
      R"re(^ SG_ (\w+) : (\d+)\|(\d+)@([01])([+-]) \(([^,]+),([^)]+)\) \[([^|]+)\|([^\]]+)\] "([^"]*)" (\w+)\s*$)re");
  std::map<std::uint32_t, ParsedMessage> out;
  ParsedMessage* current = nullptr;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    std::smatch m;
    if (std::regex_match(line, m, bo)) {
      const auto id = static_cast<std::uint32_t>(std::stoul(m[1]));
      current = &out[id];
      current->id = id;
      current->name = m[2];
      current->dlc = static_cast<unsigned>(std::stoul(m[3]));
      current->sender = m[4];
    } else if (std::regex_match(line, m, sg)) {
      EXPECT_NE(current, nullptr) << line;
      if (current == nullptr) continue;
      EXPECT_EQ(m[4], "1") << "Intel byte order expected: " << line;
      ParsedSignal p;
      p.name = m[1];
      p.unit = m[10];
      p.receiver = m[11];
      p.sig = DbcSignal{"",
                        static_cast<unsigned>(std::stoul(m[2])),
                        static_cast<unsigned>(std::stoul(m[3])),
                        m[5] == "-",
                        std::stod(m[6]),
                        std::stod(m[7]),
                        std::stod(m[8]),
                        std::stod(m[9]),
                        ""};
      current->signals.push_back(p);
    } else if (line.rfind(" SG_", 0) == 0 || line.rfind("BO_", 0) == 0) {
      ADD_FAILURE() << "unparsed DBC line: " << line;
    } else if (line.empty()) {
      current = nullptr;
    }
  }
  return out;
}

TEST(FrontendDbc, HasTheDbcSections) {
  const std::string text = read_dbc();
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.rfind("VERSION \"", 0), 0u);
  EXPECT_NE(text.find("\nNS_ :"), std::string::npos);
  EXPECT_NE(text.find("\nBS_:"), std::string::npos);
  EXPECT_NE(text.find("\nBU_: HILRIG RESOLVER_EMU CAPTURE\n"), std::string::npos);
  // Every CM_ and VAL_ statement is terminated.
  std::istringstream lines(text);
  std::string line;
  int comments = 0;
  while (std::getline(lines, line)) {
    if (line.rfind("CM_", 0) == 0 || line.rfind("VAL_", 0) == 0) {
      ++comments;
      EXPECT_EQ(line.back(), ';') << line;
    }
  }
  EXPECT_GT(comments, 10);
}

TEST(FrontendDbc, MessagesMatchTheCppLayout) {
  const auto parsed = parse_dbc(read_dbc());
  ASSERT_EQ(parsed.size(), 2u);
  for (const DbcMessage* m : {&resolver_angle_message(), &edge_report_message()}) {
    SCOPED_TRACE(std::string(m->name));
    ASSERT_EQ(parsed.count(m->id), 1u);
    const ParsedMessage& p = parsed.at(m->id);
    EXPECT_EQ(p.name, m->name);
    EXPECT_EQ(p.dlc, m->dlc);
    EXPECT_EQ(p.sender, m->sender);
    ASSERT_EQ(p.signals.size(), m->signals.size());
    for (std::size_t i = 0; i < p.signals.size(); ++i) {
      const DbcSignal& want = m->signals[i];
      const ParsedSignal& got = p.signals[i];
      SCOPED_TRACE(std::string(want.name));
      EXPECT_EQ(got.name, want.name);
      EXPECT_EQ(got.sig.start_bit, want.start_bit);
      EXPECT_EQ(got.sig.length, want.length);
      EXPECT_EQ(got.sig.is_signed, want.is_signed);
      EXPECT_DOUBLE_EQ(got.sig.factor, want.factor);
      EXPECT_DOUBLE_EQ(got.sig.offset, want.offset);
      EXPECT_DOUBLE_EQ(got.sig.minimum, want.minimum);
      EXPECT_DOUBLE_EQ(got.sig.maximum, want.maximum);
      EXPECT_EQ(got.unit, want.unit);
      EXPECT_EQ(got.receiver, m->receiver);
    }
  }
}

TEST(FrontendDbc, ADbcReaderDecodesOurFrames) {
  // Decode with the scaling read from the file, as a CAN tool would.
  const auto parsed = parse_dbc(read_dbc());
  ResolverAngleFrame f;
  f.angle_turns = 0.3;
  f.speed_turns_per_s = -12.5;
  f.sequence = 11;
  f.channel = 1;
  const CanFrame c = encode(f);
  std::map<std::string, double> v;
  for (const ParsedSignal& s : parsed.at(kResolverAngleId).signals) v[s.name] = get_physical(c, s.sig);
  EXPECT_NEAR(v["angle"], 0.3, 0.5 / 16'777'216.0);
  EXPECT_DOUBLE_EQ(v["speed"], -12.5);
  EXPECT_EQ(v["sequence"], 11.0);
  EXPECT_EQ(v["valid"], 1.0);
  EXPECT_EQ(v["channel"], 1.0);

  EdgeReportFrame e;
  e.line = 7;
  e.level = Level::High;
  e.timestamp = Nanos{123'456'789'012'345};
  const CanFrame ce = encode(e);
  std::map<std::string, double> w;
  for (const ParsedSignal& s : parsed.at(kEdgeReportId).signals) w[s.name] = get_physical(ce, s.sig);
  EXPECT_EQ(w["line"], 7.0);
  EXPECT_EQ(w["level"], 1.0);
  EXPECT_EQ(w["time_hi"] + w["time_ns"], 123'456'789'012'345.0); // exact below 2^53
}

} // namespace
} // namespace hilrig::signals
