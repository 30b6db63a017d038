// Exact scan skipping (docs/virtual-time.md): a device that nothing reaches runs no scans
// beyond its first; anything it reads wakes the next scan on its period grid, where scanning
// every period would have scanned. The byte-for-byte comparison of whole campaigns is
// tests/campaign/exact_scan_test.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "ans1_bench.hpp"

namespace hilrig::models::ans1 {
namespace {

using namespace hilrig::literals;
using testing::Bench;
using testing::every_period;

// CB2 bit 3 (QuadEnc): the encoder, whose count moves only on its edges.
void use_encoder(Bench& b) {
  PositionSetup p = b.device().position_setup();
  p.sensor = SensorType::Quadrature;
  b.device().configure_position(p);
}

TEST(ScanSkipping, StandstillCostsNoScansWhileScanningEveryPeriodCostsOneAPeriod) {
  // ans1 manual (seeds/000_08a2edf5547d4d1e.txt L572-L576, docs/spec/ans1.md L187): a master
  // scans every 10 us.
  Bench oracle(every_period());
  use_encoder(oracle);
  oracle.run_until(1_s);
  EXPECT_EQ(oracle.device().scans(), 100'001U); // t = 0, 10 us, ..., 1 s
  Bench skipping;
  use_encoder(skipping);
  skipping.run_until(1_s);
  const std::uint64_t one_second = skipping.device().scans();
  EXPECT_LE(one_second, 3U); // the first scan settles the state, the second finds it settled
  skipping.run_until(10_s);
  EXPECT_EQ(skipping.device().scans(), one_second); // 9 s more standstill: no scan at all
}

TEST(ScanSkipping, AnInputEdgeWakesTheScanOnTheGridAndIsSeenThereAsEveryPeriod) {
  // Inputs are read at the scan (spec §4.0): an edge at 5,003 us is read by the scan at
  // 5,010 us; one at exactly 7,000 us by the scan at 7,000 us (a scan sees every change at
  // its instant). Sweep edges across one period around grid points on both benches.
  for (const Nanos at : {5'003_us, 6'999_us, 7'000_us, 7'001_us, 7'009_us, 7'010_us}) {
    SCOPED_TRACE(at.count());
    Bench oracle(every_period());
    Bench skipping;
    for (Bench* b : {&oracle, &skipping}) {
      use_encoder(*b);
      b->run_until(4_ms);
      b->input_at(at, 3, true);
      b->input_at(at + 20_us, 3, false);
    }
    for (Nanos t = 4_ms; t <= 8_ms; t += 1_us) {
      oracle.run_until(t);
      skipping.run_until(t);
      ASSERT_EQ(oracle.device().input_states(), skipping.device().input_states()) << t.count();
      ASSERT_EQ(oracle.device().electrical_inputs(), skipping.device().electrical_inputs()) << t.count();
    }
    EXPECT_LT(skipping.device().scans(), oracle.device().scans() / 10);
  }
}

TEST(ScanSkipping, AResolverIsReadAtEveryExcitationPeakEvenAtStandstill) {
  // The stators are sampled at each excitation peak, positive and negative (Params,
  // 5 kHz: every 100 us). A peak that reads the same angle keeps the state; the scan after
  // it still runs, one in ten of a scan every period.
  Bench oracle(every_period());
  Bench skipping;
  oracle.run_until(100_ms);
  skipping.run_until(100_ms);
  EXPECT_EQ(oracle.device().scans(), 10'001U);
  EXPECT_GE(skipping.device().scans(), 1'000U);             // one per peak: 1,000 peaks in 100 ms
  EXPECT_LE(skipping.device().scans(), 1'000U + 100U + 2U); // and one after each 1 ms history tick
  EXPECT_EQ(oracle.device().transducer_count(), skipping.device().transducer_count());
  EXPECT_EQ(oracle.device().resolver_fault(), skipping.device().resolver_fault());
}

// The brake monitor (spec §4.0, manual L1030-L1056) runs on a 1 ms tick. While no cycle runs
// and its input stays as the last tick saw it, a tick only records the position history, so the
// skipping scan sleeps through it and records it later with the count at its grid point. Brake
// edges a hair before, at and after a tick and its scan, motion while idle (the history the
// 125 ms stop window reads), a start, a stop and a rejected application: the same status,
// faults and outputs as scanning every period, at every 10 us.
TEST(ScanSkipping, AnIdleBrakeMonitorsTicksAreSkippedAndRecordedAsEveryPeriod) {
  MonitorSetup setup;
  setup.brake = BrakeSetup{2, 10, 40, 5, 90, 6}; // input 2, CSC 10, start 40 ms -> OUT5, stop 90 ms -> OUT6
  for (const Nanos d : {-1_us, 0_us, 3_us, 10_us}) {
    SCOPED_TRACE(d.count());
    Bench oracle(every_period());
    Bench skipping;
    for (Bench* b : {&oracle, &skipping}) {
      use_encoder(*b);
      b->device().configure_monitors(setup);
      b->quadrature_run(5_ms, 70_us, 40, +1);   // history while idle
      b->input_at(20_ms + d, 2, true);          // released: a start
      b->quadrature_run(30_ms, 100_us, 30, +1); // 30 counts > 2 * CSC: the start ends
      b->input_at(80_ms + d, 2, false);         // applied: debounced, then a stop
      b->quadrature_run(85_ms, 300_us, 12, +1); // coasting to a stop
      b->input_at(400_ms + d, 2, true);         // released, never moves: start overrun
      b->input_at(470_ms + d, 2, false);        // applied
      b->input_at(480_ms + d, 2, true);         // released again during the debounce: noise
      b->input_at(520_ms + d, 2, false);        // applied for good
      b->quadrature_run(600_ms, 50_us, 25, -1); // idle motion again
    }
    for (Nanos t = 0_ms; t <= 800_ms; t += 10_us) {
      oracle.run_until(t);
      skipping.run_until(t);
      const BrakeMonitor& a = oracle.device().monitors().brake();
      const BrakeMonitor& b = skipping.device().monitors().brake();
      ASSERT_EQ(a.status(), b.status()) << t.count();
      ASSERT_EQ(a.phase(), b.phase()) << t.count();
      ASSERT_EQ(a.start_fault(), b.start_fault()) << t.count();
      ASSERT_EQ(a.stop_fault(), b.stop_fault()) << t.count();
      ASSERT_EQ(oracle.device().output_states(), skipping.device().output_states()) << t.count();
    }
    // The cycles did happen: a start, a stop, a rejected application, an overrun.
    const BrakeStatus& st = skipping.device().monitors().brake().status();
    EXPECT_EQ(st.completed_starts, 1U);
    EXPECT_GE(st.completed_stops, 1U);
    EXPECT_EQ(st.noise_rejections, 1U);
    EXPECT_TRUE(skipping.device().monitors().brake().start_fault());
    // Idle and standing still once the last stop is measured (the 125 ms window after the
    // motion at 600 ms): no brake tick wakes the scan (each of the 99,000 did), nor does the
    // speed filter's tail (S = k S every 14.6 ms, spec §4.2: ~1,600 updates until S sticks at
    // the least subnormal, each of which woke one), as the reported RPM (0) and the advances
    // stay.
    skipping.run_until(1_s);
    ASSERT_EQ(skipping.device().monitors().brake().phase(), BrakeMonitor::Phase::Idle);
    const std::uint64_t at_1s = skipping.device().scans();
    skipping.run_until(100_s);
    EXPECT_LE(skipping.device().scans() - at_1s, 2U);
    EXPECT_EQ(skipping.device().speed_rpm(), 0);
    EXPECT_LT(std::abs(skipping.device().speed()), 1e-300); // the tail did run its course
  }
}

} // namespace
} // namespace hilrig::models::ans1
