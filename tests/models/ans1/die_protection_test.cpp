// Die protection (spec §4.11, manual L1058-L1183): the five check modes, the 500 us level
// qualification, once-per-period counting, self-reset, the 8-bit counter roll-over, the fault
// output and the never-counts variant. The engine is driven directly with a 10 us scan.
//
// Motion used throughout: GMP advances one count every 100 us, FSC 360, so one machine cycle
// is 36 ms. The check window is [100, 200): inside from 10 ms to 20 ms of every cycle.
#include <cstdint>
#include <functional>

#include <gtest/gtest.h>

#include "models/ans1/die_protection.hpp"

namespace hilrig::models::ans1 {
namespace {

constexpr std::int64_t kCycleUs = 36'000;

struct DieRig {
  DieProtection die;
  int input = 5;
  std::function<bool(std::int64_t)> level = [](std::int64_t) { return false; }; // by time in us
  std::int64_t now_us = 0;

  DieRig(DieCheckMode mode, DieActionMode action = DieActionMode::Continuous, bool never_counts = false)
      : die(never_counts) {
    DieProtectionSetup s;
    DieMonitorSetup& m = s.monitors[static_cast<std::size_t>(input - 1)];
    m.mode = mode;
    m.action = action;
    m.fault_output = 12;
    m.windows[0] = DieWindow{100, 200};
    die.configure(s, 360);
  }
  static std::uint16_t gmp(std::int64_t t_us) { return static_cast<std::uint16_t>((t_us / 100) % 360); }
  void run_to(std::int64_t to_us) {
    for (; now_us <= to_us; now_us += 10) {
      const auto inputs = static_cast<std::uint16_t>(level(now_us) ? 1U << (input - 1) : 0U);
      die.update(microseconds(now_us), gmp(now_us), inputs);
    }
  }
  [[nodiscard]] int count() const { return die.fault_count(input); }
  [[nodiscard]] bool output_on() const { return (die.fault_output_levels() & (1U << 11)) != 0; }
};

// Offset within the present machine cycle, in us.
std::int64_t phase(std::int64_t t) { return t % kCycleUs; }

TEST(DieProtectionCyclic, PulseInsideAndLowOutsideNeverFaults) {
  DieRig rig(DieCheckMode::Cyclic);
  rig.level = [](std::int64_t t) { return phase(t) >= 12'000 && phase(t) < 14'000; };
  rig.run_to(5 * kCycleUs);
  EXPECT_EQ(rig.count(), 0);
  EXPECT_TRUE(rig.output_on());
}

TEST(DieProtectionCyclic, MissingPulseFaultsAtEachTrailingEdge) {
  // Trailing edges at 20 ms + k*36 ms (L1087); by 170 ms five of them have passed.
  DieRig rig(DieCheckMode::Cyclic);
  rig.run_to(20'000 - 10);
  EXPECT_EQ(rig.count(), 0);
  rig.run_to(20'000);
  EXPECT_EQ(rig.count(), 1);
  EXPECT_FALSE(rig.output_on()); // action 0: output off while the counter is not 0 (L1072)
  rig.run_to(170'000);
  EXPECT_EQ(rig.count(), 5);
}

TEST(DieProtectionCyclic, FiveHundredMicrosecondPulseQualifiesFourHundredNinetyDoesNot) {
  // L1087: high >= 500 us. The 10 us scan sees a 500 us pulse as 500 us exactly.
  DieRig ok(DieCheckMode::Cyclic);
  ok.level = [](std::int64_t t) { return phase(t) >= 12'000 && phase(t) < 12'500; };
  ok.run_to(30'000);
  EXPECT_EQ(ok.count(), 0);
  DieRig short_pulse(DieCheckMode::Cyclic);
  short_pulse.level = [](std::int64_t t) { return phase(t) >= 12'000 && phase(t) < 12'490; };
  short_pulse.run_to(30'000);
  EXPECT_EQ(short_pulse.count(), 1);
}

TEST(DieProtectionCyclic, StuckHighFaultsAtTheLeadingEdge) {
  // Never low >= 500 us outside: fault at each leading edge (10 ms, 46 ms).
  DieRig rig(DieCheckMode::Cyclic);
  rig.level = [](std::int64_t) { return true; };
  rig.run_to(10'000);
  EXPECT_EQ(rig.count(), 1);
  rig.run_to(50'000);
  EXPECT_EQ(rig.count(), 2);
}

TEST(DieProtectionCyclic, SelfResetClearsAfterAFaultFreePeriod) {
  // Cycle 1 has no pulse (fault at 20 ms); cycle 2 has one, so its trailing edge at 56 ms
  // resets the counter and re-energizes the output (L1112).
  DieRig rig(DieCheckMode::Cyclic, DieActionMode::SelfReset);
  rig.level = [](std::int64_t t) { return t > kCycleUs && phase(t) >= 12'000 && phase(t) < 14'000; };
  rig.run_to(30'000);
  EXPECT_EQ(rig.count(), 1);
  EXPECT_FALSE(rig.output_on());
  rig.run_to(56'000 - 10);
  EXPECT_EQ(rig.count(), 1);
  rig.run_to(56'000);
  EXPECT_EQ(rig.count(), 0);
  EXPECT_TRUE(rig.output_on());
}

// High from 9.5 ms to 20.5 ms of each cycle covers the window with margin.
bool covers_window(std::int64_t t) { return phase(t) >= 9'500 && phase(t) < 20'500; }

TEST(DieProtectionConstant, HighThroughTheWindowNeverFaults) {
  DieRig rig(DieCheckMode::Constant);
  rig.level = covers_window;
  rig.run_to(5 * kCycleUs);
  EXPECT_EQ(rig.count(), 0);
}

TEST(DieProtectionConstant, DropoutInsideFaultsAtOnceAndOncePerPeriod) {
  // Two dropouts in cycle 2 (at 51 ms and 53 ms): the counter steps at the first, at that
  // very scan, and not at the second (L1121: at most one per period).
  DieRig rig(DieCheckMode::Constant);
  rig.level = [](std::int64_t t) {
    const bool dropout = (t >= 51'000 && t < 51'100) || (t >= 53'000 && t < 53'100);
    return covers_window(t) && !dropout;
  };
  rig.run_to(51'000 - 10);
  EXPECT_EQ(rig.count(), 0);
  rig.run_to(51'000);
  EXPECT_EQ(rig.count(), 1);
  rig.run_to(4 * kCycleUs);
  EXPECT_EQ(rig.count(), 1);
}

TEST(DieProtectionConstant, NotLowOutsideFaultsAtTheNextLeadingEdge) {
  // Stuck high: each leading edge finds no 500 us low since the last trailing edge.
  DieRig rig(DieCheckMode::Constant);
  rig.level = [](std::int64_t) { return true; };
  rig.run_to(10'000 - 10);
  EXPECT_EQ(rig.count(), 0);
  rig.run_to(10'000);
  EXPECT_EQ(rig.count(), 1);
  rig.run_to(3 * kCycleUs);
  EXPECT_EQ(rig.count(), 3);
}

TEST(DieProtectionConstant, LowAtTheLeadingEdgeFaults) {
  // The input rises 200 us after the window opens: low inside at the leading edge (L1121).
  DieRig rig(DieCheckMode::Constant);
  rig.level = [](std::int64_t t) { return phase(t) >= 10'200 && phase(t) < 20'500; };
  rig.run_to(10'000);
  EXPECT_EQ(rig.count(), 1);
}

TEST(DieProtectionQuick, PulseInsideNeverFaults) {
  DieRig rig(DieCheckMode::Quick);
  rig.level = [](std::int64_t t) { return phase(t) >= 12'000 && phase(t) < 13'000; };
  rig.run_to(5 * kCycleUs);
  EXPECT_EQ(rig.count(), 0);
}

TEST(DieProtectionQuick, HighOutsideFaultsAtOnce) {
  DieRig rig(DieCheckMode::Quick);
  rig.level = [](std::int64_t t) {
    return (phase(t) >= 12'000 && phase(t) < 13'000) || (t >= 25'000 && t < 25'100);
  };
  rig.run_to(25'000 - 10);
  EXPECT_EQ(rig.count(), 0);
  rig.run_to(25'000);
  EXPECT_EQ(rig.count(), 1);
}

TEST(DieProtectionQuick, StillHighAtTheTrailingEdgeFaultsOnce) {
  // High 19.5..20.5 ms: 500 us inside qualifies, but the input is still high when the window
  // closes at 20 ms -> one fault, at the trailing edge (L1167), none for the rest of it.
  DieRig rig(DieCheckMode::Quick);
  rig.level = [](std::int64_t t) { return t >= 19'500 && t < 20'500; };
  rig.run_to(20'000 - 10);
  EXPECT_EQ(rig.count(), 0);
  rig.run_to(20'000);
  EXPECT_EQ(rig.count(), 1);
  rig.run_to(kCycleUs);
  EXPECT_EQ(rig.count(), 1);
}

TEST(DieProtectionQuick, ShortPulseInsideFaultsAtTheTrailingEdge) {
  DieRig rig(DieCheckMode::Quick);
  rig.level = [](std::int64_t t) { return t >= 12'000 && t < 12'300; };
  rig.run_to(20'000 - 10);
  EXPECT_EQ(rig.count(), 0);
  rig.run_to(20'000);
  EXPECT_EQ(rig.count(), 1);
}

TEST(DieProtectionNormallyTrue, LossOfSignalCountsAndContinuousModeHolds) {
  // L1077: an active->inactive transition is a fault; the output drops at once.
  DieRig rig(DieCheckMode::NormallyTrue);
  rig.level = [](std::int64_t t) { return t < 1'000 || t >= 2'000; };
  rig.run_to(1'000);
  EXPECT_EQ(rig.count(), 1);
  EXPECT_FALSE(rig.output_on());
  rig.run_to(3'000);
  EXPECT_EQ(rig.count(), 1); // continuous: stays faulted after the input returns
  EXPECT_FALSE(rig.output_on());
}

TEST(DieProtectionNormallyTrue, SelfResetClearsWhenTheSignalReturns) {
  DieRig rig(DieCheckMode::NormallyTrue, DieActionMode::SelfReset);
  rig.level = [](std::int64_t t) { return t < 1'000 || t >= 2'000; };
  rig.run_to(1'500);
  EXPECT_EQ(rig.count(), 1);
  rig.run_to(2'000);
  EXPECT_EQ(rig.count(), 0);
  EXPECT_TRUE(rig.output_on());
}

TEST(DieProtectionNormallyFalse, RisingInputCountsAndSelfResetClearsOnFalling) {
  DieRig cont(DieCheckMode::NormallyFalse);
  DieRig self(DieCheckMode::NormallyFalse, DieActionMode::SelfReset);
  for (DieRig* rig : {&cont, &self}) {
    rig->level = [](std::int64_t t) { return t >= 1'000 && t < 2'000; };
    rig->run_to(1'500);
    EXPECT_EQ(rig->count(), 1);
    rig->run_to(3'000);
  }
  EXPECT_EQ(cont.count(), 1);
  EXPECT_EQ(self.count(), 0);
}

TEST(DieProtectionCounter, RollsOverFrom255To0AndTheOutputReturns) {
  // L1067 [A51]: 8-bit counter; 256 faults bring it back to 0, which re-activates the output.
  DieRig rig(DieCheckMode::NormallyFalse);
  rig.level = [](std::int64_t t) { return (t / 100) % 2 == 1; }; // one rising edge per 200 us
  rig.run_to(255 * 200 - 100); // rising edges at 100, 300, ..., 50'900 us: 255 faults
  EXPECT_EQ(rig.count(), 255);
  EXPECT_FALSE(rig.output_on());
  rig.run_to(256 * 200 - 100);
  EXPECT_EQ(rig.count(), 0);
  EXPECT_TRUE(rig.output_on());
}

TEST(DieProtectionCounter, DisconnectedOutputStaysOnWhileCounting) {
  // Action mode 2 (L1073): the counter counts but the output is always active.
  DieRig rig(DieCheckMode::NormallyTrue, DieActionMode::ContinuousOutputOn);
  rig.level = [](std::int64_t t) { return t < 1'000; };
  rig.run_to(2'000);
  EXPECT_EQ(rig.count(), 1);
  EXPECT_TRUE(rig.output_on());
  EXPECT_EQ(rig.die.fault_output_mask(), 1U << 11);
}

TEST(DieProtectionStatus, FirstToFaultAndFaultedInputsLastForOneProductionCycle) {
  // Input 5 faults first (at 1 ms), input 7 second (at 2 ms); DA18 w4 shows only input 5,
  // w5 both; a new production cycle clears both masks but not the counters.
  DieProtection die;
  DieProtectionSetup s;
  s.monitors[4].mode = DieCheckMode::NormallyFalse;
  s.monitors[6].mode = DieCheckMode::NormallyFalse;
  die.configure(s, 360);
  die.update(microseconds(0), 0, 0);
  die.update(milliseconds(1), 0, 0x0010);
  die.update(milliseconds(2), 0, 0x0050);
  EXPECT_EQ(die.first_to_fault(), 0x0010);
  EXPECT_EQ(die.faulted_in_cycle(), 0x0050);
  EXPECT_EQ(die.monitored_inputs(), 0x0050);
  die.begin_production_cycle();
  EXPECT_EQ(die.first_to_fault(), 0);
  EXPECT_EQ(die.faulted_in_cycle(), 0);
  EXPECT_EQ(die.fault_count(5), 1);
  EXPECT_EQ(die.fault_count(7), 1);
}

TEST(DieProtectionVariant, NeverCountsVariantDetectsButDoesNotCount) {
  DieRig good(DieCheckMode::Cyclic);
  DieRig bad(DieCheckMode::Cyclic, DieActionMode::Continuous, /*never_counts=*/true);
  good.run_to(30'000);
  bad.run_to(30'000);
  EXPECT_EQ(good.count(), 1);
  EXPECT_FALSE(good.output_on());
  EXPECT_EQ(bad.count(), 0);
  EXPECT_TRUE(bad.output_on());
  EXPECT_EQ(bad.die.faulted_in_cycle(), 1U << 4);
}

TEST(DieProtectionSetupChange, ReprogrammingAMonitorRestartsItsCounter) {
  DieRig rig(DieCheckMode::Cyclic);
  rig.run_to(30'000);
  ASSERT_EQ(rig.count(), 1);
  DieProtectionSetup s = rig.die.setup();
  s.monitors[4].windows[0] = DieWindow{150, 250};
  rig.die.configure(s, 360);
  EXPECT_EQ(rig.count(), 0);
}

} // namespace
} // namespace hilrig::models::ans1
