// Live data blocks read through the status words: DA16 speed and production rate, DA19
// advances (W-13), DA16 input edge positions and DA20 shift register (spec §5.5).
#include <gtest/gtest.h>

#include "host_rig.hpp"

namespace hilrig::models::ans1 {
namespace {

using test::block;
using test::HostRig;

// Drives the slave position one count every 200 us up to `to_ms`. A 14.6 ms speed period holds
// exactly 73 such steps whatever its phase, so the measured speed is exact: 73 counts per
// 14.6 ms = 5 counts/ms = 300,000 counts/min, i.e. 100 RPM with CPC 3000 and 150 RPM with
// CPC 2000.
void run_staircase(HostRig& rig, std::int64_t to_ms) {
  const std::int64_t start_us = rig.scheduler.now() / microseconds(1);
  for (std::int64_t t = (start_us / 200 + 1) * 200; t <= to_ms * 1000; t += 200) {
    rig.scheduler.at(microseconds(t), [&rig, t] { rig.device.set_slave_position(t / 200); });
  }
  rig.scheduler.run_until(milliseconds(to_ms));
}

// Output 4 with a 10 ms lead advance, RPM filter 0 (no filtering: S is the measured speed).
void program_lead_advance(HostRig& rig, int cpc) {
  rig.use_slave_position();
  ASSERT_EQ(rig.send(block(2, {8, 12}, {{2, cpc}, {7, 0}})), ErrorCode::None);
  ASSERT_EQ(rig.send(block(3, {10}, {{1, 4}, {4, 100}, {5, 200}})), ErrorCode::None);
  ASSERT_EQ(rig.send(block(5, {8}, {{1, 4}, {2, 10}, {3, 0}})), ErrorCode::None);
}

TEST(HostLiveData, W13LeadAdvanceCountsInDataAttribute19) {
  // W-13 (L893): a 10 ms lead is 6 counts at 100 RPM and 9 counts at 150 RPM (FSC 360:
  // 10 ms x 600 or 900 counts/s).
  HostRig at100;
  program_lead_advance(at100, 3000);
  ASSERT_EQ(at100.send(block(10, {9}, {{2, 3}, {3, 2}})), ErrorCode::None); // production M/D = 3/2
  run_staircase(at100, 200);
  const HostWords da19 = at100.select(19, 4);
  EXPECT_EQ(da19[8], 4);
  EXPECT_EQ(da19[9], 6);
  EXPECT_EQ(da19[10], 0);
  const HostWords da16 = at100.select(16);
  EXPECT_EQ(da16[2], 100);
  EXPECT_EQ(da16[3], 150); // production rate = S x 3 / 2 (L2536)

  HostRig at150;
  program_lead_advance(at150, 2000);
  run_staircase(at150, 200);
  EXPECT_EQ(at150.select(16)[2], 150);
  EXPECT_EQ(at150.select(19, 4)[9], 9);
}

// The slave position one count every 200 us backwards, scheduled to `until_ms` (past the reads
// that follow, so the speed holds while the host reads): -5 counts/ms, as run_staircase forward.
void schedule_reverse_staircase(HostRig& rig, std::int64_t until_ms) {
  const std::int64_t start_us = rig.scheduler.now() / microseconds(1);
  for (std::int64_t t = (start_us / 200 + 1) * 200; t <= until_ms * 1000; t += 200) {
    rig.scheduler.at(microseconds(t), [&rig, t] { rig.device.set_slave_position(-t / 200); });
  }
}

[[nodiscard]] std::int16_t signed_word(std::uint16_t w) { return static_cast<std::int16_t>(w); }

TEST(HostLiveData, ReverseProductionRateSaturatesAtMinus32767) {
  // -73 counts per 14.6 ms with CPC 3000 is -100 RPM (as W13 forward). Production rate =
  // S x Multiplier / Divisor (L2536), saturated at -32767 like the speed words the manual
  // bounds (RPM Enable setpoints -32,767 .. +32,767, L2019-L2020) [MODEL], never -32768.
  HostRig rig;
  program_lead_advance(rig, 3000);
  schedule_reverse_staircase(rig, 300);
  rig.scheduler.run_until(milliseconds(200));
  const auto rate = [&rig](int multiplier, int divisor) {
    EXPECT_EQ(rig.send(block(10, {9}, {{2, multiplier}, {3, divisor}})), ErrorCode::None);
    return signed_word(rig.select(16)[3]);
  };
  EXPECT_EQ(signed_word(rig.select(16)[2]), -100);
  EXPECT_EQ(rate(32766, 100), -32766); // -100 x 32766 / 100: one inside the limit
  EXPECT_EQ(rate(32767, 100), -32767); // at the limit
  EXPECT_EQ(rate(32767, 99), -32767);  // -33097 beyond it
  EXPECT_EQ(rate(400, 1), -32767);     // -40000
}

TEST(HostLiveData, TheWidestSpeedWindowKeepsASaturatedReverseSpeedEnabled) {
  // CPC = FSC = 2: -5 counts/ms is -2.5 cycles/ms = -150,000 RPM, saturated to -32767 in DA16
  // w2. RPM Enable -32767 .. 32767 (L2019-L2020, CB6 bit 9) holds it: output 1's bit in the
  // RPM-enabled mask (DA16 w15) is set; output 2 with Low -32766 is one step narrower: clear.
  HostRig rig;
  rig.use_slave_position();
  ASSERT_EQ(rig.send(block(2, {8, 9, 12}, {{2, 2}, {3, 2}, {7, 0}})), ErrorCode::None);
  ASSERT_EQ(rig.send(block(6, {9}, {{1, 1}, {2, -32767}, {3, 32767}})), ErrorCode::None);
  ASSERT_EQ(rig.send(block(6, {9}, {{1, 2}, {2, -32766}, {3, 32767}})), ErrorCode::None);
  schedule_reverse_staircase(rig, 300);
  rig.scheduler.run_until(milliseconds(200));
  const HostWords da16 = rig.select(16);
  EXPECT_EQ(signed_word(da16[2]), -32767);
  EXPECT_EQ(da16[15] & 0x0003, 0x0001);
}

TEST(HostLiveData, InputEdgePositionsAndShiftRegisterInDataAttributes16And20) {
  // CPC = FSC = 360 so one slave count is one GMP count; the position advances 1 count/ms.
  // Input 2 (forced) rises at GMP 5 and falls at GMP 35; the shift register samples input 2
  // in [10, 20) and shifts at 30, so b[1] = 1 (L612-L614).
  HostRig rig;
  rig.use_slave_position();
  ASSERT_EQ(rig.send(block(2, {8, 9}, {{2, 360}, {3, 360}})), ErrorCode::None);
  ASSERT_EQ(rig.send(block(9, {8}, {{1, 2}, {2, 10}, {3, 20}, {4, 30}})), ErrorCode::None);
  const auto run_to = [&rig](std::int64_t to) {
    const std::int64_t now_ms = rig.scheduler.now() / milliseconds(1);
    for (std::int64_t t = now_ms + 1; t <= to; ++t) {
      rig.scheduler.at(milliseconds(t), [&rig, t] { rig.device.set_slave_position(t); });
    }
    rig.scheduler.run_until(milliseconds(to));
  };
  run_to(5);
  rig.transact(block(1, {10}, {{6, 0x0002}, {7, 0x0002}}));
  run_to(35);
  HostWords da20 = rig.select(20);
  EXPECT_EQ(da20[2], 0x0002); // SR input active
  EXPECT_EQ(da20[4], 0x0001); // b[1]
  EXPECT_EQ(da20[5], 0x0000);
  rig.transact(block(1, {10}, {{6, 0x0002}, {7, 0x0000}}));
  run_to(40);
  const HostWords da16 = rig.select(16, 1, 2);
  EXPECT_EQ(da16[6], 2);
  EXPECT_EQ(da16[7], 5);
  EXPECT_EQ(da16[8], 35);
}

} // namespace
} // namespace hilrig::models::ans1
