#include "models/ans1/output_channel.hpp"

#include "models/ans1/position.hpp"
#include "models/ans1/setpoint.hpp"
#include "models/ans1/shift_register.hpp"

namespace hilrig::models::ans1 {

void OutputChannel::configure(const OutputSetup& setup) {
  setup_ = setup;
  simple_inputs_ = anding_mask(setup, AndingMode::Simple);
  pulse_inputs_ = anding_mask(setup, AndingMode::Pulse);
  const std::uint16_t window = anding_mask(setup, AndingMode::Window);
  window_input_ = -1;
  for (int i = 0; i < kInputCount; ++i) {
    if ((window & (1U << static_cast<unsigned>(i))) != 0) {
      window_input_ = i; // at most one per output (L983)
      break;
    }
  }
  timer_.reset();
  pulse_.reset();
  window_.reset();
}

void OutputChannel::update_advances(double speed, std::uint16_t fsc, double scale) {
  advances_ = advance_counts(setup_, speed, fsc, scale);
}

std::uint16_t OutputChannel::ls_position(std::uint16_t gmp, std::uint16_t fsc) const {
  return ans1::ls_position(gmp, setup_.ls_offset, fsc);
}

void OutputChannel::preset(std::uint16_t gmp, std::optional<std::uint16_t> value) {
  if (value) {
    setup_.ls_preset_value = *value;
  }
  // Kept within -(FSC-1)..+(FSC-1) like a programmed offset.
  setup_.ls_offset = static_cast<std::int32_t>(setup_.ls_preset_value) - gmp;
}

EdgeShift OutputChannel::edge_shift(const ScanState& scan) const {
  // Edges move against the direction of travel, so they fire early whichever way it turns.
  const int travel = scan.speed > 0.0 ? 1 : (scan.speed < 0.0 ? -1 : 0);
  const int direction = scan.advance_wrong_sign ? -travel : travel;
  const std::int32_t lead = direction * advances_.lead;
  const std::int32_t trail = direction * advances_.trail;
  // Lead and Trail Advance Times compensate the device's activation and release (L888) and
  // advance the output's leading and trailing edges (L2621, L2622). Turning backwards the
  // output turns on at To and off at From, so To takes the lead and From the trail, and the
  // trail advanced past the lead forces the pair off as forward (L890). The Variable mode's
  // times belong to the setpoints by name (L912, L913).
  if (travel < 0 && setup_.advance_mode == AdvanceMode::Fixed) {
    return EdgeShift{trail, lead, lead};
  }
  return EdgeShift{lead, trail, lead};
}

void OutputChannel::keep_quiet(QuietInterval& quiet, const ScanState& scan) const {
  if (timer_.holding()) {
    quiet.pin(scan.gmp); // off until the position moves one count
    return;
  }
  const EdgeShift shift = edge_shift(scan);
  for (const SetpointPair& pair : setup_.pairs) {
    if (!pair.used()) {
      continue;
    }
    // p = GMP + LS offset, so the pair's arc of p is an arc of GMP shifted back by the offset.
    // A stitched pair's span is the pair unstitched (scan's inside_pair).
    const SetpointPair span{pair.from, pair.to, 0, 0};
    const PairArc arc = pair_arc(span, scan.fsc, shift, scan.late_wrap_to);
    quiet.keep_arc(scan.gmp, arc.start - setup_.ls_offset, arc.length, scan.fsc);
    if (pair.stitched()) {
      // pair_on's stitched rule: the pattern at d = p - From + stitch shift, which a GMP step moves by
      // one; keep the run of d around the present one.
      const std::uint16_t p = ls_position(scan.gmp, scan.fsc);
      const auto d =
          static_cast<std::int32_t>(wrap(static_cast<std::int64_t>(p) - pair.from + shift.stitch, scan.fsc));
      const StitchRun run =
          stitch_run(d, pair_length(pair, scan.fsc), pair.on_stitch, pair.off_stitch, scan.fsc);
      quiet.keep_run(scan.gmp, d - run.first, run.last - d);
    }
  }
  if (window_input_ >= 0) { // in_window: low..high inclusive, wrapping through 0
    quiet.keep_arc(scan.gmp, setup_.window_low,
                   wrap(static_cast<std::int64_t>(setup_.window_high) - setup_.window_low, scan.fsc) + 1,
                   scan.fsc);
  }
}

OutputState OutputChannel::scan(const ScanState& scan, bool retrigger_restarts) {
  const std::uint16_t p = ls_position(scan.gmp, scan.fsc);
  const EdgeShift shift = edge_shift(scan);

  OutputState s;
  int inside_pair = -1;
  for (int k = 0; k < kPairsPerOutput; ++k) {
    const SetpointPair& pair = setup_.pairs[static_cast<std::size_t>(k)];
    if (!pair.used()) {
      continue;
    }
    const bool on = pair_on(p, pair, scan.fsc, shift, scan.late_wrap_to);
    if (on) {
      s.calc = true;
    }
    if (inside_pair >= 0) {
      continue;
    }
    // The pair's span ignores stitching; without stitching it is the pair itself (once per
    // scan per pair is most of the scan's cost).
    const SetpointPair span{pair.from, pair.to, 0, 0};
    if (pair.stitched() ? pair_on(p, span, scan.fsc, shift, scan.late_wrap_to) : on) {
      inside_pair = k;
    }
  }

  const bool timed = timer_.step(s.calc, p, scan.now, setup_.timer_type, setup_.timer_ms, retrigger_restarts,
                                 scan.timer_error);
  s.timer_ok = !timer_.expired();
  s.rpm = speed_enabled(setup_.rpm_low, setup_.rpm_high, scan.speed_reported);
  s.simple = (scan.active_inputs & simple_inputs_) == simple_inputs_;
  s.pulse = pulse_.step(inside_pair, scan.active_inputs, pulse_inputs_);
  if (window_input_ >= 0) {
    const bool inside = in_window(scan.gmp, setup_.window_low, setup_.window_high);
    s.window = window_.step(inside, (scan.active_inputs & (1U << static_cast<unsigned>(window_input_))) != 0);
  }
  if (setup_.sr_bit != 0) {
    s.sr = scan.shift_register_enabled && scan.shift_register != nullptr &&
           scan.shift_register->bit(setup_.sr_bit);
  }
  s.ls = timed && s.rpm && s.simple && s.pulse && s.window && s.sr;
  state_ = s;
  return s;
}

} // namespace hilrig::models::ans1
