// `hilrig synth resolver`: the reference and the SIN/COS stator signals of a resolver
// turning at constant speed, sampled at --rate, with optional winding faults; optionally
// the angle frames a rig would stream to the resolver-emulator node (ResolverAngle 0x120,
// signals/resolver_frames.hpp) into the trace and a candump log.
//
// The profile is a constant speed from a start angle: synth_command.hpp does not expose
// the quadrature kind's profile options (trapezoid, S-curve, press), so they are not
// copied here.

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

#include "rig/cli/number_checks.hpp"
#include "rig/cli/synth_command.hpp"
#include "signals/move_builders.hpp"
#include "signals/resolver.hpp"
#include "signals/resolver_frames.hpp"

namespace hilrig::cli {

namespace {

struct ResolverOptions {
  std::string out;
  std::string name = "rig.res";
  double rpm = 0.0;
  double start_deg = 0.0;
  std::string duration = "10ms";
  double rate_hz = 200'000.0;
  double excitation_hz = 5'000.0;
  double amplitude = 1.0;
  double excitation_phase_deg = 0.0;
  double tr = 1.0;
  // Faults.
  bool sin_open = false;
  bool cos_open = false;
  double sin_gain = 1.0;
  double cos_gain = 1.0;
  double sin_phase_deg = 0.0;
  double cos_phase_deg = 0.0;
  bool excitation_lost = false;
  // The emulator-node stream.
  bool frames = false;
  std::string frame_period = "1ms";
  unsigned channel = 0;
  std::string can_bus = "can0";
  std::string can_log;
};

double radians(double deg) { return deg * std::numbers::pi / 180.0; }

void write_can_log(const TraceRecorder& trace, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("cannot open " + path + " for writing");
  write_candump(trace, out);
  if (!out) throw std::runtime_error("cannot write " + path);
}

void run_resolver(const ResolverOptions& o) {
  using namespace signals;
  const Nanos duration = parse_duration(o.duration);
  if (duration <= Nanos::zero()) throw CLI::ValidationError("--duration", "must be > 0");
  const double speed = o.rpm / 60.0; // turns/s
  MotionProfile profile(o.start_deg / 360.0);
  constant_speed(profile, speed, duration);

  ResolverParams params;
  params.excitation_hz = o.excitation_hz;
  params.excitation_amplitude = o.amplitude;
  params.excitation_phase_rad = radians(o.excitation_phase_deg);
  params.transformation_ratio = o.tr;
  Resolver resolver = [&] {
    try {
      return Resolver(params, angle_from_profile(profile, 1.0));
    } catch (const std::invalid_argument& e) {
      throw CLI::ValidationError("resolver", e.what());
    }
  }();
  ResolverFaults faults;
  faults.sin_open = o.sin_open;
  faults.cos_open = o.cos_open;
  faults.sin_gain = o.sin_gain;
  faults.cos_gain = o.cos_gain;
  faults.sin_phase_rad = radians(o.sin_phase_deg);
  faults.cos_phase_rad = radians(o.cos_phase_deg);
  faults.excitation_lost = o.excitation_lost;
  resolver.set_faults(faults);

  TraceRecorder trace;
  const std::uint32_t ref = trace.declare(o.name + ".ref", SignalKind::Real);
  const std::uint32_t sin_sig = trace.declare(o.name + ".sin", SignalKind::Real);
  const std::uint32_t cos_sig = trace.declare(o.name + ".cos", SignalKind::Real);
  // Sample i at round(i / rate) up to and including the end of the run.
  const auto count = static_cast<std::size_t>(std::floor(duration.seconds() * o.rate_hz + 1e-9)) + 1;
  for (const ResolverSample& s : resolver.sample_block(Nanos{0}, o.rate_hz, count)) {
    trace.real(ref, s.time, s.reference);
    trace.real(sin_sig, s.time, s.sin);
    trace.real(cos_sig, s.time, s.cos);
  }

  std::size_t frames = 0;
  if (o.frames || !o.can_log.empty()) {
    const Nanos period = parse_duration(o.frame_period);
    if (period <= Nanos::zero()) throw CLI::ValidationError("--frame-period", "must be > 0");
    if (o.channel > 15) throw CLI::ValidationError("--channel", "0..15");
    // Frame k is stamped at k * period and carries the angle and speed at that instant: the
    // stream as the node should see it (no bus here; on a bus the frame lands ~216..264 us
    // later at 500 kbit/s unless the streamer leads by that, models/resolver_emulator).
    // The raw angle field (1/2^24 turn) and sequence also go to the VCD, for a viewer.
    const std::uint32_t angle = trace.declare(o.name + ".frame.angle", SignalKind::Integer, 24);
    const std::uint32_t sequence = trace.declare(o.name + ".frame.sequence", SignalKind::Integer, 4);
    for (Nanos t{0}; t <= duration; t += period, ++frames) {
      ResolverAngleFrame f;
      f.channel = static_cast<std::uint8_t>(o.channel);
      f.angle_turns = profile.position(t);
      f.speed_turns_per_s = profile.velocity(t);
      f.sequence = static_cast<std::uint8_t>(frames & 0xFu);
      f.sin_open = o.sin_open;
      f.cos_open = o.cos_open;
      f.valid = !o.excitation_lost;
      const CanFrame frame = encode(f);
      trace.can(o.can_bus, t, frame);
      trace.value(angle, t, static_cast<std::int64_t>(get_raw(frame, 0, 24)));
      trace.value(sequence, t, static_cast<std::int64_t>(f.sequence));
    }
    if (!o.can_log.empty()) write_can_log(trace, o.can_log);
  }

  write_vcd_file(trace, o.out);
  if (o.out != "-")
    fmt::print("{}: {} samples at {} Hz over {:.6f} s, angle {:.3f} -> {:.3f} deg, {} angle frames\n", o.out,
               count, o.rate_hz, duration.seconds(), o.start_deg, profile.end_position() * 360.0, frames);
}

void add_synth_resolver(CLI::App& synth) {
  auto o = std::make_shared<ResolverOptions>();
  CLI::App* cmd = synth.add_subcommand(
      "resolver",
      "Resolver reference and SIN/COS stator signals at constant speed (and the emulator-node CAN stream)");
  cmd->add_option("--out", o->out, "VCD file to write ('-' for stdout)")->required();
  cmd->add_option("--name", o->name, "signal name prefix");
  cmd->add_option("--rpm", o->rpm, "shaft speed, RPM (signed)");
  cmd->add_option("--start", o->start_deg, "start angle, degrees");
  cmd->add_option("--duration", o->duration, "run time, e.g. 10ms");
  cmd->add_option("--rate", o->rate_hz, "sample rate, Hz")->check(positive_number());
  cmd->add_option("--excitation-hz", o->excitation_hz, "reference frequency, 2200..7000 Hz");
  cmd->add_option("--amplitude", o->amplitude, "reference peak, V");
  cmd->add_option("--excitation-phase", o->excitation_phase_deg, "reference phase at t = 0, degrees");
  cmd->add_option("--tr", o->tr, "transformation ratio (stator / reference)");
  cmd->add_flag("--sin-open", o->sin_open, "fault: SIN winding open");
  cmd->add_flag("--cos-open", o->cos_open, "fault: COS winding open");
  cmd->add_option("--sin-gain", o->sin_gain, "fault: SIN amplitude imbalance (gain)");
  cmd->add_option("--cos-gain", o->cos_gain, "fault: COS amplitude imbalance (gain)");
  cmd->add_option("--sin-phase", o->sin_phase_deg, "fault: SIN carrier phase shift, degrees");
  cmd->add_option("--cos-phase", o->cos_phase_deg, "fault: COS carrier phase shift, degrees");
  cmd->add_flag("--excitation-loss", o->excitation_lost, "fault: rotor not excited (stators zero)");
  cmd->add_flag("--can-frames", o->frames, "add the emulator-node angle frames (0x120) to the trace");
  cmd->add_option("--frame-period", o->frame_period, "angle frame period, e.g. 1ms");
  cmd->add_option("--channel", o->channel, "resolver channel in the frames, 0..15");
  cmd->add_option("--can-bus", o->can_bus, "bus name in the trace and the candump log");
  cmd->add_option("--can-log", o->can_log, "also write the angle frames as a candump -l log");
  on_run(*cmd, [o] {
    run_resolver(*o);
    return 0;
  });
}

const bool registered = register_synth_kind(&add_synth_resolver);

} // namespace

} // namespace hilrig::cli
