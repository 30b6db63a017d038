// Host actions the manuals describe, from the campaign file to the run's observations:
// negative words as PLC INTs, raw control-word writes without the Transmit handshake, and
// reads while Acknowledge is set. Expected values come from the manuals (seeds/, cited).

#include <cstdint>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "campaign_text.hpp"
#include "rig/campaign/campaign_error.hpp"
#include "rig/campaign/campaign_parser.hpp"
#include "rig/campaign/executive.hpp"
#include "test_support.hpp"

namespace hilrig::campaign {
namespace {

using test::error_of;

using namespace hilrig::literals;
using test::find;

// The 7361 with no transducer wired: host words only. Its status word 0 is %I (bit 0 =
// FMTErr %I 01, bit 15 = ACK %I 16; 7361 manual seeds/004 L2011-2048).
const std::string k7361 = R"([campaign]
name = "host-7361"
end = "20ms"
host_poll = "500us"
[dut]
model = "ssi7361"
)";

const std::string kWordCheck = R"([[check]]
kind = "word_bits"
name = "status"
observation = "status"
mask = 0xFFFF
value = 0
)";

std::string host(const std::string& body) { return "[[host]]\n" + body + "\n"; }

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("no \"" + from + "\" in the campaign");
  return text.replace(at, from.size(), to);
}

// --- negative words: a PLC INT is written as its two's complement -------------------------

TEST(HostActions, NegativeWordsAreTwosComplementAcrossTheInt16Range) {
  // A PLC INT is a 16-bit two's complement word, -32768 .. 32767 (-1 is 0xFFFF, -32768 is
  // 0x8000); the rig's words are 0 .. 0xFFFF, so both spellings meet in 0x8000 .. 0xFFFF.
  const struct {
    std::int64_t given;
    std::uint16_t word;
  } cases[] = {{-1, 0xFFFF},     {-5, 0xFFFB}, {-50, 0xFFCE},   {-32767, 0x8001},
               {-32768, 0x8000}, {0, 0},       {32767, 0x7FFF}, {65535, 0xFFFF}};
  for (const auto& c : cases) {
    const Campaign camp =
        parse_campaign(k7361 + host("at = \"1ms\"\nwrite = [0x0002, " + std::to_string(c.given) + "]") +
                           host("at = \"2ms\"\nread = 0\nname = \"status\"") + kWordCheck,
                       "t.toml");
    ASSERT_EQ(camp.points[0].host[0].words.size(), 2U);
    EXPECT_EQ(camp.points[0].host[0].words[1], c.word) << c.given;
  }
}

// 7361 manual (seeds/004_2d8564fc60a2b9d4.txt:1224-1226): presetting makes the Data Value
// equal to the Preset Value, range +-33,554,431; the Preset Value is signed 32-bit in %AQ4
// (low) / %AQ5 (high) and the Data Value comes back the same way in %AI1/%AI2 (L1980-1988,
// docs/spec/ssi7361.md §5). PrstVal (%Q 04) and AplyPst (%Q 01) in one cycle: 0x0009. -5 = words -5, -1
// (0xFFFB, 0xFFFF) and reads back the same.
TEST(HostActions, Ssi7361NegativePresetWrittenAsInts) {
  const Campaign c =
      parse_campaign(k7361 + host("at = \"1ms\"\nwrite = [0x0009, 0, 0, 0, -5, -1, 0]\nname = \"preset\"") +
                         host("at = \"5ms\"\nread = 1\nname = \"dv_low\"\nsigned = true") +
                         host("at = \"5ms\"\nread = 2\nname = \"dv_high\"") +
                         host("at = \"5ms\"\nread = 0\nname = \"status\"") + kWordCheck,
                     "t.toml");
  EXPECT_EQ(c.points[0].host[0].words[4], 0xFFFB);
  EXPECT_EQ(c.points[0].host[0].words[5], 0xFFFF);
  const rig::RunResult r = Executive(c).run(c.runs[0]).result;
  ASSERT_EQ(r.observations.size(), 3U);
  EXPECT_EQ(r.observations[0].value, -5.0);
  EXPECT_EQ(r.observations[1].value, 65535.0);
  EXPECT_EQ(r.observations[2].value, 0.0); // no error bit: -5 is within +-33,554,431 (L2166)
}

TEST(HostActions, WordsJustOutsideTheRangeAreRejectedWithTheRange) {
  for (const std::int64_t bad : {std::int64_t{-32769}, std::int64_t{-40000}, std::int64_t{65536}}) {
    const std::string e =
        error_of(k7361 + host("at = \"1ms\"\nwrite = [0x0002, " + std::to_string(bad) + "]") +
                 host("at = \"2ms\"\nread = 0\nname = \"status\"") + kWordCheck);
    EXPECT_NE(e.find("t.toml:9:"), std::string::npos) << e;
    EXPECT_NE(e.find("host[0].write: 16-bit words (-32768 .. 0xFFFF"), std::string::npos) << e;
  }
}

TEST(HostActions, WordBitsValueMayBeANegativeInt) {
  const Campaign camp = parse_campaign(k7361 + host("at = \"2ms\"\nread = 0\nname = \"status\"") +
                                           R"([[check]]
kind = "word_bits"
name = "status"
observation = "status"
mask = 0xFFFF
value = -32767
)",
                                       "t.toml");
  EXPECT_EQ(camp.points[0].checks.size(), 1U);
  EXPECT_NE(error_of(k7361 + host("at = \"2ms\"\nread = 0\nname = \"status\"") +
                     "[[check]]\nkind = \"word_bits\"\nname = \"s\"\nobservation = \"status\"\nmask = "
                     "0xFFFF\nvalue = -32769\n")
                .find("check[0].value"),
            std::string::npos);
}

// --- raw writes ---------------------------------------------------------------------------

TEST(HostActions, RawWriteIsRefusedWhereEveryWriteIsRaw) {
  // The SMD23E and the Series 2700 have no Transmit/Acknowledge handshake.
  for (const char* model : {"smd23e", "pls2700"}) {
    const std::string text = std::string("[campaign]\nname = \"r\"\nend = \"10ms\"\n[dut]\nmodel = \"") +
                             model + "\"\n" + host("at = \"1ms\"\nwrite = [0]\nraw = true") +
                             host("at = \"2ms\"\nread = 0\nname = \"status\"") + kWordCheck;
    const std::string e = error_of(text);
    EXPECT_NE(e.find("host[0].raw: no raw = true for " + std::string(model)), std::string::npos) << e;
  }
}

TEST(HostActions, RawWriteTakesNoTimeoutButMaySetTransmit) {
  EXPECT_NE(error_of(k7361 + host("at = \"1ms\"\nwrite = [0]\nraw = true\ntimeout = \"5ms\"") + kWordCheck)
                .find("host[0].timeout: no timeout on a raw write"),
            std::string::npos);
  // Raw means raw: the host may drive Transmit by hand.
  const Campaign c = parse_campaign(k7361 + host("at = \"1ms\"\nwrite = [0x8000]\nraw = true") +
                                        host("at = \"2ms\"\nread = 0\nname = \"status\"") + kWordCheck,
                                    "t.toml");
  EXPECT_TRUE(c.points[0].host[0].raw);
  EXPECT_NE(
      error_of(k7361 + host("at = \"1ms\"\nwrite = [0x8000]") + kWordCheck).find("Transmit (bit 15) clear"),
      std::string::npos);
}

// 4501 manual (seeds/001_8422c5eec3a3e376.txt:167): "Output bits 0 and 1 are not part of a
// programming cycle. These bits will be acted on immediately after being set." Bit 0 is
// Received Measurement: status bit 0 (New Measurement Value) resets (L153, spec §5.3).
// The shipped amci4501_acknowledge campaign has status 1 and a registration of 4096 at 46 ms;
// here the host acknowledges at 50 ms with a raw write of control word 0x0001 alone.
TEST(HostActions, Amci4501RawControlBit0ActsWithoutAProgrammingCycle) {
  std::string text = test::read_file(test::campaign_dir("amci4501") + "/amci4501_acknowledge.toml");
  text = replaced(text,
                  "at = \"50ms\"\nprogram = \"mode\"\nmode = 1\ntimeout_ms = 1000\nacknowledge = true\n"
                  "name = \"acknowledge_with_transmit\"",
                  "at = \"50ms\"\nwrite = [0x0001]\nraw = true\nname = \"acknowledge_raw\"");
  text = replaced(text, "at = \"52ms\"\nread = 0", "at = \"50ms\"\nread = 0");
  text = replaced(text, "at = \"52ms\"\nread = 1", "at = \"50ms\"\nread = 1");
  const Campaign c = parse_campaign(text, "t.toml");
  const rig::RunResult r = Executive(c).run(c.runs[0]).result;
  std::map<std::string, rig::Observation> seen;
  for (const auto& o : r.observations) seen[o.name] = o;
  ASSERT_TRUE(seen.contains("status_acknowledged"));
  // Acted on at once: read at the very time of the write, status 0 (bit 0 reset, and no
  // Acknowledge, bit 15, since nothing started a programming cycle).
  EXPECT_EQ(seen["status_acknowledged"].time, 50_ms);
  EXPECT_EQ(seen["status_acknowledged"].value, 0.0);
  EXPECT_EQ(seen["registration_kept"].value, 4096.0);
  EXPECT_EQ(find(r, "host.acknowledge_raw.ack"), nullptr); // no handshake measured
  ASSERT_NE(find(r, "host.mode1.ack"), nullptr);           // the handshake writes still are
}

// 4501 control bit 1, Clear Measurement Error, also without a programming cycle (L154, L167):
// a raw write that sets it keeps the mode the last programming cycle chose (control bit 3 =
// mode 3, status bit 9 = mode 3 active, L151-161, L85-110) where a handshake write of the
// same word 0 starts a programming cycle with no mode bit: mode 1 (L176), status bits 8-12 0.
TEST(HostActions, Amci4501RawClearErrorKeepsTheProgrammedMode) {
  const std::string base = R"([campaign]
name = "clear"
end = "20ms"
[dut]
model = "amci4501"
[[host]]
at = "0ms"
write = [0x0008, 1000]
name = "mode3"
[[host]]
at = "5ms"
read = 0
name = "before"
[[host]]
at = "6ms"
write = [0x0002]
)";
  const std::string tail = R"([[host]]
at = "10ms"
read = 0
name = "after"
[[check]]
kind = "word_bits"
name = "mode"
observation = "after"
mask = 0x1F00
value = 0x0200
)";
  const auto after = [&](const std::string& how) {
    const Campaign c = parse_campaign(base + how + tail, "t.toml");
    const rig::RunResult r = Executive(c).run(c.runs[0]).result;
    for (const auto& o : r.observations)
      if (o.name == "after") return static_cast<std::uint16_t>(o.value);
    return std::uint16_t{0xDEAD};
  };
  EXPECT_EQ(after("raw = true\n") & 0x1F00, 0x0200);
  EXPECT_EQ(after("") & 0x1F00, 0x0000);
}

// --- reads while Acknowledge is set -------------------------------------------------------

TEST(HostActions, ReadWhileAcknowledgedIsRefusedWhereItCannotApply) {
  EXPECT_NE(error_of(std::string("[campaign]\nname = \"r\"\nend = \"10ms\"\n[dut]\nmodel = \"smd23e\"\n") +
                     host("at = \"1ms\"\nwrite = [0]") +
                     host("read = 0\nname = \"status\"\nwhile_acknowledged = true") + kWordCheck)
                .find("host[1].while_acknowledged: no while_acknowledged for smd23e"),
            std::string::npos);
  EXPECT_NE(error_of(k7361 + host("read = 0\nname = \"status\"\nwhile_acknowledged = true") + kWordCheck)
                .find("host[0].while_acknowledged: a [[host]] write with the handshake"),
            std::string::npos);
  EXPECT_NE(error_of(k7361 + host("at = \"1ms\"\nwrite = [0x0001]\nraw = true") +
                     host("read = 0\nname = \"status\"\nwhile_acknowledged = true") + kWordCheck)
                .find("host[1].while_acknowledged: a [[host]] write with the handshake"),
            std::string::npos);
  EXPECT_NE(error_of(k7361 + host("at = \"1ms\"\nwrite = [0x0001]") +
                     host("at = \"1ms\"\nread = 0\nname = \"status\"\nwhile_acknowledged = true") +
                     kWordCheck)
                .find("host[1].at: no at with while_acknowledged"),
            std::string::npos);
}

// 7361 manual (seeds/004_2d8564fc60a2b9d4.txt:1298-1299): "Once you see the Acknowledge Bit
// set, check for any errors. The error bits are guaranteed valid while the Acknowledge Bit is
// set." A cycle with Format word 0x0101 (N = 1, outside 2..25: FMTErr, %I 01, L2011-2048)
// and RUT 0 (RUTErr, %I 04) reports FMTErr first (the shipped ssi7361_faults error_order).
// Read while Acknowledge is set: ACK (%I 16 = bit 15) and FMTErr (bit 0): 0x8001. Read
// after the handshake, the ACK bit has dropped (L2047-2048).
TEST(HostActions, Ssi7361ErrorBitsReadWhileAcknowledgeIsSet) {
  const Campaign c = parse_campaign(
      k7361 + host("at = \"1ms\"\nwrite = [0x0012, 0x0101, 0, 0, 0, 0, 0]\nname = \"bad_format\"") +
          host("read = 0\nname = \"status\"\nwhile_acknowledged = true") +
          host("read = 1\nname = \"dv_low\"\nwhile_acknowledged = true") +
          host("at = \"1ms\"\nread = 0\nname = \"status_after\"") + kWordCheck,
      "t.toml");
  const rig::RunResult r = Executive(c).run(c.runs[0]).result;
  ASSERT_EQ(r.observations.size(), 3U);
  const auto* ack = find(r, "host.bad_format.ack");
  ASSERT_NE(ack, nullptr);
  EXPECT_EQ(ack->outcome, rig::Outcome::Pass);
  // Transmit set at 1 ms, Acknowledge seen at the first poll 500 us later: both reads then.
  EXPECT_EQ(r.observations[0].name, "status");
  EXPECT_EQ(r.observations[0].time, 1500_us);
  EXPECT_EQ(static_cast<std::uint16_t>(r.observations[0].value), 0x8001);
  EXPECT_EQ(r.observations[1].name, "dv_low");
  EXPECT_EQ(r.observations[1].time, 1500_us);
  // After Transmit is cleared (1.5 ms) the module drops ACK (seen at 2 ms); the next read
  // follows the handshake.
  EXPECT_EQ(r.observations[2].name, "status_after");
  EXPECT_EQ(r.observations[2].time, 2_ms);
  EXPECT_EQ(static_cast<std::uint16_t>(r.observations[2].value) & 0x8000, 0);
}

// Acknowledge never comes: the handshake fails and its reads are lost with it, so a check on
// them judges nothing (an error), never a pass on a stale word.
TEST(HostActions, ReadWhileAcknowledgedIsLostWhenAcknowledgeNeverComes) {
  const std::string pls = replaced(test::kPlsCampaign, "model = \"reference_pls\"\n",
                                   "model = \"reference_pls\"\nvariant = \"no-ack\"\n");
  const Campaign c =
      parse_campaign(pls + host("at = \"1ms\"\nwrite = [0x0001]\nname = \"w\"\ntimeout = \"2ms\"") +
                         host("read = 0\nname = \"status\"\nwhile_acknowledged = true"),
                     "t.toml");
  const rig::RunResult r = Executive(c).run(c.runs[0]).result;
  EXPECT_TRUE(r.observations.empty());
  const auto* ack = find(r, "host.w.ack");
  ASSERT_NE(ack, nullptr);
  EXPECT_EQ(ack->outcome, rig::Outcome::Fail);
}

// A host action starts at its time or when the handshake before it has finished
// (docs/campaigns.md, [[host]]): a read the rig itself postponed past a word check's at_ms
// judged nothing (an error), not a word the board left missing (a fail). The write at 1 ms
// holds the host until 2 ms (Acknowledge seen at 1.5 ms, its drop at 2 ms, as above).
TEST(HostActions, AReadTheHandshakeDeferredPastAtMsIsNotJudged) {
  const auto within = [](const std::string& name, const std::string& observation, const std::string& at_ms) {
    return "[[check]]\nkind = \"word_within\"\nname = \"" + name + "\"\nobservation = \"" + observation +
           "\"\nlower = 0\nat_ms = " + at_ms + "\n";
  };
  const Campaign c = parse_campaign(
      k7361 + host("at = \"1ms\"\nwrite = [0x0012, 0x0101, 0, 0, 0, 0, 0]\nname = \"bad_format\"") +
          host("read = 0\nname = \"status\"\nwhile_acknowledged = true") +
          host("at = \"1ms\"\nread = 0\nname = \"status_after\"") + within("due", "status_after", "1.0") +
          within("one_ns_early", "status_after", "1.999999") + within("made", "status_after", "2.0") +
          within("in_handshake", "status", "1.0") + within("acknowledged", "status", "1.5"),
      "t.toml");
  const rig::RunResult r = Executive(c).run(c.runs[0]).result;
  ASSERT_EQ(r.observations.size(), 2U);
  ASSERT_EQ(r.observations[1].name, "status_after");
  ASSERT_EQ(r.observations[1].time, 2_ms);
  for (const char* name : {"due", "one_ns_early", "in_handshake"}) {
    const auto* m = find(r, name);
    ASSERT_NE(m, nullptr) << name;
    EXPECT_EQ(m->outcome, rig::Outcome::Error) << name;
    EXPECT_NE(m->detail.find("not judged: the rig made read"), std::string::npos) << m->detail;
  }
  EXPECT_NE(find(r, "due")->detail.find("'status_after' at 2000000 ns, after at_ms 1000000 ns"),
            std::string::npos)
      << find(r, "due")->detail;
  // At the instant the rig made the read the word is judged, as before.
  for (const char* name : {"made", "acknowledged"}) {
    const auto* m = find(r, name);
    ASSERT_NE(m, nullptr) << name;
    EXPECT_EQ(m->outcome, rig::Outcome::Pass) << name << ": " << m->detail;
  }
}

// --- block-transfer writes of a bad length (Series 2700) ----------------------------------

// A 2731 turned by its resolver at 300 rpm (no transducer fault, so a BTW is not ignored with
// 24h, L1413); output word 0 sends the first n buffer words as one BTW and input word 5 is the
// programming error byte (models/pls2700/README.md, campaign adapter).
std::string pls2700_btw(const std::string& write) {
  return R"([campaign]
name = "btw"
end = "20ms"
[dut]
model = "pls2700"
[dut.params]
model = "2731"
[[wiring]]
rig = "res.sin"
board = "SIN1"
[[wiring]]
rig = "res.cos"
board = "COS1"
[resolver]
sin = "res.sin"
cos = "res.cos"
excitation_hz = 5000
ratio = 1.0
phase_deg = 90
[encoder]
lines = 1024
[motion]
[[motion.move]]
kind = "constant"
speed_rpm = 300
duration = "20ms"
[[host]]
at = "5ms"
)" + write +
         R"(
[[host]]
at = "6ms"
read = 5
name = "error_byte"
[[check]]
kind = "word_bits"
name = "error"
observation = "error_byte"
mask = 0xFF
value = 0
)";
}

std::uint16_t error_byte_after(const std::string& write) {
  const Campaign c = parse_campaign(pls2700_btw(write), "t.toml");
  const rig::RunResult r = Executive(c).run(c.runs[0]).result;
  for (const auto& o : r.observations)
    if (o.name == "error_byte") return static_cast<std::uint16_t>(o.value);
  return 0xDEAD;
}

// pls2700 manual (seeds/002_46e90574ec92805f.txt): Transducer 1 Setup 8801h carries one data
// word, the Scale Factor (0360h BCD = 360, L1366-1369).
//   L1412: too short a length, "the final instruction ... does not contain enough data
//          words": 22h Invalid Message Length.
//   L1411: too long, "a Transducer 1 Setup instruction specifies three new parameters and four
//          are included. The fourth ... will be interpreted as a command word": 21h.
//   L1269: length 0 is only for 64 words; otherwise "the module will issue an error message":
//          the words past those written are 0000h, "a Command Word of 0000h": 21h (L1411).
TEST(HostActions, Pls2700BtwOfABadLengthGetsTheModulesError) {
  EXPECT_EQ(error_byte_after("write = [2, 0x8801, 0x0360]"), 0x00); // exact: accepted (L1410)
  EXPECT_EQ(error_byte_after("write = [1, 0x8801, 0x0360]"), 0x22); // one word short
  EXPECT_EQ(error_byte_after("write = [3, 0x8801, 0x0360]"), 0x21); // one word long: 0000h
  EXPECT_EQ(error_byte_after("write = [3, 0x8801, 0x0360, 0x0360]"), 0x21);
  EXPECT_EQ(error_byte_after("write = [0, 0x8801, 0x0360]"), 0x21); // 0 without 64 words
}

TEST(HostActions, Pls2700BtwLengthPastTheFileIsRefused) {
  EXPECT_EQ(error_of(pls2700_btw("write = [64, 0x8400]")), "accepted");
  const std::string e = error_of(pls2700_btw("write = [65, 0x8400]"));
  EXPECT_NE(e.find("host[0].write: word 0 the block-transfer length of pls2700: 0 .. 64 (0 = all 64 words)"),
            std::string::npos)
      << e;
}

// Input words a module has, by model: a one-channel module's BTR is words 0..2 and a
// two-channel one's 0..4 (L1260); the single-transfer position word (input word 6) is the
// 2731-04's only (L433, L1318; the 2732-04 has none, L437). Reading a word the module lacks is
// bad input, named, as `hilrig serve` answers it with Illegal Data Address; each model's last
// word and the one past it.
TEST(HostActions, Pls2700ReadsOnlyTheWordsItsModelHas) {
  const auto reading = [](const std::string& model, int word) {
    std::string text = pls2700_btw("write = [2, 0x8801, 0x0360]");
    text = replaced(text, "model = \"2731\"", "model = \"" + model + "\"");
    return error_of(replaced(text, "read = 5", "read = " + std::to_string(word)));
  };
  for (const char* one : {"2731", "2731-04", "2741"}) {
    SCOPED_TRACE(one);
    EXPECT_EQ(reading(one, 2), "accepted");
    EXPECT_NE(reading(one, 3).find("host[1].read: no input word 3 on the " + std::string(one) +
                                   ": its block transfer read is words 0 .. 2 (L1260)"),
              std::string::npos)
        << reading(one, 3);
    EXPECT_NE(reading(one, 4).find("no input word 4"), std::string::npos);
  }
  for (const char* two : {"2732", "2732-04", "2742", "2742-18"}) {
    SCOPED_TRACE(two);
    EXPECT_EQ(reading(two, 4), "accepted");
    EXPECT_EQ(reading(two, 5), "accepted"); // the error byte, every model
  }
  EXPECT_EQ(reading("2731-04", 6), "accepted");
  for (const char* model : {"2731", "2732", "2732-04", "2741", "2742", "2742-18"}) {
    SCOPED_TRACE(model);
    EXPECT_NE(reading(model, 6).find("host[1].read: no input word 6 on the " + std::string(model) +
                                     ": the single-transfer position word is the 2731-04's only"),
              std::string::npos)
        << reading(model, 6);
  }
}

} // namespace
} // namespace hilrig::campaign
