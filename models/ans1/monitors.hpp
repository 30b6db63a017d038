#pragma once
// The ANS1's monitors as one unit: brake monitor, die protection, production counters, the
// fault outputs they claim, and the last rising/falling GMP of each input (DA16 w7/w8, DA18
// w8/w9). The device (ans1-core's Ans1) owns one Monitors and wires it like this:
//
//   Monitors monitors{faults};                       // faults: MonitorFaults (variants)
//   monitors.configure(setup.monitors, fsc);         // after reset and after every host block
//                                                    //  that changed the setup (or the FSC)
//   monitors.scan(now, {gmp, pos4096, inputs});      // every position scan, in time order
//   out = apply_claims(monitors.claims(), ls, ls_programmed);   // see fault_outputs.hpp
//   monitors.clear_errors();                         // on Clear Errors (any block's bit 4)
//   monitors.preset_counter(id, value);              // CB11 bit 12 (counter preset)
//
// scan() runs die protection and counters on every call and the brake monitor once per
// whole millisecond of `now` (call scan at least every 1 ms; a 10 us scan is exact).
#include <array>
#include <cstdint>

#include "core/time.hpp"
#include "models/ans1/brake_monitor.hpp"
#include "models/ans1/die_protection.hpp"
#include "models/ans1/fault_outputs.hpp"
#include "models/ans1/monitor_setup.hpp"
#include "models/ans1/monitor_variants.hpp"
#include "models/ans1/production_counters.hpp"

namespace hilrig::models::ans1 {

struct MonitorInputs {
  std::uint16_t gmp = 0;    // Global Machine Position 0..FSC-1
  std::int64_t pos4096 = 0; // transducer position, 4096 counts/turn base, unwrapped
  std::uint16_t inputs = 0; // logical input states (after polarity and forces), bit n-1 = input n
};

class Monitors {
public:
  explicit Monitors(MonitorFaults faults = {}, Nanos brake_sample_start = BrakeMonitor::kSampleStart);

  void configure(const MonitorSetup& setup, std::uint16_t full_scale_count);
  void scan(Nanos now, const MonitorInputs& in);
  void clear_errors() { brake_.clear_errors(); }
  void preset_counter(CounterId id, std::uint32_t value) { counters_.preset(id, value); }

  // Exact scan skipping while the encoder moves (quiet_interval.hpp): where a scan's die
  // windows or part-cycle mark make a difference, and the position a skipped scan would have
  // left (the brake monitor's ticks that can find an edge are deadlines of next_change()).
  void keep_quiet(QuietInterval& quiet, std::uint16_t gmp) const {
    die_.keep_quiet(quiet, gmp);
    counters_.keep_quiet(quiet, gmp);
  }
  void settle_position(std::uint16_t gmp) {
    if (started_) gmp_ = gmp;
    counters_.settle(gmp);
  }
  // The next 1 ms tick that only records the position history: an unused brake monitor's, or
  // an idle one's whose input is as the last scan read it (BrakeMonitor::tick_records_only);
  // max otherwise (its ticks are next_change() deadlines) and before the first scan.
  // idle_tick() records it with the position a scan at its grid point read: a caller that
  // records every idle tick before a scan reads an input that changed (Ans1::settle_position).
  [[nodiscard]] Nanos next_idle_tick() const { return brake_ticks_idle() ? next_tick_ : Nanos::max(); }
  void idle_tick(std::int64_t pos4096) {
    brake_.tick(next_tick_, brake_.released(), pos4096, gmp_);
    next_tick_ += BrakeMonitor::kTick;
  }
  // `copy` is a copy of this that ran scan(): it left everything as it was. scan() never
  // writes a setup (its own, die protection's), so those are not compared (scan skipping's
  // repeat check, Ans1::scan_repeats, runs this after every scan that may arm).
  [[nodiscard]] bool scan_left_alone(const Monitors& copy) const {
    return started_ == copy.started_ && next_tick_ == copy.next_tick_ && inputs_ == copy.inputs_ &&
           gmp_ == copy.gmp_ && rising_ == copy.rising_ && falling_ == copy.falling_ &&
           die_.same_state(copy.die_) && counters_ == copy.counters_ && brake_ == copy.brake_;
  }
  [[nodiscard]] OutputClaims claims() const;
  // The earliest time at which scan() with unchanged inputs can change what the monitors
  // report: a brake monitor's tick or debounce sample while one is set up (not an idle tick
  // when `idle_ticks_recorded`), a die-protection level qualifying.
  // Ticks of an unused brake monitor only record position history, which nothing reads
  // before the monitor is set up, so they are caught up at the next scan. An idle set-up
  // monitor's ticks are deadlines unless `idle_ticks_recorded` (next_idle_tick()).
  [[nodiscard]] Nanos next_change(bool idle_ticks_recorded) const;
  [[nodiscard]] const MonitorSetup& setup() const { return setup_; }
  [[nodiscard]] const BrakeMonitor& brake() const { return brake_; }
  [[nodiscard]] const DieProtection& die() const { return die_; }
  [[nodiscard]] const ProductionCounters& counters() const { return counters_; }
  [[nodiscard]] std::uint16_t inputs() const { return inputs_; }
  [[nodiscard]] std::uint16_t gmp() const { return gmp_; }
  [[nodiscard]] std::uint16_t rising_position(int input) const {
    return rising_[static_cast<std::size_t>(input - 1)];
  }
  [[nodiscard]] std::uint16_t falling_position(int input) const {
    return falling_[static_cast<std::size_t>(input - 1)];
  }

private:
  [[nodiscard]] bool brake_ticks_idle() const;

  MonitorSetup setup_{};
  BrakeMonitor brake_;
  DieProtection die_;
  ProductionCounters counters_;
  bool started_ = false;
  Nanos next_tick_{};
  std::uint16_t inputs_ = 0;
  std::uint16_t gmp_ = 0;
  std::array<std::uint16_t, 16> rising_{};
  std::array<std::uint16_t, 16> falling_{};
  friend bool operator==(const Monitors&, const Monitors&) = default;
};

} // namespace hilrig::models::ans1
