#include "rig/cli/synth_command.hpp"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

#include "rig/cli/exit_status.hpp"
#include "rig/cli/number_checks.hpp"
#include "signals/discrete_bounce.hpp"
#include "signals/discrete_input.hpp"
#include "signals/edge_rate.hpp"
#include "signals/move_builders.hpp"
#include "signals/quadrature_edges.hpp"
#include "signals/quadrature_faults.hpp"

namespace hilrig::cli {

namespace {

std::vector<SynthKindAdder>& synth_kinds() {
  static std::vector<SynthKindAdder> kinds;
  return kinds;
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t at = text.find(sep, start);
    parts.push_back(text.substr(start, at == std::string::npos ? std::string::npos : at - start));
    if (at == std::string::npos) return parts;
    start = at + 1;
  }
}

double parse_number(const std::string& text, const std::string& what) {
  try {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used == text.size()) return v;
  } catch (const std::exception&) {}
  throw CLI::ValidationError(what, "'" + text + "' is not a number");
}

Level parse_level(const std::string& text) {
  if (text == "1" || text == "high" || text == "H") return Level::High;
  if (text == "0" || text == "low" || text == "L") return Level::Low;
  throw CLI::ValidationError("level", "'" + text + "' is not 0/1/high/low");
}

// ---- quadrature -------------------------------------------------------------------

struct QuadratureOptions {
  std::string out;
  std::string profile = "constant";
  std::string name = "rig.enc";
  std::uint32_t lines = 1024;
  double rpm = 600.0;
  std::string duration = "10ms";
  double turns = 1.0;
  double accel = 0.0; // turns/s²
  double decel = 0.0; // turns/s²; 0 = same as accel
  double jerk = 0.0;  // turns/s³
  int steps = 8;
  double brake = 0.0; // turns/s²
  std::string dwell = "0";
  double start_turns = 0.0;
  bool reversed = false;
  std::int64_t index_count = 0;
  std::int64_t index_width = 0;
  std::int64_t index_line = -1;
  bool with_count = false;
  double max_input_hz = 0.0;
  std::string rate_action = "warn";
  // Faults, applied in this order.
  std::vector<std::string> glitches;      // channel,at,width
  std::vector<std::size_t> missing_edges; // index into the edge list
  std::vector<std::size_t> simultaneous;  // index into the edge list
  std::vector<std::string> noise;         // start,length,pulses,seed[,min_width,max_width]
  double phase_error = 0.0;               // fraction of a quarter period
};

signals::QuadChannel parse_channel(const std::string& text) {
  if (text == "A" || text == "a") return signals::QuadChannel::A;
  if (text == "B" || text == "b") return signals::QuadChannel::B;
  if (text == "Z" || text == "z") return signals::QuadChannel::Z;
  throw CLI::ValidationError("--glitch", "'" + text + "' is not A, B or Z");
}

void apply_faults(signals::QuadratureTrace& trace, const QuadratureOptions& o) {
  using namespace signals;
  for (const std::string& g : o.glitches) {
    const auto parts = split(g, ',');
    if (parts.size() != 3) throw CLI::ValidationError("--glitch", "expected channel,at,width");
    inject_glitch(trace, parse_channel(parts[0]), parse_duration(parts[1]), parse_duration(parts[2]));
  }
  for (const std::size_t i : o.missing_edges) inject_missing_edge(trace, i);
  for (const std::size_t i : o.simultaneous) inject_simultaneous_edges(trace, i);
  for (const std::string& n : o.noise) {
    const auto parts = split(n, ',');
    if (parts.size() != 4 && parts.size() != 6)
      throw CLI::ValidationError("--noise", "expected start,length,pulses,seed[,min_width,max_width]");
    NoiseBurst burst;
    burst.start = parse_duration(parts[0]);
    burst.length = parse_duration(parts[1]);
    burst.pulses = static_cast<std::size_t>(parse_number(parts[2], "--noise"));
    burst.seed = static_cast<std::uint64_t>(parse_number(parts[3], "--noise"));
    if (parts.size() == 6) {
      burst.min_width = parse_duration(parts[4]);
      burst.max_width = parse_duration(parts[5]);
    }
    inject_noise_burst(trace, burst);
  }
  if (o.phase_error != 0.0) inject_phase_error(trace, o.phase_error);
}

signals::MotionProfile build_profile(const QuadratureOptions& o) {
  using namespace signals;
  MotionProfile p(o.start_turns);
  const double speed = o.rpm / 60.0; // turns/s
  const double decel = o.decel > 0 ? o.decel : o.accel;
  const auto duration = [&o] {
    const Nanos d = parse_duration(o.duration);
    if (d <= Nanos::zero()) throw CLI::ValidationError("--duration", "must be > 0, got " + o.duration);
    return d;
  };
  if (o.profile == "constant") {
    constant_speed(p, speed, duration());
  } else if (o.profile == "trapezoid") {
    if (o.accel <= 0) throw CLI::ValidationError("--accel", "a trapezoid needs --accel > 0");
    trapezoid_move(p, o.turns, MoveLimits{std::abs(speed), o.accel, decel});
  } else if (o.profile == "scurve") {
    if (o.accel <= 0 || o.jerk <= 0)
      throw CLI::ValidationError("--jerk", "an S-curve needs --accel and --jerk > 0");
    s_curve_move(p, o.turns, SCurveLimits{std::abs(speed), o.accel, o.jerk, o.steps});
  } else if (o.profile == "press") {
    if (o.brake <= 0) throw CLI::ValidationError("--brake", "a press stroke needs --brake > 0");
    press_stroke(p, speed, duration(), o.brake);
  } else {
    throw CLI::ValidationError("--profile", "unknown profile '" + o.profile + "'");
  }
  const Nanos dwell = parse_duration(o.dwell);
  if (dwell > Nanos::zero()) {
    if (p.at_rest())
      p.dwell(dwell);
    else
      signals::constant_speed(p, p.end_velocity(), dwell);
  }
  return p;
}

int run_quadrature(const QuadratureOptions& o) {
  using namespace signals;
  const MotionProfile profile = build_profile(o);
  QuadratureEncoder enc;
  // The rig's placement (rig/campaign/rig_drive.cpp, docs/campaigns.md "[encoder]"): count =
  // floor(position), so the VCD shows the edges `hilrig run` drives for the same motion.
  enc.placement = EdgePlacement::WholeCount;
  enc.lines_per_turn = o.lines;
  enc.reversed = o.reversed;
  enc.index_count = o.index_count;
  enc.index_width = o.index_width;
  if (o.index_line >= 0) enc.gate_index_to_line(o.index_line);

  if (o.max_input_hz > 0) {
    const auto action = o.rate_action == "fail" ? RateLimitAction::Fail : RateLimitAction::Warn;
    try {
      for (const auto& v : check_edge_rate(profile, enc, o.max_input_hz, action))
        fmt::print(stderr, "hilrig synth: warning: {}\n", describe(v));
    } catch (const EdgeRateError& e) {
      fmt::print(stderr, "hilrig synth: {}\n", e.what());
      return kCheckFailed;
    }
  }

  QuadratureTrace signal = solve_quadrature(profile, enc);
  const std::int64_t final_count = signal.edges.empty() ? signal.initial_count : [&] {
    for (auto it = signal.edges.rbegin(); it != signal.edges.rend(); ++it)
      if (it->channel != QuadChannel::Z) return it->count;
    return signal.initial_count;
  }();
  apply_faults(signal, o);

  TraceRecorder trace;
  const std::uint32_t a = trace.declare(o.name + ".A");
  const std::uint32_t b = trace.declare(o.name + ".B");
  const bool has_z = enc.index_width > 0;
  const std::uint32_t z = has_z ? trace.declare(o.name + ".Z") : 0;
  const std::uint32_t count = o.with_count ? trace.declare(o.name + ".count", SignalKind::Integer, 32) : 0;
  const std::int64_t initial = signal.initial_count;
  trace.set_initial(a, signal.initial_level(QuadChannel::A) ? 1 : 0);
  trace.set_initial(b, signal.initial_level(QuadChannel::B) ? 1 : 0);
  if (has_z) trace.set_initial(z, signal.initial_z ? 1 : 0);
  if (o.with_count) trace.set_initial(count, initial);
  const std::size_t edges = signal.edges.size();
  for (const QuadEdge& e : signal.edges) {
    const Edge edge{e.time, e.level};
    switch (e.channel) {
    case QuadChannel::A:
      trace.edge(a, edge);
      break;
    case QuadChannel::B:
      trace.edge(b, edge);
      break;
    case QuadChannel::Z:
      if (has_z) trace.edge(z, edge);
      continue;
    }
    // The true count (faults do not change what the shaft did).
    if (o.with_count) trace.value(count, e.time, e.count);
  }
  write_vcd_file(trace, o.out);
  if (o.out != "-")
    fmt::print("{}: {} edges over {:.6f} s, count {} -> {} ({} counts/turn)\n", o.out, edges,
               (profile.end_time() - profile.start_time()).seconds(), initial, final_count,
               enc.counts_per_turn());
  return kPassed;
}

void add_quadrature(CLI::App& synth) {
  auto o = std::make_shared<QuadratureOptions>();
  CLI::App* cmd =
      synth.add_subcommand("quadrature", "A/B/Z quadrature for a motion profile (positions in turns)");
  cmd->add_option("--out", o->out, "VCD file to write ('-' for stdout)")->required();
  cmd->add_option("--profile", o->profile, "constant | trapezoid | scurve | press")
      ->check(CLI::IsMember({"constant", "trapezoid", "scurve", "press"}));
  cmd->add_option("--lines", o->lines, "lines per turn (X4: 4 counts per line)")->check(positive_number());
  cmd->add_option("--rpm", o->rpm, "speed (constant, press) or max speed (trapezoid, scurve), RPM");
  cmd->add_option("--duration", o->duration, "run time (constant, press), e.g. 10ms");
  cmd->add_option("--turns", o->turns, "move distance in turns, signed (trapezoid, scurve)");
  cmd->add_option("--accel", o->accel, "acceleration, turns/s² (trapezoid, scurve)");
  cmd->add_option("--decel", o->decel, "deceleration, turns/s² (trapezoid; default = accel)");
  cmd->add_option("--jerk", o->jerk, "jerk, turns/s³ (scurve)");
  cmd->add_option("--steps", o->steps, "constant-acceleration steps per jerk ramp (scurve)")
      ->check(positive_number());
  cmd->add_option("--brake", o->brake, "brake deceleration, turns/s² (press)");
  cmd->add_option("--dwell", o->dwell, "time to hold (or keep turning) after the move");
  cmd->add_option("--start", o->start_turns, "start position, turns");
  cmd->add_flag("--reverse-direction", o->reversed, "B leads A for forward motion");
  cmd->add_option("--index-count", o->index_count, "Z position in counts within a turn");
  cmd->add_option("--index-width", o->index_width, "Z width in counts (0: no Z)");
  cmd->add_option("--index-line", o->index_line, "Z gated to A·B high on this line (overrides count/width)");
  cmd->add_flag("--count", o->with_count, "also record the encoder count as an integer signal");
  cmd->add_option("--name", o->name, "signal name prefix");
  cmd->add_option("--max-input-hz", o->max_input_hz,
                  "check each channel against this frequency (e.g. 250e3)");
  cmd->add_option("--rate-action", o->rate_action, "warn | fail when --max-input-hz is exceeded")
      ->check(CLI::IsMember({"warn", "fail"}));
  cmd->add_option("--glitch", o->glitches, "fault: invert a channel for a while: channel,at,width");
  cmd->add_option("--missing-edge", o->missing_edges,
                  "fault: lose the A/B edge with this index (and its pulse)");
  cmd->add_option("--simultaneous", o->simultaneous,
                  "fault: the other channel's next edge moves onto edge INDEX");
  cmd->add_option("--noise", o->noise, "fault: noise burst start,length,pulses,seed[,min_width,max_width]");
  cmd->add_option("--phase-error", o->phase_error, "fault: shift B by this fraction of a quarter period");
  on_run(*cmd, [o] { return run_quadrature(*o); });
}

// ---- discrete ---------------------------------------------------------------------

struct DiscreteOptions {
  std::string out;
  std::string name = "rig.in";
  std::string initial = "0";
  std::vector<std::string> sets;    // time=level
  std::vector<std::string> trains;  // start,period,width,count
  std::vector<std::string> bounces; // time,level,window,bounces,seed[,min_width]
};

int run_discrete(const DiscreteOptions& o) {
  std::vector<Edge> wanted;
  for (const std::string& s : o.sets) {
    const auto parts = split(s, '=');
    if (parts.size() != 2) throw CLI::ValidationError("--set", "expected time=level, got '" + s + "'");
    wanted.push_back(Edge{parse_duration(parts[0]), parse_level(parts[1])});
  }
  for (const std::string& s : o.trains) {
    const auto parts = split(s, ',');
    if (parts.size() != 4) throw CLI::ValidationError("--train", "expected start,period,width,count");
    signals::DiscreteSignal train(parse_level(o.initial));
    train.pulse_train(parse_duration(parts[0]), parse_duration(parts[1]), parse_duration(parts[2]),
                      static_cast<std::size_t>(parse_number(parts[3], "--train")), !parse_level(o.initial));
    wanted.insert(wanted.end(), train.edges().begin(), train.edges().end());
  }
  for (const std::string& s : o.bounces) {
    const auto parts = split(s, ',');
    if (parts.size() != 5 && parts.size() != 6)
      throw CLI::ValidationError("--bounce", "expected time,level,window,bounces,seed[,min_width]");
    signals::ContactBounce bounce;
    bounce.window = parse_duration(parts[2]);
    bounce.bounces = static_cast<std::size_t>(parse_number(parts[3], "--bounce"));
    bounce.seed = static_cast<std::uint64_t>(parse_number(parts[4], "--bounce"));
    if (parts.size() == 6) bounce.min_width = parse_duration(parts[5]);
    const auto edges = signals::bounce_edges(parse_duration(parts[0]), parse_level(parts[1]), bounce);
    wanted.insert(wanted.end(), edges.begin(), edges.end());
  }
  std::stable_sort(wanted.begin(), wanted.end(),
                   [](const Edge& x, const Edge& y) { return x.time < y.time; });
  signals::DiscreteSignal signal(parse_level(o.initial));
  for (const Edge& e : wanted) signal.set(e.time, e.level);

  TraceRecorder trace;
  const std::uint32_t line = trace.declare(o.name);
  trace.set_initial(line, is_high(signal.initial()) ? 1 : 0);
  for (const Edge& e : signal.edges()) trace.edge(line, e);
  write_vcd_file(trace, o.out);
  if (o.out != "-") fmt::print("{}: {} edges on {}\n", o.out, signal.edges().size(), o.name);
  return kPassed;
}

void add_discrete(CLI::App& synth) {
  auto o = std::make_shared<DiscreteOptions>();
  CLI::App* cmd =
      synth.add_subcommand("discrete", "A discrete input: level changes, pulse trains, contact bounce");
  cmd->add_option("--out", o->out, "VCD file to write ('-' for stdout)")->required();
  cmd->add_option("--name", o->name, "signal name");
  cmd->add_option("--initial", o->initial, "initial level (0/1)");
  cmd->add_option("--set", o->sets, "a level change: time=level, e.g. 1ms=1 (repeatable)");
  cmd->add_option("--train", o->trains, "pulses away from the initial level: start,period,width,count");
  cmd->add_option("--bounce", o->bounces,
                  "contact bounce settling at level: time,level,window,bounces,seed[,min_width]");
  on_run(*cmd, [o] { return run_discrete(*o); });
}

} // namespace

Nanos parse_duration(const std::string& text) {
  static const std::pair<const char*, double> units[] = {
      {"ns", 1e-9}, {"us", 1e-6}, {"ms", 1e-3}, {"s", 1.0}};
  for (const auto& [suffix, scale] : units) {
    const std::string unit(suffix);
    if (text.size() > unit.size() && text.compare(text.size() - unit.size(), unit.size(), unit) == 0) {
      const std::string number = text.substr(0, text.size() - unit.size());
      // "ms" also ends in "s": only accept a suffix whose number part parses fully.
      try {
        std::size_t used = 0;
        const double v = std::stod(number, &used);
        if (used == number.size()) return Nanos::from_seconds(v * scale);
      } catch (const std::exception&) {}
    }
  }
  return Nanos::from_seconds(parse_number(text, "duration"));
}

void write_vcd_file(const TraceRecorder& trace, const std::string& path) {
  if (path == "-") {
    write_vcd(trace, std::cout);
    return;
  }
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("cannot open " + path + " for writing");
  write_vcd(trace, out);
  if (!out) throw std::runtime_error("cannot write " + path);
}

bool register_synth_kind(SynthKindAdder add) {
  synth_kinds().push_back(add);
  return true;
}

void on_run(CLI::App& kind, std::function<int()> run) {
  kind.callback([name = kind.get_name(), run = std::move(run)] {
    int status = kPassed;
    try {
      status = run();
    } catch (const std::invalid_argument& e) {
      throw CLI::ValidationError(name, e.what());
    }
    if (status != kPassed) exit_with(status);
  });
}

void add_synth_command(CLI::App& app) {
  CLI::App* synth = app.add_subcommand("synth", "Write synthesized sensor signals to a VCD file");
  synth->require_subcommand(1);
  add_quadrature(*synth);
  add_discrete(*synth);
  for (const SynthKindAdder add : synth_kinds()) add(*synth);
}

} // namespace hilrig::cli
