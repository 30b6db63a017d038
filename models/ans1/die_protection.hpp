#pragma once
// The ANS1's 16 die-protection monitors (spec §4.11, manual L1058-L1183, CB7, DA4, DA18).
// Monitor n watches input n; it is active when its check mode is not Off. Each counts faults
// in an 8-bit counter (255 + 1 -> 0, L1067) and drives an optional fault output that is ON
// while the counter is 0 (action modes 0/1) or always ON (2/3).
//
// How the device calls it (ans1-core: Monitors does this for you): in time order, on every
// scan, or at least at every change of GMP or of an input,
//     die.update(now, gmp, inputs);    // inputs: logical states, bit n-1 = input n active
// and at each production-cycle boundary (part-cycle event) begin_production_cycle().
// Levels are taken as constant between two calls, so the "held >= 500 us" qualification is
// exact when calls happen at every change.
#include <array>
#include <cstdint>

#include "core/time.hpp"
#include "models/ans1/monitor_setup.hpp"
#include "models/ans1/quiet_interval.hpp"

namespace hilrig::models::ans1 {

class DieProtection {
public:
  static constexpr Nanos kQualifyTime = microseconds(500); // L1087, L1121, L1157 [A61: continuous]

  explicit DieProtection(bool never_counts = false) : never_counts_(never_counts) {}

  // A monitor whose setup changes restarts (counter 0, no history); the others keep running.
  void configure(const DieProtectionSetup& setup, std::uint16_t full_scale_count);
  void update(Nanos now, std::uint16_t gmp, std::uint16_t inputs);
  void begin_production_cycle();
  // Clear Errors is not a DP reset in the manual; counters only reset by self-reset or by a
  // new setup of that monitor.

  // Scan skipping (quiet_interval.hpp): the windows of the monitors in use.
  void keep_quiet(QuietInterval& quiet, std::uint16_t gmp) const;
  [[nodiscard]] const DieProtectionSetup& setup() const { return setup_; }
  [[nodiscard]] std::uint8_t fault_count(int input) const { return state_[index(input)].counter; }
  // Masks, bit n-1 = input n (DA18 w3, w4, w5).
  [[nodiscard]] std::uint16_t monitored_inputs() const;
  [[nodiscard]] std::uint16_t first_to_fault() const { return first_to_fault_; }
  [[nodiscard]] std::uint16_t faulted_in_cycle() const { return faulted_in_cycle_; }
  [[nodiscard]] bool fault_in_cycle() const { return faulted_in_cycle_ != 0; }
  // The earliest time at which update() with unchanged inputs and window can change the state:
  // a level held inside (high) or outside (low) qualifying after 500 us; max when none waits.
  [[nodiscard]] Nanos next_change() const;
  // Fault outputs, bit n-1 = output n: the outputs owned by an active monitor, and their level.
  [[nodiscard]] std::uint16_t fault_output_mask() const;
  [[nodiscard]] std::uint16_t fault_output_levels() const;
  // Equal but for the setup, which update() and begin_production_cycle() never write: a copy
  // that ran a scan against the original (Monitors::scan_left_alone).
  [[nodiscard]] bool same_state(const DieProtection& o) const {
    return state_ == o.state_ && first_to_fault_ == o.first_to_fault_ &&
           faulted_in_cycle_ == o.faulted_in_cycle_;
  }

private:
  struct MonitorState {
    bool primed = false;
    bool level = false; // input active
    Nanos level_since{};
    bool inside = false; // GMP inside one of the windows
    Nanos inside_since{};
    bool low_ok = false;  // low >= 500 us outside since the last trailing edge
    bool high_ok = false; // high >= 500 us inside since the last leading edge
    bool period_fault = false;
    std::uint8_t counter = 0;
    friend bool operator==(const MonitorState&, const MonitorState&) = default;
  };
  [[nodiscard]] static std::size_t index(int input) { return static_cast<std::size_t>(input - 1); }
  [[nodiscard]] bool inside(const DieMonitorSetup& m, std::uint16_t gmp) const;
  void update_one(int input, Nanos now, bool level, bool in_window);
  void input_edge(int input, bool level);
  void leading_edge(int input);
  void trailing_edge(int input);
  void fault(int input);
  void fault_once_per_period(int input);

  DieProtectionSetup setup_{};
  std::uint16_t fsc_ = 360;
  bool never_counts_;
  std::array<MonitorState, 16> state_{};
  std::uint16_t first_to_fault_ = 0;
  std::uint16_t faulted_in_cycle_ = 0;
  friend bool operator==(const DieProtection&, const DieProtection&) = default;
};

} // namespace hilrig::models::ans1
