#include "drivers/virtual/can_bus.hpp"

#include <gtest/gtest.h>

#include <vector>

using namespace hilrig;
using namespace hilrig::literals;
using namespace hilrig::virt;

namespace {

CanFrame make(std::uint32_t id, std::vector<std::uint8_t> bytes = {}, bool extended = false) {
  CanFrame f;
  f.id = id;
  f.extended = extended;
  f.len = static_cast<std::uint8_t>(bytes.size());
  for (std::size_t i = 0; i < bytes.size(); ++i) f.data[i] = bytes[i];
  return f;
}

struct Received {
  CanFrame frame;
  Nanos time;
};

struct Listener {
  std::vector<Received> got;
  void attach(CanPort& port) {
    port.on_receive([this](const CanFrame& f, Nanos t) { got.push_back({f, t}); });
  }
  [[nodiscard]] std::vector<std::uint32_t> ids() const {
    std::vector<std::uint32_t> v;
    for (const auto& r : got) v.push_back(r.frame.id);
    return v;
  }
};

// 500 kbit/s: one bit is 2 us. ID 0x000 with no data is 53 bits on the wire (hand count in
// can_bits_test.cpp: 34 zeros + 6 stuff bits + 13), so 106 us, received at the end of its EOF
// 3 bits (6 us) earlier, at 100 us after SOF.
const CanBitTiming k500k{500'000, 2'000'000};
constexpr Nanos kBit = 2_us;

Nanos duration_of(const CanFrame& f) { return can_frame_duration(can_frame_bits(f), k500k); }

} // namespace

TEST(CanBus, DeliversToEveryOtherNodeAtEndOfFrame) {
  Scheduler s;
  TraceRecorder trace;
  CanBus bus(s, "can0", k500k, &trace);
  CanPort& a = bus.attach("a");
  Listener la;
  Listener lb;
  Listener lc;
  la.attach(a);
  lb.attach(bus.attach("b"));
  lc.attach(bus.attach("c"));
  a.send(make(0x000));
  s.run_until_idle();
  EXPECT_TRUE(la.got.empty()); // the sender does not receive its own frame
  ASSERT_EQ(lb.got.size(), 1U);
  ASSERT_EQ(lc.got.size(), 1U);
  EXPECT_EQ(lb.got[0].time, 100_us);
  EXPECT_EQ(lc.got[0].time, 100_us);
  EXPECT_EQ(lb.got[0].frame, make(0x000));
  EXPECT_EQ(s.now(), 106_us); // the bus was busy until the end of the intermission
  ASSERT_EQ(trace.can_frames().size(), 1U);
  EXPECT_EQ(trace.can_frames()[0].bus, "can0");
  EXPECT_EQ(trace.can_frames()[0].time, 100_us);
  EXPECT_EQ(bus.frames_delivered(), 1U);
}

TEST(CanBus, FdFrameUsesTheDataBitrate) {
  // ID 0x555, BRS, 16 x 0x55 at 500k/2M: 140 us (hand count in can_bits_test.cpp); received
  // 3 nominal bits (6 us) before its end: 134 us.
  Scheduler s;
  CanBus bus(s, "can0", k500k, nullptr);
  CanPort& a = bus.attach("a");
  Listener lb;
  lb.attach(bus.attach("b"));
  CanFrame f = make(0x555);
  f.fd = true;
  f.brs = true;
  f.len = 16;
  f.data.fill(0x55);
  a.send(f);
  s.run_until_idle();
  ASSERT_EQ(lb.got.size(), 1U);
  EXPECT_EQ(lb.got[0].time, 134_us);
  EXPECT_EQ(lb.got[0].frame, f);
}

TEST(CanBus, ArbitrationPicksTheLowestIdentifier) {
  Scheduler s;
  CanBus bus(s, "can0", k500k, nullptr);
  CanPort& a = bus.attach("a");
  CanPort& b = bus.attach("b");
  CanPort& c = bus.attach("c");
  Listener l;
  l.attach(bus.attach("monitor"));
  a.send(make(0x300));
  b.send(make(0x100));
  c.send(make(0x200));
  s.run_until_idle();
  EXPECT_EQ(l.ids(), (std::vector<std::uint32_t>{0x100, 0x200, 0x300}));
  // Back to back: each loser starts at the previous frame's end of intermission.
  const Nanos d1 = duration_of(make(0x100));
  const Nanos d2 = duration_of(make(0x200));
  const Nanos d3 = duration_of(make(0x300));
  EXPECT_EQ(l.got[0].time, d1 - 3 * kBit);
  EXPECT_EQ(l.got[1].time, d1 + d2 - 3 * kBit);
  EXPECT_EQ(l.got[2].time, d1 + d2 + d3 - 3 * kBit);
}

TEST(CanBus, StandardBeatsExtendedAndDataBeatsRemote) {
  Scheduler s;
  CanBus bus(s, "can0", k500k, nullptr);
  CanPort& a = bus.attach("a");
  CanPort& b = bus.attach("b");
  CanPort& c = bus.attach("c");
  Listener l;
  l.attach(bus.attach("monitor"));
  // Same base ID 0x123 three ways, queued in the order that loses if order decided.
  a.send(make(0x123U << 18, {}, true)); // extended: SRR and IDE recessive
  CanFrame remote = make(0x123);
  remote.rtr = true;
  b.send(remote);      // standard remote: RTR recessive, IDE dominant
  c.send(make(0x123)); // standard data: RTR and IDE dominant
  s.run_until_idle();
  ASSERT_EQ(l.got.size(), 3U);
  EXPECT_FALSE(l.got[0].frame.rtr);
  EXPECT_FALSE(l.got[0].frame.extended);
  EXPECT_TRUE(l.got[1].frame.rtr);
  EXPECT_TRUE(l.got[2].frame.extended);
}

TEST(CanBus, ExtendedIdsArbitrateOnTheFull29Bits) {
  Scheduler s;
  CanBus bus(s, "can0", k500k, nullptr);
  CanPort& a = bus.attach("a");
  CanPort& b = bus.attach("b");
  Listener l;
  l.attach(bus.attach("monitor"));
  a.send(make(0x18FF50E6, {}, true));
  b.send(make(0x18FF50E5, {}, true));
  s.run_until_idle();
  EXPECT_EQ(l.ids(), (std::vector<std::uint32_t>{0x18FF50E5, 0x18FF50E6}));
}

TEST(CanBus, FramesQueuedDuringATransmissionArbitrateAfterIt) {
  Scheduler s;
  CanBus bus(s, "can0", k500k, nullptr);
  CanPort& a = bus.attach("a");
  CanPort& b = bus.attach("b");
  CanPort& c = bus.attach("c");
  Listener l;
  l.attach(bus.attach("monitor"));
  a.send(make(0x400));
  // Higher-priority frames arriving mid-frame cannot pre-empt it; they go next, by ID.
  s.at(10_us, [&] {
    c.send(make(0x060));
    b.send(make(0x050));
  });
  s.run_until_idle();
  EXPECT_EQ(l.ids(), (std::vector<std::uint32_t>{0x400, 0x050, 0x060}));
  EXPECT_EQ(l.got[1].time, duration_of(make(0x400)) + duration_of(make(0x050)) - 3 * kBit);
}

TEST(CanBus, NodeQueueIsFirstInFirstOut) {
  Scheduler s;
  CanBus bus(s, "can0", k500k, nullptr);
  CanPort& a = bus.attach("a");
  Listener l;
  l.attach(bus.attach("b"));
  a.send(make(0x300));
  a.send(make(0x100));
  s.run_until_idle();
  EXPECT_EQ(l.ids(), (std::vector<std::uint32_t>{0x300, 0x100}));
}

TEST(CanBus, ErrorFrameThenAutomaticRetransmission) {
  Scheduler s;
  TraceRecorder trace;
  CanBus bus(s, "can0", k500k, &trace);
  CanPort& a = bus.attach("a");
  Listener l;
  l.attach(bus.attach("b"));
  int attempts = 0;
  bus.set_error([&](const CanFrame&) { return ++attempts == 1; });
  a.send(make(0x000));
  s.run_until_idle();
  // Attempt 1: 53 - 10 (EOF + IFS) = 43 bits to the ACK delimiter = 86 us, then the error
  // frame 6 + 8 + 3 = 17 bits = 34 us -> bus idle at 120 us. Attempt 2 at 120 us is received
  // 50 bits (100 us) later: 220 us.
  EXPECT_EQ(attempts, 2);
  ASSERT_EQ(l.got.size(), 1U);
  EXPECT_EQ(l.got[0].time, 220_us);
  EXPECT_EQ(bus.error_frames(), 1U);
  EXPECT_EQ(bus.frames_delivered(), 1U);
  EXPECT_EQ(trace.can_frames().size(), 1U);
  EXPECT_EQ(bus.transmit_errors(a), 7U); // +8 for the error, -1 for the success
}

TEST(CanBus, PersistentErrorsTakeTheSenderBusOff) {
  Scheduler s;
  CanBus bus(s, "can0", k500k, nullptr);
  CanPort& a = bus.attach("a");
  Listener l;
  l.attach(bus.attach("b"));
  bus.set_error([](const CanFrame& f) { return f.id == 0x0AA; });
  a.send(make(0x0AA));
  a.send(make(0x0AB));
  s.run_until_idle();
  // 32 errors x 8 = 256 > 255: bus-off, the queue (0x0AB too) is dropped, sends are ignored.
  EXPECT_EQ(bus.error_frames(), 32U);
  EXPECT_TRUE(bus.bus_off(a));
  a.send(make(0x001));
  s.run_until_idle();
  EXPECT_TRUE(l.got.empty());
}

TEST(CanBus, FrameLossDropsButTakesBusTime) {
  Scheduler s;
  TraceRecorder trace;
  CanBus bus(s, "can0", k500k, &trace);
  CanPort& a = bus.attach("a");
  Listener l;
  l.attach(bus.attach("b"));
  int seen = 0;
  bus.set_drop([&](const CanFrame&) { return ++seen == 1; });
  a.send(make(0x000, {}));
  a.send(make(0x000, {}));
  s.run_until_idle();
  // The first frame occupies 0..106 us and is lost; the second is received at 106 + 100 us.
  ASSERT_EQ(l.got.size(), 1U);
  EXPECT_EQ(l.got[0].time, 206_us);
  EXPECT_EQ(bus.frames_dropped(), 1U);
  EXPECT_EQ(bus.frames_delivered(), 1U);
  EXPECT_EQ(trace.can_frames().size(), 1U);
}

TEST(CanBus, AReceiverCanAnswerFromItsHandler) {
  Scheduler s;
  CanBus bus(s, "can0", k500k, nullptr);
  CanPort& host = bus.attach("host");
  CanPort& node = bus.attach("node");
  node.on_receive([&](const CanFrame& f, Nanos) {
    if (f.id == 0x000) node.send(make(0x001, {0x42}));
  });
  Listener l;
  l.attach(host);
  host.send(make(0x000));
  s.run_until_idle();
  ASSERT_EQ(l.got.size(), 1U);
  EXPECT_EQ(l.got[0].frame, make(0x001, {0x42}));
  // The answer starts when the request's intermission ends (106 us).
  EXPECT_EQ(l.got[0].time, 106_us + duration_of(make(0x001, {0x42})) - 3 * kBit);
}

TEST(CanBus, InvalidFrameIsRejectedAtSend) {
  Scheduler s;
  CanBus bus(s, "can0", k500k, nullptr);
  CanPort& a = bus.attach("a");
  CanFrame f = make(0x100);
  f.len = 9;
  EXPECT_THROW(a.send(f), std::invalid_argument);
}
