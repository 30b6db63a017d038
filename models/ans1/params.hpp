#pragma once
// Every choice the ANS1 manual leaves open ([MODEL] in docs/spec/ans1.md) as a named parameter,
// with the digest's default. The rig must measure the real board; these only make the
// virtual DUT definite.
#include "core/time.hpp"

namespace hilrig::models::ans1 {

struct Params {
  // §4.0: one position-and-output scan every 10 us on a master; the outputs computed in a
  // scan reach the pins output_delay later. Latency from a position crossing to the output
  // edge is then within [output_delay, scan_period + output_delay] = [10, 20] us, the manual's
  // "10 to 20 us" master throughput (L572).
  Nanos master_scan_period = microseconds(10);
  // A slave's throughput is 50 us (L576): 40 us scan + 10 us output delay.
  Nanos slave_scan_period = microseconds(40);
  Nanos output_delay = microseconds(10);
  // [MODEL] The manual states one throughput for both edges ("10 to 20 microseconds,
  // depending on load", L572-L574): the model turns each output off as fast as on. A
  // detection-power knob (README, docs/power.md): a driver that turns off this much slower
  // (< 0: turns on slower) than it turns on, e.g. a sourcing output (L1658) or a solid-state
  // relay (L1562) on its load, stretches (shortens) every ON pulse at the pin by it.
  Nanos output_off_skew{0};
  // [MODEL] Where the first scan falls after power-up (the manual gives none: the scan clock
  // free-runs against the machine). The rig draws it from the run's seed, in [0, scan).
  Nanos scan_phase{0};

  // §4.10: the brake input's debounce samples it once a ms for 16 ms, starting 16 ms after the
  // application edge (L1039); 12 applied samples qualify it (L1040). A detection-power knob
  // (README): a later start lengthens the narrowest application that counts; a duration, so
  // the knob moves to the ns (samples off the whole ms fall between the 1 ms ticks).
  Nanos brake_sample_start = milliseconds(16);

  // §4.2: the speed value is updated every 14.6 ms (L820).
  Nanos speed_update_period = microseconds(14'600);

  // Resolver excitation the model generates on R1/R2 (frequency not stated, A35; foreign
  // resolvers are accepted from 2.2 to 7 kHz, L1455). The stator signals are sampled at each
  // excitation peak (positive and negative), so the angle is refreshed every half period.
  double excitation_hz = 5000.0;
  double excitation_amplitude = 1.0; // peak value of the reference, in the stator signals' unit
  // Stator amplitude sqrt(S^2 + C^2) relative to the reference peak outside
  // [min, max] is a Resolver Fault. TR is 0.9..1.0 (L1456); an open pair drops below min.
  double resolver_min_ratio = 0.75;
  double resolver_max_ratio = 1.25;

  // §4.6: an advance longer than one cycle sets RPM Clamped and is held at FSC - 1 counts.
  // (The clamp value is not stated.)
  // §4.7: a Time-Only output whose From edge comes again before expiry restarts its timer
  // (A39).
  bool time_only_retrigger_restarts = true;
  // §4.7: a timed output's timer expires timer_ms after its start (W-10, 1 ms units). A
  // detection-power knob (README, docs/power.md): a timer running off by this much makes every
  // timed output's on time that much longer (or shorter). 0 = the manual's timer.
  Nanos timer_error{0};

  // Not the device's: how the simulation runs it. false skips every scan that cannot change
  // anything (exactly: the same outputs, words and trace as scanning every period,
  // docs/virtual-time.md); true scans every period, the oracle the skipping is tested against.
  bool exact_scan = false;

  // §4.2/A46: Time of Rotation saturates at the 16-bit maximum (6,553.5 ms).
  // §5.5/A36: a quadrature count starts at 0 at power-up.
};

} // namespace hilrig::models::ans1
