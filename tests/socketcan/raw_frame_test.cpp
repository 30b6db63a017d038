// The conversions between CanFrame and the kernel's canfd_frame, and the one reader of a
// received frame's control messages, against linux/can.h and the socket ABI written out by
// hand: CAN_MTU = 16 and CANFD_MTU = 72 bytes, CAN_EFF_FLAG 0x80000000, CAN_RTR_FLAG
// 0x40000000, CAN_ERR_FLAG 0x20000000, CANFD_BRS 0x01, CANFD_ESI 0x02; SO_TIMESTAMPING's
// control message carries struct scm_timestamping { timespec ts[3]; } with the software stamp
// in ts[0] and the raw hardware stamp in ts[2] (Documentation/networking/timestamping.rst).
#include "drivers/socketcan/raw_frame.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <ctime>
#include <vector>

#include "tests/rt/allocation_counter.hpp"

using namespace hilrig;
using namespace hilrig::socketcan;

namespace {

constexpr std::size_t kCanMtu = 16;
constexpr std::size_t kCanFdMtu = 72;

// One received message as recvmmsg leaves it: a frame and its control messages.
struct Message {
  canfd_frame raw{};
  iovec iov{};
  alignas(cmsghdr) std::array<char, kRxControlBytes> control{};
  msghdr hdr{};

  // `stamp` as scm_timestamping.ts[0] (with a different hardware stamp in ts[2]), and a drop
  // count when `drops` >= 0.
  Message(std::int64_t sec, long nsec, long drops) {
    iov = iovec{&raw, sizeof(raw)};
    hdr.msg_iov = &iov;
    hdr.msg_iovlen = 1;
    hdr.msg_control = control.data();
    hdr.msg_controllen = control.size();
    cmsghdr* c = CMSG_FIRSTHDR(&hdr);
    c->cmsg_level = SOL_SOCKET;
    c->cmsg_type = SO_TIMESTAMPING;
    c->cmsg_len = CMSG_LEN(3 * sizeof(timespec));
    const std::array<timespec, 3> ts{timespec{sec, nsec}, timespec{0, 0}, timespec{sec + 100, 5}};
    std::memcpy(CMSG_DATA(c), ts.data(), sizeof(ts));
    std::size_t used = CMSG_SPACE(3 * sizeof(timespec));
    if (drops >= 0) {
      c = CMSG_NXTHDR(&hdr, c);
      c->cmsg_level = SOL_SOCKET;
      c->cmsg_type = SO_RXQ_OVFL;
      c->cmsg_len = CMSG_LEN(sizeof(std::uint32_t));
      const auto d = static_cast<std::uint32_t>(drops);
      std::memcpy(CMSG_DATA(c), &d, sizeof(d));
      used += CMSG_SPACE(sizeof(std::uint32_t));
    }
    hdr.msg_controllen = used; // what the kernel sets after filling it
  }
  Message(const Message&) = delete;
};

CanFrame frame(std::uint32_t id, std::uint8_t len, bool extended = false, bool fd = false) {
  CanFrame f;
  f.id = id;
  f.len = len;
  f.extended = extended;
  f.fd = fd;
  for (std::uint8_t i = 0; i < len; ++i) f.data[i] = static_cast<std::uint8_t>(0xA0 + i);
  return f;
}

} // namespace

TEST(RxControl, TheSoftwareStampAndTheDropCountAreRead) {
  const Message m(1767225600, 123'456'789, 7);
  const RxControl c = read_rx_control(m.hdr);
  EXPECT_EQ(c.timestamp, Nanos{1767225600LL * 1'000'000'000 + 123'456'789}); // ts[0], not ts[2]
  EXPECT_TRUE(c.has_drops);
  EXPECT_EQ(c.queue_drops, 7U);
}

TEST(RxControl, NoControlMessageMeansNoStampAndNoDropCount) {
  msghdr none{};
  const RxControl c = read_rx_control(none);
  EXPECT_EQ(c.timestamp, Nanos{0});
  EXPECT_FALSE(c.has_drops);
  const Message stamp_only(5, 6, -1);
  const RxControl s = read_rx_control(stamp_only.hdr);
  EXPECT_EQ(s.timestamp, Nanos{5'000'000'006});
  EXPECT_FALSE(s.has_drops);
}

// A batch from one recvmmsg: every frame keeps its own stamp and bytes, and the drop count is
// the last one the kernel reported.
TEST(ReadReceived, EachFrameOfABatchHasItsOwnTimestamp) {
  std::vector<std::unique_ptr<Message>> batch;
  for (int k = 0; k < 5; ++k) {
    batch.push_back(std::make_unique<Message>(1767225600, 1000L * k + 17, k == 3 ? 2 : (k == 4 ? 3 : -1)));
    to_raw(frame(0x100U + static_cast<std::uint32_t>(k), 8), batch.back()->raw);
  }
  std::uint32_t drops = 0;
  for (int k = 0; k < 5; ++k) {
    const CanReceived r = read_received(batch[static_cast<std::size_t>(k)]->hdr, kCanMtu, drops);
    EXPECT_EQ(r.timestamp, Nanos{1767225600LL * 1'000'000'000 + 1000L * k + 17}) << k;
    EXPECT_FALSE(r.is_error);
    EXPECT_EQ(r.frame, frame(0x100U + static_cast<std::uint32_t>(k), 8)) << k;
    EXPECT_EQ(drops, k < 3 ? 0U : (k == 3 ? 2U : 3U)) << k;
  }
}

TEST(RawFrame, ClassicFramesOfEveryLengthRoundTrip) {
  for (std::uint8_t len = 0; len <= 8; ++len) {
    for (const bool extended : {false, true}) {
      const CanFrame f = frame(extended ? 0x1ABCDEF0U : 0x7FFU, len, extended);
      canfd_frame raw{};
      ASSERT_EQ(to_raw(f, raw), kCanMtu);
      EXPECT_EQ(raw.can_id, f.id | (extended ? 0x80000000U : 0U));
      EXPECT_EQ(raw.len, len);
      const CanReceived back = from_raw(raw, kCanMtu, Nanos{42});
      EXPECT_EQ(back.frame, f) << int(len);
      EXPECT_EQ(back.timestamp, Nanos{42});
    }
  }
}

TEST(RawFrame, RemoteFrameKeepsItsFlag) {
  CanFrame f = frame(0x123, 0);
  f.rtr = true;
  canfd_frame raw{};
  to_raw(f, raw);
  EXPECT_EQ(raw.can_id, 0x123U | 0x40000000U);
  EXPECT_EQ(from_raw(raw, kCanMtu, Nanos{0}).frame, f);
}

TEST(RawFrame, FdFramesKeepLengthAndFlags) {
  for (const int n : {0, 8, 12, 16, 20, 24, 32, 48, 64}) {
    const auto len = static_cast<std::uint8_t>(n);
    CanFrame f = frame(0x18DAF110, len, true, true);
    f.brs = len % 16 == 0;
    f.esi = len == 12;
    canfd_frame raw{};
    ASSERT_EQ(to_raw(f, raw), kCanFdMtu);
    EXPECT_EQ(raw.flags, (f.brs ? 0x01 : 0) | (f.esi ? 0x02 : 0));
    EXPECT_EQ(from_raw(raw, kCanFdMtu, Nanos{0}).frame, f) << int(len);
  }
}

TEST(RawFrame, ErrorFrameIsDecodedAsAnErrorReport) {
  canfd_frame raw{};
  raw.can_id = 0x20000000U | 0x040U; // CAN_ERR_FLAG | CAN_ERR_BUSOFF
  raw.len = 8;
  const CanReceived r = from_raw(raw, kCanMtu, Nanos{9});
  EXPECT_TRUE(r.is_error);
  ASSERT_TRUE(r.error.state.has_value());
  EXPECT_EQ(*r.error.state, BusState::BusOff);
}

// The RT rule: reading a received batch allocates nothing.
TEST(ReadReceived, DoesNotAllocate) {
  const Message m(1, 2, 3);
  std::uint32_t drops = 0;
  hilrig::test::arm_allocation_counter();
  std::int64_t sum = 0;
  for (int k = 0; k < 100; ++k) sum += read_received(m.hdr, kCanMtu, drops).timestamp.count();
  const std::uint64_t allocations = hilrig::test::disarm_allocation_counter();
  EXPECT_EQ(allocations, 0U);
  EXPECT_EQ(sum, 100 * 1'000'000'002LL);
  EXPECT_EQ(drops, 3U);
}
