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

#include <cctype>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

#include "rig/campaign/limits.hpp"
#include "rig/cli/number_checks.hpp"
#include "rig/cli/synth_command.hpp"
#include "signals/move_builders.hpp"
#include "signals/resolver.hpp"
#include "signals/resolver_frames.hpp"

namespace hilrig::cli {

namespace limits = campaign::limits;

namespace {

// The most samples one run writes: each is a reference, a SIN and a COS value in the trace
// (~130 bytes while it is built, ~60 in the VCD): 5 million is ~650 MB, 25 s at 200 kHz.
constexpr std::int64_t kMaxSamples = 5'000'000;
// The most angle frames: a CAN frame and two values each in the trace.
constexpr std::int64_t kMaxFrames = 1'000'000;
// The angle frame's speed field: 24 bits signed at 1/4096 turn/s (signals/resolver_frames.hpp,
// rt-config/can/hilrig-frontend.dbc). It holds every speed --rpm may ask for, so a frame never
// saturates: encode() clamps silently, and a clamped speed would make the node drift.
constexpr double kFrameMaxTurnsPerS = 8'388'607.0 / 4096.0;
static_assert(limits::kMaxRpm / 60.0 <= kFrameMaxTurnsPerS, "--rpm must fit the ResolverAngle speed field");
// Gains and phase shifts of the winding faults: a fault of one winding, not a second resolver.
constexpr double kMaxGain = limits::kMaxRatio;
constexpr double kMaxPhaseDeg = 360.0;

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
  std::int64_t channel = 0; // signed: CLI11 reads "-1" into an unsigned as 2^64 - 1
  std::string can_bus = "can0";
  std::string can_log;
};

double radians(double deg) { return deg * std::numbers::pi / 180.0; }

void write_can_log(const TraceRecorder& trace, const std::string& path) {
  write_output_file(path, [&trace](std::ostream& out) { write_candump(trace, out); });
}

// A Linux network interface name (dev_valid_name, IFNAMSIZ 16 with its NUL): a candump line
// is "(time) IFACE ID#DATA", so a space would split it and an empty name leave a field out.
constexpr std::size_t kMaxIfName = 15;

void check_can_bus(const std::string& name) {
  const auto bad = [&name](const std::string& why) {
    return CLI::ValidationError("--can-bus", fmt::format("an interface name of 1 .. {} characters, without "
                                                         "whitespace, '/' or ':', not . or .. ({}: got '{}')",
                                                         kMaxIfName, why, name));
  };
  if (name.empty()) throw bad("empty");
  if (name.size() > kMaxIfName) throw bad(fmt::format("{} characters", name.size()));
  if (name == "." || name == "..") throw bad("not a name");
  for (const char c : name)
    if (std::isspace(static_cast<unsigned char>(c)) != 0 || c == '/' || c == ':')
      throw bad(fmt::format("'{}' in it", c == '\t' ? std::string("\\t") : std::string(1, c)));
}

constexpr double kMaxRateHz = 1e9; // the trace's resolution: one sample a nanosecond

void check_phase(const std::string& option, double deg) {
  require_within(option, deg, -kMaxPhaseDeg, kMaxPhaseDeg, fmt::format("-{0} .. {0} degrees", kMaxPhaseDeg));
}

// The options against the campaign's limits (docs/campaigns.md "Ranges and limits") and the
// signal library's resolver (2.2 .. 7 kHz excitation, signals/resolver.hpp).
void check_resolver(const CLI::App& cmd, const ResolverOptions& o) {
  // The stream's options do nothing without the stream: refused, not ignored.
  const bool frames_wanted = o.frames || !o.can_log.empty();
  for (const char* option : {"--frame-period", "--channel", "--can-bus"})
    refuse_unless_applies(cmd, option, frames_wanted,
                          "only with --can-frames or --can-log: it shapes the angle frames they write");
  if (frames_wanted) check_can_bus(o.can_bus);
  require_within("--rpm", o.rpm, -limits::kMaxRpm, limits::kMaxRpm,
                 fmt::format("-{0} .. {0} rpm", limits::kMaxRpm));
  const double max_deg = limits::kMaxTurns * 360.0;
  require_within("--start", o.start_deg, -max_deg, max_deg,
                 fmt::format("-{0} .. {0} degrees ({1} turns)", max_deg, limits::kMaxTurns));
  require_within("--excitation-hz", o.excitation_hz, signals::kMinExcitationHz, signals::kMaxExcitationHz,
                 fmt::format("{} .. {} Hz", signals::kMinExcitationHz, signals::kMaxExcitationHz));
  if (!(o.amplitude > 0.0 && o.amplitude <= limits::kMaxAmplitude))
    throw CLI::ValidationError(
        "--amplitude", fmt::format("0 < amplitude <= {} (got {})", limits::kMaxAmplitude, o.amplitude));
  if (!(o.tr > 0.0 && o.tr <= limits::kMaxRatio))
    throw CLI::ValidationError("--tr", fmt::format("0 < ratio <= {} (got {})", limits::kMaxRatio, o.tr));
  const auto gain = fmt::format("0 .. {}", kMaxGain);
  require_within("--sin-gain", o.sin_gain, 0.0, kMaxGain, gain);
  require_within("--cos-gain", o.cos_gain, 0.0, kMaxGain, gain);
  check_phase("--excitation-phase", o.excitation_phase_deg);
  check_phase("--sin-phase", o.sin_phase_deg);
  check_phase("--cos-phase", o.cos_phase_deg);
  if (o.channel < 0 || o.channel > 15)
    throw CLI::ValidationError("--channel", fmt::format("0 .. 15 (got {})", o.channel));
  // Samples of the carrier at or below twice its frequency alias it (at exactly twice they can
  // all be zero crossings); above 1 GHz two samples share the trace's nanosecond.
  if (!(o.rate_hz > 2.0 * o.excitation_hz && o.rate_hz <= kMaxRateHz))
    throw CLI::ValidationError(
        "--rate",
        fmt::format("above twice --excitation-hz ({} Hz: the carrier's Nyquist rate) and at most {:.0f} "
                    "Hz, one sample a nanosecond (got {})",
                    2.0 * o.excitation_hz, kMaxRateHz, o.rate_hz));
}

// Sample i at round(i / rate) up to and including the end of the run.
std::int64_t samples_in(Nanos duration, double rate_hz) {
  const double samples = std::floor(duration.seconds() * rate_hz + 1e-9) + 1.0;
  if (samples > static_cast<double>(kMaxSamples))
    throw CLI::ValidationError("resolver",
                               fmt::format("--duration x --rate makes {:.0f} samples; synth writes at "
                                           "most {}: shorten --duration or lower --rate",
                                           samples, kMaxSamples));
  return static_cast<std::int64_t>(samples);
}

// Frame k at k x period up to and including the end of the run.
Nanos frame_period_of(const ResolverOptions& o, Nanos duration) {
  const Nanos period = parse_positive_duration(o.frame_period, "--frame-period");
  const std::int64_t frames = duration.count() / period.count() + 1;
  if (frames > kMaxFrames)
    throw CLI::ValidationError("--frame-period",
                               fmt::format("--duration / --frame-period makes {} angle frames; "
                                           "synth writes at most {}: a longer --frame-period",
                                           frames, kMaxFrames));
  return period;
}

void run_resolver(const CLI::App& cmd, const ResolverOptions& o) {
  using namespace signals;
  check_resolver(cmd, o);
  const Nanos duration = parse_positive_duration(o.duration, "--duration");
  const auto count = static_cast<std::size_t>(samples_in(duration, o.rate_hz));
  const bool frames_wanted = o.frames || !o.can_log.empty();
  const Nanos period = frames_wanted ? frame_period_of(o, duration) : Nanos{0};
  // Every output is checked before any is written: a refused --out leaves no --can-log behind.
  require_writable("--out", o.out);
  if (!o.can_log.empty()) {
    require_writable("--can-log", o.can_log);
    if (same_file(o.can_log, o.out))
      throw CLI::ValidationError("--can-log", "a file other than --out's (got " + o.out + ")");
  }
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
  for (const ResolverSample& s : resolver.sample_block(Nanos{0}, o.rate_hz, count)) {
    trace.real(ref, s.time, s.reference);
    trace.real(sin_sig, s.time, s.sin);
    trace.real(cos_sig, s.time, s.cos);
  }

  std::size_t frames = 0;
  if (frames_wanted) {
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
  }

  write_vcd_file(trace, o.out);
  if (!o.can_log.empty()) write_can_log(trace, o.can_log);
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
  cmd->add_option("--rpm", o->rpm, fmt::format("shaft speed, RPM (signed): -{0} .. {0}", limits::kMaxRpm));
  cmd->add_option("--start", o->start_deg,
                  fmt::format("start angle, degrees: -{0} .. {0}", limits::kMaxTurns * 360.0));
  cmd->add_option(
      "--duration", o->duration,
      fmt::format("run time, e.g. 10ms: 1ns .. 3600s, at most {} samples at --rate", kMaxSamples));
  cmd->add_option("--rate", o->rate_hz, "sample rate, Hz: above 2 x --excitation-hz, at most 1e9")
      ->check(positive_number());
  cmd->add_option(
      "--excitation-hz", o->excitation_hz,
      fmt::format("reference frequency, {} .. {} Hz", signals::kMinExcitationHz, signals::kMaxExcitationHz));
  cmd->add_option("--amplitude", o->amplitude,
                  fmt::format("reference peak, V: > 0, <= {}", limits::kMaxAmplitude));
  cmd->add_option("--excitation-phase", o->excitation_phase_deg,
                  "reference phase at t = 0, degrees: -360 .. 360");
  cmd->add_option("--tr", o->tr,
                  fmt::format("transformation ratio (stator / reference): > 0, <= {}", limits::kMaxRatio));
  cmd->add_flag("--sin-open", o->sin_open, "fault: SIN winding open");
  cmd->add_flag("--cos-open", o->cos_open, "fault: COS winding open");
  cmd->add_option("--sin-gain", o->sin_gain,
                  fmt::format("fault: SIN amplitude imbalance (gain), 0 .. {}", kMaxGain));
  cmd->add_option("--cos-gain", o->cos_gain,
                  fmt::format("fault: COS amplitude imbalance (gain), 0 .. {}", kMaxGain));
  cmd->add_option("--sin-phase", o->sin_phase_deg, "fault: SIN carrier phase shift, degrees: -360 .. 360");
  cmd->add_option("--cos-phase", o->cos_phase_deg, "fault: COS carrier phase shift, degrees: -360 .. 360");
  cmd->add_flag("--excitation-loss", o->excitation_lost, "fault: rotor not excited (stators zero)");
  cmd->add_flag(
      "--can-frames", o->frames,
      "add the emulator-node angle frames (0x120) to the trace (speed field +-2047.99 turn/s: every --rpm "
      "fits)");
  cmd->add_option("--frame-period", o->frame_period,
                  fmt::format("angle frame period, e.g. 1ms: 1ns .. 3600s, at most {} frames (with "
                              "--can-frames or --can-log)",
                              kMaxFrames));
  cmd->add_option("--channel", o->channel, "resolver channel in the frames, 0 .. 15 (with the frames)");
  cmd->add_option("--can-bus", o->can_bus,
                  "bus name in the trace and the candump log: a Linux interface name, 1 .. 15 characters, "
                  "no whitespace, '/' or ':' (with the frames)");
  cmd->add_option("--can-log", o->can_log, "also write the angle frames as a candump -l log");
  on_run(*cmd, [cmd, o] {
    run_resolver(*cmd, *o);
    return 0;
  });
}

const bool registered = register_synth_kind(&add_synth_resolver);

} // namespace

} // namespace hilrig::cli
