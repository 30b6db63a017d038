// Error frames built by hand from linux/can/error.h's documented values (not the macros),
// so the decoder is checked against the kernel's ABI.
#include "drivers/socketcan/bus_state.hpp"

#include <gtest/gtest.h>

using namespace hilrig::socketcan;

namespace {
constexpr std::uint32_t kErrFlag = 0x20000000; // CAN_ERR_FLAG
constexpr std::uint32_t kCrtl = 0x004;         // CAN_ERR_CRTL
constexpr std::uint32_t kAck = 0x020;          // CAN_ERR_ACK
constexpr std::uint32_t kBusOff = 0x040;       // CAN_ERR_BUSOFF
constexpr std::uint32_t kRestarted = 0x100;    // CAN_ERR_RESTARTED
constexpr std::uint32_t kCnt = 0x200;          // CAN_ERR_CNT
constexpr std::uint8_t kRxOverflow = 0x01;     // data[1]: CAN_ERR_CRTL_RX_OVERFLOW
constexpr std::uint8_t kTxOverflow = 0x02;     // data[1]: CAN_ERR_CRTL_TX_OVERFLOW
} // namespace

TEST(ErrorFrame, ControllerTxPassiveIsErrorPassive) {
  const auto r = decode_error_frame(kErrFlag | kCrtl, {0, 0x20 /*TX_PASSIVE*/, 0, 0, 0, 0, 0, 0});
  ASSERT_TRUE(r.state.has_value());
  EXPECT_EQ(*r.state, BusState::ErrorPassive);
}

TEST(ErrorFrame, ControllerRxWarningIsErrorWarning) {
  const auto r = decode_error_frame(kErrFlag | kCrtl, {0, 0x04 /*RX_WARNING*/, 0, 0, 0, 0, 0, 0});
  ASSERT_TRUE(r.state.has_value());
  EXPECT_EQ(*r.state, BusState::ErrorWarning);
}

TEST(ErrorFrame, BusOffWithCountersAndMissingAck) {
  const auto r = decode_error_frame(kErrFlag | kBusOff | kAck | kCnt, {0, 0, 0, 0, 0, 0, 248, 0});
  ASSERT_TRUE(r.state.has_value());
  EXPECT_EQ(*r.state, BusState::BusOff);
  EXPECT_TRUE(r.no_ack);
  EXPECT_EQ(r.tx_errors.value_or(0), 248);
  EXPECT_EQ(r.describe(), "bus-off; no ACK; TEC 248; REC 0");
}

TEST(BusStateTracker, WalksActiveWarningPassiveBusOffAndBackOnRestart) {
  BusStateTracker t;
  EXPECT_EQ(t.state(), BusState::ErrorActive);
  t.apply(decode_error_frame(kErrFlag | kCrtl, {0, 0x08 /*TX_WARNING*/, 0, 0, 0, 0, 0, 0}));
  EXPECT_EQ(t.state(), BusState::ErrorWarning);
  t.apply(decode_error_frame(kErrFlag | kCrtl, {0, 0x20, 0, 0, 0, 0, 0, 0}));
  EXPECT_EQ(t.state(), BusState::ErrorPassive);
  t.apply(decode_error_frame(kErrFlag | kBusOff, {}));
  t.apply(decode_error_frame(kErrFlag | kBusOff, {})); // repeated report: still one bus-off
  EXPECT_EQ(t.state(), BusState::BusOff);
  EXPECT_EQ(t.bus_off_count(), 1U);
  t.apply(decode_error_frame(kErrFlag | kRestarted, {}));
  EXPECT_EQ(t.state(), BusState::ErrorActive);
  EXPECT_EQ(t.restart_count(), 1U);
}

TEST(ErrorFrame, ControllerOverflowsAreDecodedWithoutAStateChange) {
  const auto rx = decode_error_frame(kErrFlag | kCrtl, {0, kRxOverflow, 0, 0, 0, 0, 0, 0});
  EXPECT_TRUE(rx.rx_overflow);
  EXPECT_FALSE(rx.tx_overflow);
  EXPECT_FALSE(rx.state.has_value());
  EXPECT_EQ(rx.describe(), "RX overflow");
  const auto both = decode_error_frame(kErrFlag | kCrtl, {0, kRxOverflow | kTxOverflow, 0, 0, 0, 0, 0, 0});
  EXPECT_TRUE(both.rx_overflow);
  EXPECT_TRUE(both.tx_overflow);
  // The same bits outside a controller-class frame mean nothing.
  const auto not_crtl = decode_error_frame(kErrFlag | kAck, {0, kRxOverflow | kTxOverflow, 0, 0, 0, 0, 0, 0});
  EXPECT_FALSE(not_crtl.rx_overflow);
  EXPECT_FALSE(not_crtl.tx_overflow);
}

TEST(BusStateTracker, CountsEveryOverflowReportAndKeepsTheState) {
  BusStateTracker t;
  EXPECT_EQ(t.rx_overflow_count(), 0U);
  EXPECT_EQ(t.tx_overflow_count(), 0U);
  for (int i = 0; i < 3; ++i)
    t.apply(decode_error_frame(kErrFlag | kCrtl, {0, kRxOverflow, 0, 0, 0, 0, 0, 0}));
  t.apply(decode_error_frame(kErrFlag | kCrtl, {0, kTxOverflow | 0x08 /*TX_WARNING*/, 0, 0, 0, 0, 0, 0}));
  EXPECT_EQ(t.rx_overflow_count(), 3U);
  EXPECT_EQ(t.tx_overflow_count(), 1U);
  EXPECT_EQ(t.state(), BusState::ErrorWarning);
  t.apply(decode_error_frame(kErrFlag | kAck, {})); // another error kind: no overflow counted
  EXPECT_EQ(t.rx_overflow_count(), 3U);
  EXPECT_EQ(t.tx_overflow_count(), 1U);
}
