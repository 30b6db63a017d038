// SocketCAN backend on the guest's vcan0 (CAN FD capable) and can0/can1, two SJA1000
// boards on one QEMU CAN bus at 500 kbit/s.
#include <gtest/gtest.h>

#include <array>
#include <cerrno>
#include <ctime>
#include <vector>

#include "core/candump.hpp"
#include "core/clock.hpp"
#include "drivers/socketcan/can_socket.hpp"
#include "tests/rt/allocation_counter.hpp"

using namespace hilrig;
using namespace hilrig::socketcan;

namespace {

CanFrame classic(std::uint32_t id, std::initializer_list<std::uint8_t> bytes, bool extended = false) {
  CanFrame f;
  f.id = id;
  f.extended = extended;
  f.len = static_cast<std::uint8_t>(bytes.size());
  std::copy(bytes.begin(), bytes.end(), f.data.begin());
  return f;
}

Nanos realtime_now() {
  timespec ts{};
  clock_gettime(CLOCK_REALTIME, &ts);
  return Nanos{static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec};
}

Nanos soon() { return MonotonicClock{}.now() + milliseconds(100); }

} // namespace

TEST(SocketCan, FrameOnVcanArrivesWithAKernelTimestamp) {
  CanSocket rx("vcan0");
  CanSocket tx("vcan0");
  const Nanos before = realtime_now();
  ASSERT_EQ(tx.send(classic(0x123, {0xDE, 0xAD, 0xBE, 0xEF}), soon()), SendStatus::Sent);
  const auto got = rx.receive(seconds(1));
  ASSERT_TRUE(got.has_value());
  EXPECT_FALSE(got->is_error);
  EXPECT_EQ(got->frame, classic(0x123, {0xDE, 0xAD, 0xBE, 0xEF}));
  EXPECT_GE(got->timestamp, before);
  EXPECT_LE(got->timestamp, realtime_now());
  EXPECT_NE(candump_line(got->timestamp, "vcan0", got->frame).find("vcan0 123#DEADBEEF"), std::string::npos);
}

// A burst sent a batch per sendmmsg arrives whole and in order, read a batch per recvmmsg,
// each frame with its own kernel stamp (non-decreasing, between the send and the read).
TEST(SocketCan, BatchedFramesArriveInOrderEachWithItsOwnTimestamp) {
  CanSocket rx("vcan0");
  CanSocket tx("vcan0");
  constexpr std::size_t kFrames = 3 * CanSocket::kBatch + 5;
  std::vector<CanFrame> frames;
  for (std::size_t i = 0; i < kFrames; ++i)
    frames.push_back(classic(0x124, {static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(i >> 8)}));
  const Nanos before = realtime_now();
  const BatchSent sent = tx.send_batch(frames, soon());
  ASSERT_EQ(sent.sent, kFrames);
  ASSERT_EQ(sent.status, SendStatus::Sent);
  std::array<CanReceived, CanSocket::kBatch> batch{};
  std::vector<CanReceived> got;
  std::size_t calls = 0;
  while (got.size() < kFrames) {
    const std::size_t n = rx.receive_batch(batch, seconds(1));
    ASSERT_GT(n, 0U) << "after " << got.size();
    ++calls;
    got.insert(got.end(), batch.begin(), batch.begin() + static_cast<std::ptrdiff_t>(n));
  }
  const Nanos after = realtime_now();
  // Everything was queued before the first read: full batches, then the rest.
  EXPECT_EQ(calls, 4U);
  for (std::size_t i = 0; i < kFrames; ++i) {
    EXPECT_EQ(got[i].frame, frames[i]) << i;
    EXPECT_GE(got[i].timestamp, i == 0 ? before : got[i - 1].timestamp) << i;
    EXPECT_LE(got[i].timestamp, after) << i;
  }
  EXPECT_EQ(rx.rx_queue_drops(), 0U);
}

// The frames before an FD frame on a classic socket go; it and the ones after do not.
TEST(SocketCan, AnFdFrameInAClassicBatchStopsTheBatchThere) {
  CanSocket rx("vcan0");
  CanSocket tx("vcan0");
  std::vector<CanFrame> frames{classic(0x125, {1}), classic(0x125, {2}), CanFrame{}, classic(0x125, {4})};
  frames[2].fd = true;
  frames[2].len = 12;
  const BatchSent sent = tx.send_batch(frames, soon());
  EXPECT_EQ(sent.sent, 2U);
  EXPECT_EQ(sent.status, SendStatus::Failed);
  EXPECT_EQ(sent.error, EINVAL);
  std::array<CanReceived, 8> batch{};
  EXPECT_EQ(rx.receive_batch(batch, seconds(1)), 2U);
  EXPECT_EQ(batch[1].frame, frames[1]);
  EXPECT_EQ(rx.receive_batch(batch, milliseconds(50)), 0U);
}

// The RT rule on the real socket: sending and receiving batches allocates nothing.
TEST(SocketCan, BatchedSendAndReceiveDoNotAllocate) {
  CanSocket rx("vcan0");
  CanSocket tx("vcan0");
  std::array<CanFrame, 100> frames{};
  for (std::size_t i = 0; i < frames.size(); ++i) frames[i] = classic(0x126, {static_cast<std::uint8_t>(i)});
  std::array<CanReceived, CanSocket::kBatch> batch{};
  const Nanos deadline = soon();
  std::size_t received = 0;
  hilrig::test::arm_allocation_counter();
  const BatchSent sent = tx.send_batch(frames, deadline);
  const auto one = tx.send(frames[0], deadline);
  for (int k = 0; k < 4 && received < frames.size() + 1; ++k) received += rx.receive_batch(batch, Nanos{0});
  const auto single = rx.receive(Nanos{0});
  const std::uint64_t allocations = hilrig::test::disarm_allocation_counter();
  EXPECT_EQ(allocations, 0U);
  EXPECT_EQ(sent.sent, frames.size());
  EXPECT_EQ(one, SendStatus::Sent);
  EXPECT_EQ(received + (single ? 1U : 0U), frames.size() + 1);
}

// A socket nobody reads while 4,000 frames arrive: its receive queue fills and the kernel
// drops the rest. SO_RXQ_OVFL reports exactly the frames the reader did not get.
TEST(SocketCan, ReceiveQueueDropsAreCountedExactly) {
  CanSocket rx("vcan0");
  CanSocket tx("vcan0");
  EXPECT_EQ(rx.rx_queue_drops(), 0U);
  constexpr std::uint32_t kSent = 4000;
  for (std::uint32_t i = 0; i < kSent; ++i)
    ASSERT_EQ(tx.send(classic(0x200, {static_cast<std::uint8_t>(i)}), soon()), SendStatus::Sent) << i;
  std::uint32_t received = 0;
  while (rx.receive(milliseconds(50))) ++received;
  EXPECT_LT(received, kSent); // the queue did overflow
  EXPECT_GT(rx.rx_queue_drops(), 0U);
  EXPECT_EQ(received + rx.rx_queue_drops(), kSent);
}

// A socket that asks for error frames alone never queues (nor drops) a data frame.
TEST(SocketCan, AnErrorFramesOnlySocketTakesNoDataFrame) {
  CanSocketOptions errors_only;
  errors_only.data_frames = false;
  CanSocket rx("vcan0", errors_only);
  CanSocket tx("vcan0");
  for (std::uint8_t i = 0; i < 200; ++i) ASSERT_EQ(tx.send(classic(0x201, {i}), soon()), SendStatus::Sent);
  EXPECT_FALSE(rx.receive(milliseconds(50)).has_value());
  EXPECT_EQ(rx.rx_queue_drops(), 0U);
}

TEST(SocketCan, FiltersPassOnlyTheAskedIdentifier) {
  CanSocketOptions only_0x321;
  only_0x321.filters.push_back(CanFilter{0x321, 0x7FF, false});
  CanSocket rx("vcan0", only_0x321);
  CanSocket tx("vcan0");
  ASSERT_EQ(tx.send(classic(0x100, {1}), soon()), SendStatus::Sent);
  ASSERT_EQ(tx.send(classic(0x321, {2}, /*extended=*/true), soon()), SendStatus::Sent); // extended 0x321: no
  ASSERT_EQ(tx.send(classic(0x321, {3}), soon()), SendStatus::Sent);
  const auto got = rx.receive(seconds(1));
  ASSERT_TRUE(got.has_value());
  EXPECT_EQ(got->frame.id, 0x321U);
  EXPECT_FALSE(got->frame.extended);
  EXPECT_EQ(got->frame.data[0], 3);
  EXPECT_FALSE(rx.receive(milliseconds(50)).has_value());
}

TEST(SocketCan, CanFdFrameWithBitRateSwitchRoundTrips) {
  CanSocketOptions fd;
  fd.fd = true;
  CanSocket rx("vcan0", fd);
  CanSocket tx("vcan0", fd);
  CanFrame f;
  f.id = 0x18DAF110;
  f.extended = true;
  f.fd = true;
  f.brs = true;
  f.len = 64;
  for (std::uint8_t i = 0; i < 64; ++i) f.data[i] = i;
  ASSERT_EQ(tx.send(f, soon()), SendStatus::Sent);
  const auto got = rx.receive(seconds(1));
  ASSERT_TRUE(got.has_value());
  EXPECT_EQ(got->frame, f);
}

TEST(SocketCan, FdFrameOnAClassicSocketIsRefused) {
  CanSocket tx("vcan0");
  CanFrame f;
  f.fd = true;
  f.len = 12;
  EXPECT_EQ(tx.send(f, soon()), SendStatus::Failed);
}

TEST(SocketCan, FrameCrossesTheSja1000BusFromCan0ToCan1) {
  CanSocket rx("can1");
  CanSocket tx("can0");
  ASSERT_EQ(tx.send(classic(0x7FF, {1, 2, 3, 4, 5, 6, 7, 8}), soon()), SendStatus::Sent);
  std::optional<CanReceived> got;
  do {
    got = rx.receive(seconds(2)); // skip any error frame, e.g. from bring-up
  } while (got && got->is_error);
  ASSERT_TRUE(got.has_value());
  EXPECT_EQ(got->frame, classic(0x7FF, {1, 2, 3, 4, 5, 6, 7, 8}));
}

TEST(SocketCan, MissingInterfaceIsANamedError) {
  try {
    CanSocket s("can9");
    FAIL() << "opening a missing interface must throw";
  } catch (const CanError& e) {
    EXPECT_NE(std::string(e.what()).find("can9"), std::string::npos);
  }
}
