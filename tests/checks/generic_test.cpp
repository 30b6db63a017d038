#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "check_test_support.hpp"
#include "rig/checks/frames.hpp"
#include "rig/checks/pulse_width.hpp"
#include "rig/checks/word_bits.hpp"
#include "rig/checks/words.hpp"

namespace hilrig::checks {
namespace {

using namespace hilrig::literals;
using test::find;

// High pulses 0..10 us and 20..25 us; a third starts at 40 us and never ends.
const std::vector<Edge> kLine{{0_us, Level::High},
                              {10_us, Level::Low},
                              {20_us, Level::High},
                              {25_us, Level::Low},
                              {40_us, Level::High}};

TEST(PulseWidth, ShortestAndLongestWorkedByHand) {
  const auto r = check_pulse_width(kLine, {.name = "p", .min = 5_us, .max = 10_us});
  EXPECT_EQ(r.outcome(), rig::Outcome::Pass);
  EXPECT_EQ(find(r, "p.count").value, 2.0);
  EXPECT_EQ(find(r, "p.shortest").value, 5.0);
  EXPECT_EQ(find(r, "p.longest").value, 10.0);
  EXPECT_EQ(find(r, "p.shortest").window->begin, 20_us);
  // Low pulses: 10..20 and 25..40 us.
  const auto low = check_pulse_width(kLine, {.name = "l", .level = Level::Low});
  EXPECT_EQ(find(low, "l.shortest").value, 10.0);
  EXPECT_EQ(find(low, "l.longest").value, 15.0);
}

TEST(PulseWidth, FailsOneNanosecondBeyondEitherLimit) {
  EXPECT_EQ(check_pulse_width(kLine, {.name = "p", .min = 5_us + 1_ns}).outcome(), rig::Outcome::Fail);
  EXPECT_EQ(check_pulse_width(kLine, {.name = "p", .max = 10_us - 1_ns}).outcome(), rig::Outcome::Fail);
  const std::vector<Edge> none{};
  const auto r = check_pulse_width(none, {.name = "p"});
  EXPECT_EQ(r.outcome(), rig::Outcome::Fail);
  EXPECT_NE(find(r, "p.count").detail.find("missing edge"), std::string::npos);
  // A pulse still open when the capture ends is cut, not missing: nothing judged.
  const std::vector<Edge> open{{0_us, Level::High}};
  EXPECT_EQ(check_pulse_width(open, {.name = "p"}).outcome(), rig::Outcome::Error);
}

const std::vector<rig::Observation> kWords{
    {"da19.w6", 150.0, "ms", 10_ms}, {"da19.w6", 151.0, "ms", 20_ms}, {"status", 4.0, "", 5_ms}};

TEST(Words, EqualsJudgesTheLatestObservation) {
  EXPECT_EQ(check_word_equals(kWords, {.name = "w", .observation = "da19.w6"}, 151.0).outcome(),
            rig::Outcome::Pass);
  EXPECT_EQ(check_word_equals(kWords, {.name = "w", .observation = "da19.w6"}, 150.0).outcome(),
            rig::Outcome::Fail);
  // At 15 ms the latest is the 150 read at 10 ms.
  EXPECT_EQ(check_word_equals(kWords, {.name = "w", .observation = "da19.w6", .at = 15_ms}, 150.0).outcome(),
            rig::Outcome::Pass);
}

TEST(Words, WithinPassesAtTheLimitsAndFailsOneUnitBeyond) {
  EXPECT_EQ(
      check_word_within(kWords, {.name = "w", .observation = "status", .lower = 4.0, .upper = 4.0}).outcome(),
      rig::Outcome::Pass);
  EXPECT_EQ(check_word_within(kWords, {.name = "w", .observation = "status", .upper = 3.0}).outcome(),
            rig::Outcome::Fail);
  EXPECT_EQ(check_word_within(kWords, {.name = "w", .observation = "status", .lower = 5.0}).outcome(),
            rig::Outcome::Fail);
  const auto r = check_word_within(kWords, {.name = "w", .observation = "absent", .lower = 0.0});
  EXPECT_EQ(r.outcome(), rig::Outcome::Fail);
  EXPECT_NE(find(r, "w").detail.find("missing word"), std::string::npos);
}

TEST(Words, AValueThatIsNotANumberCannotBeJudged) {
  const std::vector<rig::Observation> nan{{"w", std::numeric_limits<double>::quiet_NaN(), "", 1_ms}};
  EXPECT_EQ(check_word_within(nan, {.name = "w", .observation = "w", .lower = 0.0}).outcome(),
            rig::Outcome::Error);
}

// A host action starts at its time or when the handshake before it has finished
// (docs/campaigns.md, [[host]]). The read below was due at 10.45 ms and made at 11.35 ms.
TEST(Words, AReadTheRigMadeAfterAtMsThoughDueByThenIsNotJudged) {
  const std::vector<rig::Observation> late{{"w1", 7.0, "", 11'350'000_ns, 10'450'000_ns}};
  const auto spec = [](Nanos at) {
    return WordSpec{.name = "c", .observation = "w1", .lower = 0.0, .at = at};
  };
  // Due at at_ms, or one ns before the read: the rig read late, nothing judged, in every kind.
  for (const Nanos at : {10'450'000_ns, 11'349'999_ns}) {
    const auto r = check_word_within(late, spec(at));
    EXPECT_EQ(r.outcome(), rig::Outcome::Error);
    EXPECT_NE(find(r, "c").detail.find("not judged: the rig made read 'w1' at 11350000 ns, after at_ms"),
              std::string::npos)
        << find(r, "c").detail;
    EXPECT_EQ(check_word_equals(late, spec(at), 7.0).outcome(), rig::Outcome::Error);
    EXPECT_EQ(check_word_bits(late, spec(at), 0xFFFF, 7).outcome(), rig::Outcome::Error);
  }
  // At the read itself (and after it) the word is judged, as before.
  EXPECT_EQ(check_word_within(late, spec(11'350'000_ns)).outcome(), rig::Outcome::Pass);
  EXPECT_EQ(check_word_equals(late, spec(11'350'001_ns), 8.0).outcome(), rig::Outcome::Fail);
  // Not due by at_ms (made on time, at_ms 1 ns before it; or due 1 ns after at_ms): still a
  // missing word, and so is a read with no due time known.
  const std::vector<rig::Observation> on_time{{"w1", 7.0, "", 11'350'000_ns, 11'350'000_ns}};
  const std::vector<rig::Observation> unknown{{"w1", 7.0, "", 11'350'000_ns}};
  const std::vector<rig::Observation> due_after{{"w1", 7.0, "", 11'350'000_ns, 10'450'001_ns}};
  for (const auto* obs : {&on_time, &unknown}) {
    const auto r = check_word_within(*obs, spec(11'349'999_ns));
    EXPECT_EQ(r.outcome(), rig::Outcome::Fail);
    EXPECT_NE(find(r, "c").detail.find("missing word"), std::string::npos);
  }
  EXPECT_EQ(check_word_within(due_after, spec(10'450'000_ns)).outcome(), rig::Outcome::Fail);
  // A read never made (the board never acknowledged the write before it) stays a fail.
  EXPECT_EQ(check_word_bits({}, spec(10'450'000_ns), 0xFFFF, 7).outcome(), rig::Outcome::Fail);
}

TEST(Frames, EveryFrameDecodesOrTheFirstErrorIsNamed) {
  // A decoder that calls a first byte of 0xFF a "crc" error.
  const FrameDecoder decode = [](const RawFrame& f) {
    return !f.bytes.empty() && f.bytes[0] == 0xFF ? std::string("crc") : std::string();
  };
  std::vector<RawFrame> frames{{1_ms, 0x181, {0x01, 0x02}}, {2_ms, 0x181, {0x03}}, {3_ms, 0x281, {0xFF}}};
  auto r = check_frames_decode(frames, decode, {.name = "can"});
  EXPECT_EQ(find(r, "can.frames").value, 3.0);
  EXPECT_EQ(find(r, "can.errors").value, 1.0);
  EXPECT_EQ(r.outcome(), rig::Outcome::Fail);
  EXPECT_NE(find(r, "can.errors").detail.find("0x281 at 3000000 ns: crc"), std::string::npos);
  r = check_frames_decode(frames, decode, {.name = "can", .id = 0x181U});
  EXPECT_EQ(r.outcome(), rig::Outcome::Pass);
  EXPECT_EQ(find(r, "can.frames").value, 2.0);
  r = check_frames_decode({}, decode, {.name = "can"});
  EXPECT_EQ(find(r, "can.frames").outcome, rig::Outcome::Fail);
}

} // namespace
} // namespace hilrig::checks
