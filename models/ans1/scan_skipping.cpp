// Exact scan skipping (docs/virtual-time.md). A scan is a function of the device state, what
// it reads from outside (pins, host words, speed, settings) and the time. When no outside
// change preceded a scan and that scan left the state as it found it, every later scan does the
// same until either something outside changes (wake(), from every edge handler and mutator) or
// a time-driven behaviour's deadline arrives (next_change()). The scans in between are skipped:
// they would have changed nothing, so results, words and traces are the same as scanning every
// period (Params::exact_scan, the oracle the differential test compares against).
#include <algorithm>
#include <optional>
#include <tuple>

#include "models/ans1/ans1.hpp"

namespace hilrig::models::ans1 {

// Every member a scan may write. A member added to the scan's state belongs here; one left
// out makes a changing scan look quiet, which the differential test catches.
struct Ans1::ScanSnapshot {
  std::array<OutputChannel, kOutputCount> channels;
  Monitors monitors;
  ShiftRegister shift_register;
  PositionSetup position; // presets move the offset
  std::tuple<std::int64_t, std::uint16_t, bool, bool, bool> resolver;
  std::tuple<std::uint16_t, std::uint16_t, bool> gmp;
  std::tuple<std::uint16_t, std::uint16_t, std::uint16_t> inputs;
  std::tuple<std::uint16_t, std::uint16_t, std::uint16_t> outputs;
  std::tuple<std::uint16_t, std::uint16_t, std::uint16_t, std::uint16_t, std::uint16_t, std::uint16_t,
             std::uint16_t>
      masks;
  std::tuple<std::uint16_t, Nanos> rotation;
  std::tuple<bool, bool, ErrorCode, bool> host;
  friend bool operator==(const ScanSnapshot&, const ScanSnapshot&) = default;
};

Ans1::ScanSnapshot Ans1::snapshot() const {
  return ScanSnapshot{
      channels_,
      monitors_,
      shift_register_,
      position_,
      {resolver_count_, resolver_angle_, resolver_seen_, resolver_fault_active_, resolver_fault_latched_},
      {gmp_, previous_gmp_, first_scan_},
      {electrical_inputs_, active_inputs_, previous_active_inputs_},
      {ls_, outputs_, queued_levels_},
      {masks_.calc, masks_.simple, masks_.pulse, masks_.window, masks_.shift_register, masks_.rpm,
       masks_.timer},
      {time_of_rotation_, last_wrap_},
      {host_.transmit_seen(), host_.acknowledge(), host_.error(), host_.hardware_fault()},
  };
}

Nanos Ans1::next_change() const {
  Nanos next = monitors_.next_change();
  for (const OutputChannel& channel : channels_) {
    next = std::min(next, channel.next_change());
  }
  // The stators are sampled at each excitation peak; the last sampled one is not in the
  // snapshot, so a peak that reads the same angle keeps the scan quiet.
  if (!position_.slave_mode && position_.sensor == SensorType::Resolver) {
    next = std::min(next, excitation_.next_peak(scheduler_.now()));
  }
  return next;
}

Nanos Ans1::grid_at_or_after(Nanos t) const {
  if (t == Nanos::max()) {
    return t;
  }
  const Nanos period = scan_period();
  const Nanos first = grid_origin_ + period;
  if (t <= first) {
    return first;
  }
  const std::int64_t periods = (t - grid_origin_ + period - Nanos{1}) / period;
  return grid_origin_ + period * periods;
}

void Ans1::wake() {
  changed_outside_ = true;
  if (params_.exact_scan || in_scan_ || !powered_) {
    return; // scanning every period, or the running scan schedules the next
  }
  wake_now();
}

void Ans1::wake_now() {
  if (in_scan_) {
    return;
  }
  const Nanos at = grid_at_or_after(scheduler_.now());
  if (at < scan_at_) {
    scheduler_.cancel(scan_event_);
    schedule_scan(at);
  }
}

void Ans1::run_scan() {
  const Nanos now = scheduler_.now();
  scan_at_ = Nanos::max();
  grid_origin_ = now;
  const bool outside = changed_outside_;
  changed_outside_ = false;
  std::optional<ScanSnapshot> before;
  if (!params_.exact_scan && !outside) {
    before = snapshot();
  }
  in_scan_ = true;
  scan();
  in_scan_ = false;
  // The period may have changed in the scan.
  Nanos next = now + scan_period();
  if (before && !changed_outside_ && *before == snapshot()) {
    next = grid_at_or_after(next_change()); // asleep until then, or until wake()
  }
  if (next != Nanos::max()) {
    schedule_scan(next);
  }
}

} // namespace hilrig::models::ans1
