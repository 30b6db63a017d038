#include "rig/cli/synth_command.hpp"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "rig/campaign/limits.hpp"
#include "rig/cli/exit_status.hpp"
#include "rig/cli/number_checks.hpp"
#include "rig/results/atomic_file.hpp"
#include "signals/discrete_bounce.hpp"
#include "signals/discrete_input.hpp"
#include "signals/edge_rate.hpp"
#include "signals/move_builders.hpp"
#include "signals/quadrature_edges.hpp"
#include "signals/quadrature_faults.hpp"

namespace hilrig::cli {

namespace limits = campaign::limits;

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

// "10ms" -> 0.01; any number, infinities and NaN too (parse_duration bounds them).
double seconds_in(const std::string& text, const std::string& option) {
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
        if (used == number.size()) return v * scale;
      } catch (const std::exception&) {}
    }
  }
  return parse_number(text, option);
}

// A level of `option`; `item` is the whole value it came from ("1ms=2"), empty if the text is
// the whole value: "--set: 1ms=2: the level '2' is not 0, 1, high or low".
Level parse_level(const std::string& text, const std::string& option, const std::string& item = {}) {
  if (text == "1" || text == "high" || text == "H") return Level::High;
  if (text == "0" || text == "low" || text == "L") return Level::Low;
  throw CLI::ValidationError(option, fmt::format("{}the level '{}' is not 0, 1, high or low",
                                                 item.empty() ? "" : item + ": ", text));
}

// ---- quadrature -------------------------------------------------------------------

// --index-line not given (any value given is checked against 0 .. lines - 1).
constexpr std::int64_t kNoIndexLine = std::numeric_limits<std::int64_t>::min();

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
  std::int64_t index_line = kNoIndexLine;
  bool with_count = false;
  double max_input_hz = 0.0;
  std::string rate_action = "warn";
  // Faults, applied in this order.
  std::vector<std::string> glitches; // channel,at,width
  // Signed: CLI11 reads "-1" into an unsigned as 2^64 - 1, and the refusal would quote that.
  std::vector<std::int64_t> missing_edges; // index into the edge list, as before any is lost
  std::vector<std::int64_t> simultaneous;  // index into the edge list
  std::vector<std::string> noise;          // start,length,pulses,seed[,min_width,max_width]
  double phase_error = 0.0;                // fraction of a quarter period
};

signals::QuadChannel parse_channel(const std::string& text) {
  if (text == "A" || text == "a") return signals::QuadChannel::A;
  if (text == "B" || text == "b") return signals::QuadChannel::B;
  if (text == "Z" || text == "z") return signals::QuadChannel::Z;
  throw CLI::ValidationError("--glitch", "'" + text + "' is not A, B or Z");
}

struct Glitch {
  signals::QuadChannel channel;
  Nanos at;
  Nanos width;
};

Glitch parse_glitch(const std::string& text) {
  const auto parts = split(text, ',');
  if (parts.size() != 3)
    throw CLI::ValidationError("--glitch", "expected channel,at,width, got '" + text + "'");
  return Glitch{parse_channel(parts[0]), parse_instant(parts[1], "--glitch"),
                parse_positive_duration(parts[2], "--glitch")};
}

// A seed drawn from a double: whole and exact (2^53), so the same text is the same burst.
constexpr std::int64_t kMaxSeed = std::int64_t{1} << 53;

signals::NoiseBurst parse_noise(const std::string& text) {
  const auto parts = split(text, ',');
  if (parts.size() != 4 && parts.size() != 6)
    throw CLI::ValidationError("--noise",
                               "expected start,length,pulses,seed[,min_width,max_width], got '" + text + "'");
  signals::NoiseBurst burst;
  burst.start = parse_instant(parts[0], "--noise");
  burst.length = parse_positive_duration(parts[1], "--noise");
  // Each pulse is two edges; a burst is bounded like a contact bounce stimulus.
  burst.pulses =
      static_cast<std::size_t>(parse_whole(parts[2], "--noise", "pulses", 0, limits::kMaxBounceEdges));
  burst.seed = static_cast<std::uint64_t>(parse_whole(parts[3], "--noise", "a seed", 0, kMaxSeed));
  if (parts.size() == 6) {
    burst.min_width = parse_positive_duration(parts[4], "--noise");
    burst.max_width = parse_positive_duration(parts[5], "--noise");
    if (burst.max_width < burst.min_width)
      throw CLI::ValidationError("--noise",
                                 fmt::format("min_width <= max_width (got {} > {})", parts[4], parts[5]));
  }
  return burst;
}

// An index names an A or B edge of the trace: the limit is the signal's own edge count.
void require_ab_edge(const signals::QuadratureTrace& trace, std::int64_t index, const std::string& option) {
  const auto edges = static_cast<std::int64_t>(trace.edges.size());
  if (index < 0 || index >= edges)
    throw CLI::ValidationError(option, edges == 0 ? fmt::format("this motion makes no edges (got {})", index)
                                                  : fmt::format("an edge index 0 .. {}: this motion makes {} "
                                                                "edges (got {})",
                                                                edges - 1, edges, index));
  if (trace.edges[static_cast<std::size_t>(index)].channel == signals::QuadChannel::Z)
    throw CLI::ValidationError(option, fmt::format("edge {} is a Z edge: name an A or B edge", index));
}

// Every --missing-edge names an edge as the trace stood before any was lost: losing one
// renumbers the edges after it, so they are lost from the highest index down, and each lower
// one still names its own edge. A lost edge takes its channel's next remaining edge with it.
void lose_edges(signals::QuadratureTrace& trace, std::vector<std::int64_t> indices) {
  std::sort(indices.begin(), indices.end(), std::greater<>());
  if (const auto twice = std::adjacent_find(indices.begin(), indices.end()); twice != indices.end())
    throw CLI::ValidationError("--missing-edge", fmt::format("edge {} is named twice", *twice));
  for (const std::int64_t i : indices) require_ab_edge(trace, i, "--missing-edge");
  for (const std::int64_t i : indices) signals::inject_missing_edge(trace, static_cast<std::size_t>(i));
}

void move_edges_together(signals::QuadratureTrace& trace, const std::vector<std::int64_t>& indices) {
  using signals::QuadChannel;
  for (const std::int64_t index : indices) {
    require_ab_edge(trace, index, "--simultaneous");
    const auto i = static_cast<std::size_t>(index);
    const QuadChannel other = trace.edges[i].channel == QuadChannel::A ? QuadChannel::B : QuadChannel::A;
    const auto later =
        std::find_if(trace.edges.begin() + static_cast<std::ptrdiff_t>(i) + 1, trace.edges.end(),
                     [other](const signals::QuadEdge& e) { return e.channel == other; });
    if (later == trace.edges.end())
      throw CLI::ValidationError(
          "--simultaneous", fmt::format("edge {} has no later {} edge to move onto it: this motion makes {} "
                                        "edges",
                                        i, other == QuadChannel::A ? "A" : "B", trace.edges.size()));
    signals::inject_simultaneous_edges(trace, i);
  }
}

void apply_faults(signals::QuadratureTrace& trace, const QuadratureOptions& o) {
  using namespace signals;
  for (const std::string& g : o.glitches) {
    const Glitch glitch = parse_glitch(g);
    inject_glitch(trace, glitch.channel, glitch.at, glitch.width);
  }
  lose_edges(trace, o.missing_edges);
  move_edges_together(trace, o.simultaneous);
  for (const std::string& n : o.noise) inject_noise_burst(trace, parse_noise(n));
  if (o.phase_error != 0.0) inject_phase_error(trace, o.phase_error);
}

// ---- the quadrature options' ranges (docs/campaigns.md "Ranges and limits") ------------

// Accelerations in turns/s², as a campaign's rpm/s bound.
constexpr double kMaxTurnsPerS2 = limits::kMaxRpmPerS / 60.0;
// That bound in words: 1e6 / 60 = 16666.666... turns/s², its digits cut, not rounded (a
// rounded 16666.7 would be a maximum that is refused).
std::string max_rate_words() {
  return fmt::format("{:.3f}... turns/s² ({} rpm/s)", std::floor(kMaxTurnsPerS2 * 1000.0) / 1000.0,
                     limits::kMaxRpmPerS);
}
// A jerk ramp is this many profile segments at most (each is solved for its edges).
constexpr int kMaxSteps = 1'000;
// B moved past the next A edge but one is no longer a phase error of one encoder.
constexpr double kMaxPhaseError = 2.0;

bool moves_to_a_distance(const QuadratureOptions& o) {
  return o.profile == "trapezoid" || o.profile == "scurve";
}

void check_speed(const QuadratureOptions& o) {
  require_within("--rpm", o.rpm, -limits::kMaxRpm, limits::kMaxRpm,
                 fmt::format("-{0} .. {0} rpm", limits::kMaxRpm));
  if (o.profile != "constant")
    require_within(
        "--rpm", std::abs(o.rpm), limits::kMinCruiseRpm, limits::kMaxRpm,
        fmt::format("a {} profile needs |rpm| {} .. {}", o.profile, limits::kMinCruiseRpm, limits::kMaxRpm));
  // The fastest encoder input of the boards (the 4501's 250 kHz a channel, X4).
  const double counts_per_turn = 4.0 * static_cast<double>(o.lines);
  const double max_rpm = limits::kMaxCountsPerS / counts_per_turn * 60.0;
  if (std::abs(o.rpm) > max_rpm)
    throw CLI::ValidationError("--rpm",
                               fmt::format("at most {} encoder counts/s (X4): {:.6g} rpm with --lines {} "
                                           "(got {})",
                                           limits::kMaxCountsPerS, max_rpm, o.lines, o.rpm));
}

// A rate (acceleration, brake) the profile needs (> 0) or may leave at 0.
void check_rate(const std::string& option, double value, bool needed, const std::string& profile) {
  const std::string range = max_rate_words();
  if (needed && !(value > 0.0))
    throw CLI::ValidationError(
        option, fmt::format("a {} needs 0 < {} <= {} (got {})", profile, option.substr(2), range, value));
  require_within(option, value, 0.0, kMaxTurnsPerS2, "0 .. " + range);
}

void check_profile(const QuadratureOptions& o) {
  const auto turns = fmt::format("-{0} .. {0} turns", limits::kMaxTurns);
  require_within("--start", o.start_turns, -limits::kMaxTurns, limits::kMaxTurns, turns);
  require_within("--turns", o.turns, -limits::kMaxTurns, limits::kMaxTurns, turns);
  check_rate("--accel", o.accel, moves_to_a_distance(o), o.profile);
  check_rate("--decel", o.decel, false, o.profile);
  check_rate("--brake", o.brake, o.profile == "press", o.profile);
  if (o.profile == "scurve" && !(o.jerk > 0.0 && std::isfinite(o.jerk)))
    throw CLI::ValidationError("--jerk",
                               fmt::format("an scurve needs a finite jerk > 0 turns/s³ (got {})", o.jerk));
  require_within("--jerk", o.jerk, 0.0, std::numeric_limits<double>::max(), "a finite number >= 0 turns/s³");
  (void)parse_instant(o.dwell, "--dwell");
  require_within("--phase-error", o.phase_error, -kMaxPhaseError, kMaxPhaseError,
                 fmt::format("-{0} .. {0} quarter periods", kMaxPhaseError));
}

// ---- the move's time: a synthesized motion ends within a campaign's run (limits::kMaxEnd) ---

// x rounded up to 4 significant digits: a least value quoted is one that works.
double round_up(double x) {
  const double unit = std::pow(10.0, std::floor(std::log10(x)) - 3.0);
  return std::ceil(x / unit) * unit;
}

// The least rate in (0, hi] that makes `time_at` (falling as the rate rises) at most `limit`.
std::optional<double> least_rate(const std::function<double(double)>& time_at, double hi, double limit) {
  if (!(time_at(hi) <= limit)) return std::nullopt;
  double lo = std::numeric_limits<double>::min();
  for (int i = 0; i < 200; ++i) {
    const double mid = std::sqrt(lo) * std::sqrt(hi); // halves the range of exponents
    (time_at(mid) <= limit ? hi : lo) = mid;
  }
  return round_up(hi);
}

// The move and its dwell end within a campaign's run, as a campaign's motion must; refused
// naming the rate at fault and its least value, else what else to change.
void check_move_time(const QuadratureOptions& o) {
  const double limit = limits::kMaxEnd.seconds() - parse_instant(o.dwell, "--dwell").seconds();
  const double d = std::abs(o.turns);
  const double v = std::abs(o.rpm) / 60.0;
  const std::string within = "ends within " + duration_words(limits::kMaxEnd) + " with its --dwell";
  const auto refuse = [&](const std::string& option, double taken,
                          const std::function<double(double)>& time_at, double hi, const std::string& unit) {
    if (const auto least = least_rate(time_at, hi, limit))
      throw CLI::ValidationError(option, fmt::format("at least {:.6g} {} for a move that {} (this one takes "
                                                     "{:.6g} s)",
                                                     *least, unit, within, taken));
    throw CLI::ValidationError(option, fmt::format("a move that {} (this one takes {:.6g} s): raise --rpm, "
                                                   "--accel, --decel or --jerk, or shorten --turns",
                                                   within, taken));
  };
  if (o.profile == "trapezoid" && d > 0.0) {
    const double b = o.decel > 0 ? o.decel : o.accel;
    const auto seconds = [&](double accel, double decel) {
      return signals::trapezoid_seconds(d, signals::MoveLimits{v, accel, decel});
    };
    const double taken = seconds(o.accel, b);
    if (taken <= limit) return;
    if (o.decel > 0 && o.decel < o.accel)
      refuse(
          "--decel", taken, [&](double x) { return seconds(o.accel, x); }, kMaxTurnsPerS2, "turns/s²");
    refuse(
        "--accel", taken, [&](double x) { return seconds(x, o.decel > 0 ? o.decel : x); }, kMaxTurnsPerS2,
        "turns/s²");
  } else if (o.profile == "scurve" && d > 0.0) {
    const auto seconds = [&](double accel, double jerk) {
      return signals::s_curve_seconds(d, signals::SCurveLimits{v, accel, jerk});
    };
    const double taken = seconds(o.accel, o.jerk);
    if (taken <= limit) return;
    if (o.accel / o.jerk >= v / o.accel)
      refuse(
          "--jerk", taken, [&](double x) { return seconds(o.accel, x); }, std::numeric_limits<double>::max(),
          "turns/s³");
    refuse(
        "--accel", taken, [&](double x) { return seconds(x, o.jerk); }, kMaxTurnsPerS2, "turns/s²");
  } else if (o.profile == "press") {
    const double run = parse_positive_duration(o.duration, "--duration").seconds();
    const double taken = run + v / o.brake;
    if (taken <= limit) return;
    refuse(
        "--brake", taken, [&](double x) { return run + v / x; }, kMaxTurnsPerS2, "turns/s²");
  } else if (o.profile == "constant") {
    const double taken = parse_positive_duration(o.duration, "--duration").seconds();
    if (taken <= limit) return;
    throw CLI::ValidationError("--dwell",
                               fmt::format("--duration and --dwell together at most {} (got {} and {})",
                                           duration_words(limits::kMaxEnd), o.duration, o.dwell));
  }
}

void check_index(const QuadratureOptions& o) {
  const std::int64_t lines = o.lines;
  const std::int64_t cpt = 4 * lines;
  if (o.index_line != kNoIndexLine && (o.index_line < 0 || o.index_line >= lines))
    throw CLI::ValidationError(
        "--index-line", fmt::format("a line 0 .. {} of --lines {} (got {})", lines - 1, lines, o.index_line));
  if (o.index_count < 0 || o.index_count >= cpt)
    throw CLI::ValidationError("--index-count",
                               fmt::format("a count within the turn, 0 .. {} ({} counts/turn) "
                                           "(got {})",
                                           cpt - 1, cpt, o.index_count));
  if (o.index_width < 0 || o.index_width > cpt)
    throw CLI::ValidationError("--index-width",
                               fmt::format("0 .. {} counts, at most a turn (got {})", cpt, o.index_width));
}

// An option the chosen profile or Z does not use is refused, not ignored: a person who gave it
// expected it to change the signal.
void check_applies(const CLI::App& cmd, const QuadratureOptions& o) {
  const std::string& p = o.profile;
  const std::string is = " (this is --profile " + p + ")";
  refuse_unless_applies(cmd, "--duration", p == "constant" || p == "press",
                        "only with --profile constant or press (a trapezoid or scurve runs until it has "
                        "moved --turns)" +
                            is);
  const std::string moves = "only with --profile trapezoid or scurve" + is;
  refuse_unless_applies(cmd, "--turns", moves_to_a_distance(o), moves);
  refuse_unless_applies(cmd, "--accel", moves_to_a_distance(o), moves);
  refuse_unless_applies(cmd, "--decel", p == "trapezoid",
                        "only with --profile trapezoid (an scurve slows at --accel)" + is);
  refuse_unless_applies(cmd, "--jerk", p == "scurve", "only with --profile scurve" + is);
  refuse_unless_applies(cmd, "--steps", p == "scurve", "only with --profile scurve" + is);
  refuse_unless_applies(cmd, "--brake", p == "press", "only with --profile press" + is);
  const bool gated = o.index_line != kNoIndexLine;
  refuse_unless_applies(cmd, "--index-count", !gated,
                        "not with --index-line, which places Z itself (on A·B high of that line)");
  refuse_unless_applies(cmd, "--index-width", !gated,
                        "not with --index-line, which makes Z one count wide itself");
  refuse_unless_applies(cmd, "--index-count", o.index_width > 0,
                        "only with --index-width > 0: Z is that many counts wide from --index-count "
                        "(without it there is no Z)");
  refuse_unless_applies(cmd, "--rate-action", o.max_input_hz > 0,
                        "only with --max-input-hz > 0: it says what exceeding that frequency does");
}

void check_quadrature(const CLI::App& cmd, const QuadratureOptions& o) {
  check_applies(cmd, o);
  check_speed(o);
  check_profile(o);
  check_move_time(o);
  check_index(o);
  for (const std::string& g : o.glitches) static_cast<void>(parse_glitch(g));
  for (const std::string& n : o.noise) static_cast<void>(parse_noise(n));
}

// n in (lo, hi] with n = r (mod m).
std::int64_t congruent_in(std::int64_t lo, std::int64_t hi, std::int64_t r, std::int64_t m) {
  const auto floor_div = [m](std::int64_t x) { return x >= 0 ? x / m : -((-x + m - 1) / m); };
  return floor_div(hi - r) - floor_div(lo - r);
}

// The edges a motion makes, before solving it. Every profile here turns one way and stops (a
// constant speed, a rest-to-rest move, a stroke and its brake), so A and B change once for each
// count between the first and the last; Z rises where the count enters its window and falls
// where it leaves (QuadratureEncoder::index_high), once a turn each unless it is a whole turn.
std::int64_t edges_made(const signals::MotionProfile& profile, double start,
                        const signals::QuadratureEncoder& enc) {
  const std::int64_t from = enc.count_at(start);
  const std::int64_t to = enc.count_at(profile.end_position());
  const std::int64_t lo = std::min(from, to);
  const std::int64_t hi = std::max(from, to);
  const std::int64_t cpt = enc.counts_per_turn();
  if (enc.index_width <= 0 || enc.index_width >= cpt) return hi - lo;
  return hi - lo + congruent_in(lo, hi, enc.index_count, cpt) +
         congruent_in(lo, hi, enc.index_count + enc.index_width, cpt);
}

void require_edges_within_cap(std::int64_t edges, const std::string& kind, const std::string& shorten) {
  if (edges > kMaxSynthEdges)
    throw CLI::ValidationError(kind, fmt::format("this motion makes {} edges; synth writes at most {}: {}",
                                                 edges, kMaxSynthEdges, shorten));
}

signals::MotionProfile build_profile(const QuadratureOptions& o) {
  using namespace signals;
  MotionProfile p(o.start_turns);
  const double speed = o.rpm / 60.0; // turns/s
  const double decel = o.decel > 0 ? o.decel : o.accel;
  const auto duration = [&o] { return parse_positive_duration(o.duration, "--duration"); };
  if (o.profile == "constant") {
    constant_speed(p, speed, duration());
  } else if (o.profile == "trapezoid") {
    trapezoid_move(p, o.turns, MoveLimits{std::abs(speed), o.accel, decel});
  } else if (o.profile == "scurve") {
    s_curve_move(p, o.turns, SCurveLimits{std::abs(speed), o.accel, o.jerk, o.steps});
  } else if (o.profile == "press") {
    press_stroke(p, speed, duration(), o.brake);
  } else {
    throw CLI::ValidationError("--profile", "unknown profile '" + o.profile + "'");
  }
  const Nanos dwell = parse_instant(o.dwell, "--dwell");
  if (dwell > Nanos::zero()) {
    if (p.at_rest())
      p.dwell(dwell);
    else
      signals::constant_speed(p, p.end_velocity(), dwell);
  }
  return p;
}

int run_quadrature(const CLI::App& cmd, const QuadratureOptions& o) {
  using namespace signals;
  check_quadrature(cmd, o);
  require_writable("--out", o.out);
  const MotionProfile profile = build_profile(o);
  QuadratureEncoder enc;
  // The rig's placement (rig/campaign/rig_drive.cpp, docs/campaigns.md "[encoder]"): count =
  // floor(position), so the VCD shows the edges `hilrig run` drives for the same motion.
  enc.placement = EdgePlacement::WholeCount;
  enc.lines_per_turn = o.lines;
  enc.reversed = o.reversed;
  enc.index_count = o.index_count;
  enc.index_width = o.index_width;
  if (o.index_line != kNoIndexLine) enc.gate_index_to_line(o.index_line);
  require_edges_within_cap(edges_made(profile, o.start_turns, enc), "quadrature",
                           "shorten --duration or --turns, or lower --rpm or --lines");

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
  // 64 bits, as a run's shaft.count: 10,000 turns of a fine encoder pass 2^31 counts.
  const std::uint32_t count = o.with_count ? trace.declare(o.name + ".count", SignalKind::Integer, 64) : 0;
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
  CLI::App* cmd = synth.add_subcommand(
      "quadrature",
      fmt::format("A/B/Z quadrature for a motion profile (positions in turns); at most {} edges "
                  "(A, B and Z: the counts the motion crosses plus Z's), more is refused",
                  kMaxSynthEdges));
  cmd->add_option("--out", o->out, "VCD file to write ('-' for stdout)")->required();
  cmd->add_option("--profile", o->profile, "constant | trapezoid | scurve | press")
      ->check(CLI::IsMember({"constant", "trapezoid", "scurve", "press"}));
  cmd->add_option("--lines", o->lines, "lines per turn (X4: 4 counts per line)")->check(positive_number());
  const std::string rate = "0 .. " + max_rate_words();
  cmd->add_option("--rpm", o->rpm,
                  fmt::format("speed (constant, press) or max speed (trapezoid, scurve), RPM: -{0} .. {0}, "
                              "and at most {1} counts/s (X4); trapezoid, scurve, press: |rpm| >= {2}",
                              limits::kMaxRpm, limits::kMaxCountsPerS, limits::kMinCruiseRpm));
  cmd->add_option("--duration", o->duration, "run time (constant, press only), e.g. 10ms: 1ns .. 3600s");
  cmd->add_option(
      "--turns", o->turns,
      fmt::format("move distance in turns, signed (trapezoid, scurve only): -{0} .. {0}", limits::kMaxTurns));
  cmd->add_option("--accel", o->accel, "acceleration, turns/s² (trapezoid, scurve only: > 0): " + rate);
  cmd->add_option("--decel", o->decel, "deceleration, turns/s² (trapezoid only; 0 = accel): " + rate);
  cmd->add_option("--jerk", o->jerk, "jerk, turns/s³ (scurve only: > 0)");
  cmd->add_option("--steps", o->steps, "constant-acceleration steps per jerk ramp (scurve only)")
      ->check(CLI::Range(1, kMaxSteps));
  cmd->add_option("--brake", o->brake, "brake deceleration, turns/s² (press only: > 0): " + rate);
  cmd->add_option("--dwell", o->dwell, "time to hold (or keep turning) after the move: 0 .. 3600s");
  cmd->add_option("--start", o->start_turns,
                  fmt::format("start position, turns: -{0} .. {0}", limits::kMaxTurns));
  cmd->add_flag("--reverse-direction", o->reversed, "B leads A for forward motion");
  cmd->add_option("--index-count", o->index_count,
                  "Z position in counts within a turn: 0 .. 4 x lines - 1 (with --index-width > 0)");
  cmd->add_option("--index-width", o->index_width, "Z width in counts (0: no Z): 0 .. 4 x lines");
  cmd->add_option("--index-line", o->index_line,
                  "Z gated to A·B high on this line, 0 .. lines - 1 (not with --index-count/--index-width)");
  cmd->add_flag("--count", o->with_count, "also record the encoder count as an integer signal");
  cmd->add_option("--name", o->name, "signal name prefix");
  cmd->add_option("--max-input-hz", o->max_input_hz,
                  "check each channel against this frequency (e.g. 250e3; 0: no check)")
      ->check(non_negative_number());
  cmd->add_option("--rate-action", o->rate_action,
                  "warn | fail when --max-input-hz is exceeded (with --max-input-hz > 0)")
      ->check(CLI::IsMember({"warn", "fail"}));
  cmd->add_option("--glitch", o->glitches,
                  "fault: invert a channel for a while: channel,at,width (A|B|Z, 0 .. 3600s, 1ns .. 3600s)");
  cmd->add_option("--missing-edge", o->missing_edges,
                  "fault: lose the A/B edge with this index (and its pulse: the channel's next edge); "
                  "indices count the edges (A, B, Z in time order, after --glitch) before any is lost, so "
                  "several all name edges of that one list");
  cmd->add_option(
      "--simultaneous", o->simultaneous,
      "fault: the other channel's next edge moves onto the A/B edge INDEX (after --missing-edge)");
  cmd->add_option(
      "--noise", o->noise,
      fmt::format("fault: noise burst start,length,pulses,seed[,min_width,max_width] (pulses 0 .. {})",
                  limits::kMaxBounceEdges));
  cmd->add_option(
      "--phase-error", o->phase_error,
      fmt::format("fault: shift B by this fraction of a quarter period, -{0} .. {0}", kMaxPhaseError));
  on_run(*cmd, [cmd, o] { return run_quadrature(*cmd, *o); });
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

// Level changes by time: the same instant at two levels says nothing about the line.
std::vector<Edge> parse_sets(const std::vector<std::string>& sets) {
  std::map<Nanos, std::pair<Level, std::string>> at;
  std::vector<Edge> edges;
  for (const std::string& s : sets) {
    const auto parts = split(s, '=');
    if (parts.size() != 2) throw CLI::ValidationError("--set", "expected time=level, got '" + s + "'");
    const Edge e{parse_instant(parts[0], "--set"), parse_level(parts[1], "--set", s)};
    const auto [it, added] = at.try_emplace(e.time, e.level, s);
    if (!added && it->second.first != e.level)
      throw CLI::ValidationError("--set",
                                 fmt::format("one level at each time (got {} and {})", it->second.second, s));
    edges.push_back(e);
  }
  return edges;
}

struct Train {
  Nanos start;
  Nanos period;
  Nanos width;
  std::int64_t count = 0;
};

// Two edges a pulse: a train is bounded by the edge cap, and ends within a campaign's run.
Train parse_train(const std::string& text) {
  const auto parts = split(text, ',');
  if (parts.size() != 4)
    throw CLI::ValidationError("--train", "expected start,period,width,count, got '" + text + "'");
  Train t{parse_instant(parts[0], "--train"), parse_positive_duration(parts[1], "--train"),
          parse_positive_duration(parts[2], "--train"),
          parse_whole(parts[3], "--train", "a count", 1, kMaxSynthEdges / 2)};
  if (t.width >= t.period)
    throw CLI::ValidationError("--train",
                               fmt::format("a width 0 < width < period {} (got {})", parts[1], parts[2]));
  // A train spans its first to its last edge, the last pulse's falling edge (docs/synth.md):
  // start + (count - 1) x period + width, in ns. Exact in a double up to 2^53 ns (104 days);
  // past that it is far beyond the limit anyway (and would overflow Nanos).
  const double last = static_cast<double>(t.start.count()) +
                      static_cast<double>(t.period.count()) * static_cast<double>(t.count - 1) +
                      static_cast<double>(t.width.count());
  if (last > static_cast<double>(limits::kMaxEnd.count()))
    throw CLI::ValidationError("--train",
                               fmt::format("a train within 0 .. {} (got {}: its last edge is at {:.9f} s)",
                                           duration_words(limits::kMaxEnd), text, last * 1e-9));
  return t;
}

struct Bounce {
  Nanos at;
  Level level = Level::Low;
  signals::ContactBounce bounce;
};

Bounce parse_bounce(const std::string& text) {
  const auto parts = split(text, ',');
  if (parts.size() != 5 && parts.size() != 6)
    throw CLI::ValidationError("--bounce",
                               "expected time,level,window,bounces,seed[,min_width], got '" + text + "'");
  Bounce b{parse_instant(parts[0], "--bounce"), parse_level(parts[1], "--bounce", text), {}};
  b.bounce.window = parse_instant(parts[2], "--bounce");
  b.bounce.bounces =
      static_cast<std::size_t>(parse_whole(parts[3], "--bounce", "bounces", 0, limits::kMaxBounceEdges));
  b.bounce.seed = static_cast<std::uint64_t>(parse_whole(parts[4], "--bounce", "a seed", 0, kMaxSeed));
  if (parts.size() == 6) b.bounce.min_width = parse_positive_duration(parts[5], "--bounce");
  // Every gap (2 a bounce: reopen, touch again) is at least min_width, all inside the window.
  const auto gaps = static_cast<std::int64_t>(2 * b.bounce.bounces);
  if (b.bounce.window < b.bounce.min_width * gaps)
    throw CLI::ValidationError("--bounce",
                               fmt::format("a window of at least 2 x bounces x min_width = 2 x {} x {} "
                                           "= {} (got {})",
                                           b.bounce.bounces, duration_words(b.bounce.min_width),
                                           duration_words(b.bounce.min_width * gaps), parts[2]));
  return b;
}

// One stimulus of the line: a --set (one edge), a --train or a --bounce (its edges, in time).
struct Stimulus {
  std::string option; // "--set"
  std::string text;   // as given: "1ms=1"
  std::vector<Edge> edges;
  [[nodiscard]] Nanos first() const { return edges.front().time; }
  [[nodiscard]] Nanos last() const { return edges.back().time; }
  [[nodiscard]] std::string named() const { return option + " " + text; }
};

// The stimuli as given play one at a time, each as written. Two whose spans (first edge ..
// last edge, both included) meet would play neither as asked: a --set inside a train stretches
// or cuts a pulse, a train inside a bounce toggles against it. So they are refused, naming both
// (two --set of one level at one time are one change). A train's pulses leave --initial and
// return to it, so the line must be at --initial when the train starts: a --set or --bounce
// before it that left the line at the other level is refused too.
void check_stimuli(std::vector<Stimulus>& stimuli, Level initial, const std::string& initial_text) {
  std::stable_sort(stimuli.begin(), stimuli.end(),
                   [](const Stimulus& x, const Stimulus& y) { return x.first() < y.first(); });
  const auto span = [](const Stimulus& x) {
    return x.first() == x.last() ? "at " + duration_words(x.first())
                                 : duration_words(x.first()) + " .. " + duration_words(x.last());
  };
  const Stimulus* reaching = nullptr; // the stimulus that ends last so far
  const Stimulus* leveller = nullptr; // the one that last set the line's level
  Level level = initial;
  for (const Stimulus& x : stimuli) {
    if (reaching != nullptr && x.first() <= reaching->last()) {
      const bool same_change = x.option == "--set" && reaching->option == "--set" &&
                               x.edges.front().level == reaching->edges.front().level;
      if (!same_change)
        throw CLI::ValidationError(x.option,
                                   fmt::format("{} ({}) overlaps {} ({}): one stimulus at a time on the line",
                                               x.named(), span(x), reaching->named(), span(*reaching)));
    }
    if (x.option == "--train" && level != initial)
      throw CLI::ValidationError(
          x.option, fmt::format("{} pulses away from --initial {} and back, but {} left the line at {} "
                                "before it starts",
                                x.named(), initial_text, leveller->named(), is_high(level) ? 1 : 0));
    if (reaching == nullptr || x.last() > reaching->last()) reaching = &x;
    level = x.edges.back().level;
    leveller = &x;
  }
}

int run_discrete(const DiscreteOptions& o) {
  const Level initial = parse_level(o.initial, "--initial");
  std::vector<Stimulus> stimuli;
  const std::vector<Edge> sets = parse_sets(o.sets);
  for (std::size_t i = 0; i < sets.size(); ++i) stimuli.push_back({"--set", o.sets[i], {sets[i]}});
  std::vector<Train> trains;
  std::vector<Bounce> bounces;
  auto edges = static_cast<std::int64_t>(sets.size());
  for (const std::string& s : o.trains) edges += 2 * trains.emplace_back(parse_train(s)).count;
  for (const std::string& s : o.bounces)
    edges += 2 * static_cast<std::int64_t>(bounces.emplace_back(parse_bounce(s)).bounce.bounces) + 1;
  require_edges_within_cap(edges, "discrete", "fewer or shorter --train and --bounce");
  require_writable("--out", o.out);
  for (std::size_t i = 0; i < trains.size(); ++i) {
    const Train& t = trains[i];
    signals::DiscreteSignal train(initial);
    train.pulse_train(t.start, t.period, t.width, static_cast<std::size_t>(t.count), !initial);
    stimuli.push_back({"--train", o.trains[i], train.edges()});
  }
  for (std::size_t i = 0; i < bounces.size(); ++i) {
    const Bounce& b = bounces[i];
    stimuli.push_back({"--bounce", o.bounces[i], signals::bounce_edges(b.at, b.level, b.bounce)});
  }
  check_stimuli(stimuli, initial, o.initial);
  signals::DiscreteSignal signal(initial);
  for (const Stimulus& x : stimuli)
    for (const Edge& e : x.edges) signal.set(e.time, e.level);

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
      synth.add_subcommand("discrete", "A discrete input: level changes, pulse trains, contact bounce; one "
                                       "stimulus at a time (overlapping ones are refused, naming both), and "
                                       "a train starts with the line at --initial");
  cmd->add_option("--out", o->out, "VCD file to write ('-' for stdout)")->required();
  cmd->add_option("--name", o->name, "signal name");
  cmd->add_option("--initial", o->initial, "initial level: 0, 1, low or high");
  cmd->add_option("--set", o->sets,
                  "a level change: time=level, e.g. 1ms=1 (repeatable; times 0 .. 3600s, one level a time)");
  cmd->add_option(
      "--train", o->trains,
      fmt::format("pulses away from the initial level: start,period,width,count (0 < width < period, "
                  "count 1 .. {}, ending by 3600s)",
                  kMaxSynthEdges / 2));
  cmd->add_option("--bounce", o->bounces,
                  fmt::format("contact bounce settling at level: time,level,window,bounces,seed[,min_width] "
                              "(bounces 0 .. {}, window >= 2 x bounces x min_width, min_width default 1ns)",
                              limits::kMaxBounceEdges));
  on_run(*cmd, [o] { return run_discrete(*o); });
}

} // namespace

std::string duration_words(Nanos d) {
  constexpr std::pair<std::int64_t, const char*> units[] = {
      {1'000'000'000, "s"}, {1'000'000, "ms"}, {1'000, "us"}};
  for (const auto& [ns, suffix] : units)
    if (d.count() != 0 && d.count() % ns == 0) return fmt::format("{}{}", d.count() / ns, suffix);
  return d.count() == 0 ? std::string("0s") : fmt::format("{}ns", d.count());
}

void require_within(const std::string& option, double value, double lo, double hi, const std::string& range) {
  if (!(value >= lo && value <= hi))
    throw CLI::ValidationError(option, fmt::format("{} (got {})", range, value));
}

std::int64_t parse_whole(const std::string& text, const std::string& option, const std::string& what,
                         std::int64_t lo, std::int64_t hi) {
  const double v = parse_number(text, option);
  if (!(v >= static_cast<double>(lo) && v <= static_cast<double>(hi)) || v != std::floor(v))
    throw CLI::ValidationError(option, fmt::format("{} {} .. {} (got {})", what, lo, hi, text));
  return static_cast<std::int64_t>(v);
}

Nanos parse_duration(const std::string& text, const std::string& option, Nanos lo, Nanos hi) {
  const double seconds = seconds_in(text, option);
  const auto refuse = [&] {
    return CLI::ValidationError(
        option, fmt::format("{} .. {} (got {})", duration_words(lo), duration_words(hi), text));
  };
  // As written first: NaN, infinities and huge values never reach the conversion to Nanos.
  // Half a ns of slack: a value is judged as it rounds (docs/synth.md "Ranges"), so 0.6ns on
  // a 1ns option is 1 ns and 3600.0000000004s is 3600 s; below 0 stays refused.
  const double lo_s = lo > Nanos::zero() ? lo.seconds() - 0.5e-9 : lo.seconds();
  if (!(seconds >= lo_s && seconds <= hi.seconds() + 0.5e-9)) throw refuse();
  const Nanos t = Nanos::from_seconds(seconds);
  if (t < lo || t > hi) throw refuse();
  return t;
}

Nanos parse_instant(const std::string& text, const std::string& option) {
  return parse_duration(text, option, Nanos::zero(), limits::kMaxEnd);
}

Nanos parse_positive_duration(const std::string& text, const std::string& option) {
  return parse_duration(text, option, Nanos{1}, limits::kMaxEnd);
}

void refuse_unless_applies(const CLI::App& kind, const std::string& option, bool applies,
                           const std::string& needs) {
  if (!applies && kind.count(option) > 0) throw CLI::ValidationError(option, needs);
}

void require_writable(const std::string& option, const std::string& path) {
  if (path == "-") return;
  if (path.empty()) throw CLI::ValidationError(option, "a file to write (got an empty path)");
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw CLI::ValidationError(option, path + ": a directory, not a file to write");
  // A file there already (a device like /dev/null, a pipe, a link) is written through.
  if (std::filesystem::exists(std::filesystem::symlink_status(path, ec)) && ::access(path.c_str(), W_OK) == 0)
    return;
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  const std::string where = dir.empty() ? "." : dir.string();
  if (::access(where.c_str(), W_OK | X_OK) != 0)
    throw CLI::ValidationError(option,
                               fmt::format("{}: cannot write in {}: {}", path, where, std::strerror(errno)));
}

void write_output_file(const std::string& path, const std::function<void(std::ostream&)>& write) {
  if (path == "-") {
    write(std::cout);
    std::cout.flush();
    return;
  }
  // A new or regular file is replaced whole (a crash leaves the old one or the new one); a
  // device, a pipe or a symlink is written through, as a shell redirection would: renaming a
  // file over it would replace /dev/null itself, or the link instead of its target.
  std::error_code ec;
  const auto status = std::filesystem::symlink_status(path, ec);
  if (!std::filesystem::exists(status) || std::filesystem::is_regular_file(status)) {
    rig::write_file_atomically(path, write);
    return;
  }
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error(fmt::format("cannot open {}: {}", path, std::strerror(errno)));
  write(out);
  out.flush();
  if (!out) throw std::runtime_error(fmt::format("cannot write {}: {}", path, std::strerror(errno)));
}

bool same_file(const std::string& a, const std::string& b) {
  if (a == "-" || b == "-") return false;
  std::error_code ec;
  if (std::filesystem::equivalent(a, b, ec)) return true; // both there: one inode
  const auto ca = std::filesystem::weakly_canonical(std::filesystem::absolute(a, ec), ec);
  const auto cb = std::filesystem::weakly_canonical(std::filesystem::absolute(b, ec), ec);
  return ca == cb;
}

void write_vcd_file(const TraceRecorder& trace, const std::string& path) {
  write_output_file(path, [&trace](std::ostream& out) { write_vcd(trace, out); });
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
