#pragma once
// Programmed setup of the ANS1's monitors: the press brake monitor (CB8, spec §4.10), the 16
// die-protection monitors (CB7, §4.11) and the production counters (CB10/CB11, §4.12). Plain
// structs: the host interface parses command blocks into them, the device hands them to
// Monitors::configure(). Inputs and outputs are numbered 1..16 as on the module; 0 = none.
#include <array>
#include <cstdint>

namespace hilrig::models::ans1 {

// CB8. Defaults: everything 0 (monitor off), as after "Delete all brake data".
struct BrakeSetup {
  std::uint8_t input = 0;                // w1: brake input 1..16 (active = brake released); 0 = off
  std::uint8_t complete_stop_count = 0;  // w2: CSC 0..255, always on a 4096 counts/turn base
  std::uint16_t start_time_limit_ms = 0; // w3: 0..32767
  std::uint8_t start_overrun_output = 0; // w4: 0..16
  std::uint16_t stop_time_limit_ms = 0;  // w5: 0..32767
  std::uint8_t stop_overrun_output = 0;  // w6: 0..16
  friend bool operator==(const BrakeSetup&, const BrakeSetup&) = default;
};

// CB7 word 3.
enum class DieCheckMode : std::uint8_t {
  Off = 0,
  NormallyTrue = 1,
  NormallyFalse = 2,
  Cyclic = 3,
  Constant = 4,
  Quick = 5,
};

// CB7 word 12: bit 0 = self-reset counter, bit 1 = fault output disconnected (always active).
enum class DieActionMode : std::uint8_t {
  Continuous = 0,
  SelfReset = 1,
  ContinuousOutputOn = 2,
  SelfResetOutputOn = 3,
};

[[nodiscard]] constexpr bool self_resets(DieActionMode a) { return (static_cast<unsigned>(a) & 1U) != 0; }
[[nodiscard]] constexpr bool output_follows_counter(DieActionMode a) {
  return (static_cast<unsigned>(a) & 2U) == 0;
}

inline constexpr int kDieWindows = 4;

// A check window [leading, trailing) in GMP counts; leading > trailing wraps through zero.
// leading == trailing is an unused window [MODEL: the manual gives no "unused" value; 0/0 is
// what "Delete" leaves].
struct DieWindow {
  std::uint16_t leading = 0;
  std::uint16_t trailing = 0;
  [[nodiscard]] constexpr bool used() const { return leading != trailing; }
  friend bool operator==(const DieWindow&, const DieWindow&) = default;
};

// One monitor; the monitor of input n is DieProtectionSetup::monitors[n-1].
struct DieMonitorSetup {
  std::uint8_t fault_output = 0; // w1: 0..16, 0 = none
  DieCheckMode mode = DieCheckMode::Off;
  std::array<DieWindow, kDieWindows> windows{};
  DieActionMode action = DieActionMode::Continuous;
  friend bool operator==(const DieMonitorSetup&, const DieMonitorSetup&) = default;
};

struct DieProtectionSetup {
  std::array<DieMonitorSetup, 16> monitors{};
  friend bool operator==(const DieProtectionSetup&, const DieProtectionSetup&) = default;
};

// CB11 word 1.
enum class CounterId : std::uint8_t {
  PartCycle = 0,
  Batch1 = 1,
  Batch2 = 2,
  Batch3 = 3,
  Revolutions = 4,
  GoodPart = 5,
};
inline constexpr int kCounterCount = 6;
inline constexpr std::uint32_t kCounterMax = 999'999'999; // 0x3B9AC9FF (L2181)

// CB11 word 3.
enum class OverflowMode : std::uint8_t { None = 0, ActiveUntilNextCycle = 1, Toggle = 2 };

struct CounterSetup {
  std::uint8_t overflow_output = 0;                // w2: 0..16
  OverflowMode overflow_mode = OverflowMode::None; // w3
  bool only_good_cycles = false; // w4 batch increment mode: 1 = only cycles without a DP fault
  std::uint32_t limit = 0;       // w5/w6: 0..999,999,999; 0 = no limit programmed [MODEL]
  friend bool operator==(const CounterSetup&, const CounterSetup&) = default;
};

// CB10 plus CB11.
struct ProductionSetup {
  std::uint16_t increment_position = 0; // CB10 w1: 0..FSC-1
  std::uint16_t multiplier = 1;         // CB10 w2: 1..32767
  std::uint16_t divisor = 1;            // CB10 w3: 1..32767
  std::array<CounterSetup, kCounterCount> counters{};
  friend bool operator==(const ProductionSetup&, const ProductionSetup&) = default;
};

struct MonitorSetup {
  BrakeSetup brake{};
  DieProtectionSetup die{};
  ProductionSetup production{};
  friend bool operator==(const MonitorSetup&, const MonitorSetup&) = default;
};

} // namespace hilrig::models::ans1
