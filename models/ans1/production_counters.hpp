#pragma once
// The ANS1's six production counters (spec §4.12, manual L1185-L1226, CB10, CB11, DA7, DA8,
// DA17): Part Cycle, Batch 1..3, Machine Revolutions and Good Part, each 0..999,999,999, and
// the counter overflow (batch complete) outputs of counters 0..3.
//
// How the device calls it (ans1-core: Monitors does this for you): at every change of GMP,
//     bool part_cycle = counters.update(gmp, dp_fault_in_cycle);
// dp_fault_in_cycle: a die-protection fault happened in the production cycle now ending. When
// update() returns true a part-cycle event happened (a production cycle ended); the caller then
// starts a new die-protection cycle.
//
// [MODEL] choices (the manual is silent, see spec):
//  - a part-cycle event is GMP reaching the Increment Position moving forward (A52); a step of
//    at most FSC/2 counts is forward motion, a larger one is reverse;
//  - Machine Revolutions counts forward passes through GMP 0; reverse motion counts nothing (A53);
//  - Part Cycle = base + floor(events * Multiplier / Divisor) since the last preset (A52); the
//    other counters advance by the same step at that event;
//  - past 999,999,999 a counter rolls over to 0, like an odometer (A30);
//  - a limit is "reached" when a step takes the count from below the limit to the limit or
//    beyond; the count does not reset (A30).
#include <array>
#include <cstdint>

#include "models/ans1/monitor_setup.hpp"
#include "models/ans1/quiet_interval.hpp"

namespace hilrig::models::ans1 {

class ProductionCounters {
public:
  // Counts are kept across a new setup; a new multiplier/divisor re-bases the Part Cycle
  // counter at its present value.
  void configure(const ProductionSetup& setup, std::uint16_t full_scale_count);
  bool update(std::uint16_t gmp, bool dp_fault_in_cycle);
  void preset(CounterId counter, std::uint32_t value);

  [[nodiscard]] const ProductionSetup& setup() const { return setup_; }
  [[nodiscard]] std::uint32_t value(CounterId c) const { return values_[idx(c)]; }
  [[nodiscard]] bool overflowed(CounterId c) const { return overflow_[idx(c)]; }
  // Outputs programmed as overflow outputs (DA17 w14), and their levels (true = active).
  // Scan skipping (quiet_interval.hpp): the part-cycle position is a mark a forward move
  // counts at; settle() makes the last position the one a skipped scan would have left.
  void keep_quiet(QuietInterval& quiet, std::uint16_t gmp) const {
    quiet.keep_before_mark(gmp, setup_.increment_position);
  }
  void settle(std::uint16_t gmp) {
    if (primed_) last_gmp_ = gmp;
  }
  [[nodiscard]] std::uint16_t overflow_output_mask() const;
  [[nodiscard]] std::uint16_t overflow_output_levels() const;
  // DA17 w15..w18: the overflow output of counter c if it is in its overflow state.
  [[nodiscard]] std::uint16_t overflow_state_mask(CounterId c) const;

private:
  [[nodiscard]] static std::size_t idx(CounterId c) { return static_cast<std::size_t>(c); }
  void advance(CounterId c, std::uint32_t step);

  ProductionSetup setup_{};
  std::uint16_t fsc_ = 360;
  bool primed_ = false;
  std::uint16_t last_gmp_ = 0;
  std::uint32_t part_base_ = 0;
  std::uint64_t part_events_ = 0;
  std::array<std::uint32_t, kCounterCount> values_{};
  std::array<bool, kCounterCount> overflow_{};
  friend bool operator==(const ProductionCounters&, const ProductionCounters&) = default;
};

} // namespace hilrig::models::ans1
