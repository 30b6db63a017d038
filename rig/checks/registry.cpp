#include "rig/checks/registry.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <nlohmann/json.hpp>

#include "core/did_you_mean.hpp"
#include "rig/checks/phase_coverage.hpp"
#include "rig/checks/standstill.hpp"
#include "rig/checks/word_bits.hpp"

namespace hilrig::checks {
namespace {

using nlohmann::json;

// A number of a unit (ns_per_unit ns) in whole ns, rounded half away from zero: the one
// rounding of every check time (0.0005 us is 1 ns, 0.0004 us is 0).
double rounded_ns(double v, double ns_per_unit) { return std::round(v * ns_per_unit); }

// A check's table after validation: every key known, of its declared type, finite and in
// range. Read only while the parser builds the typed parameters.
class Table {
public:
  explicit Table(const json& p) : p_(p) {}
  [[nodiscard]] bool has(const char* k) const { return p_.contains(k); }
  [[nodiscard]] double num(const char* k, double def = 0.0) const {
    return has(k) ? p_.at(k).get<double>() : def;
  }
  [[nodiscard]] std::optional<double> opt_num(const char* k) const {
    return has(k) ? std::optional<double>{num(k)} : std::nullopt;
  }
  [[nodiscard]] std::int64_t integer(const char* k, std::int64_t def) const {
    return has(k) ? p_.at(k).get<std::int64_t>() : def;
  }
  [[nodiscard]] std::size_t count(const char* k, std::size_t def) const {
    return static_cast<std::size_t>(integer(k, static_cast<std::int64_t>(def)));
  }
  [[nodiscard]] std::string str(const char* k, std::string def = {}) const {
    return has(k) ? p_.at(k).get<std::string>() : def;
  }
  [[nodiscard]] bool flag(const char* k) const { return has(k) && p_.at(k).get<bool>(); }
  [[nodiscard]] Level level(const char* k, Level def) const {
    return has(k) ? level_of(p_.at(k).get<std::string>() == "high") : def;
  }
  [[nodiscard]] Nanos us(const char* k, Nanos def = Nanos{0}) const {
    return has(k) ? time(k, num(k), 1e3) : def;
  }
  [[nodiscard]] Nanos ms(const char* k, Nanos def = Nanos{0}) const {
    return has(k) ? time(k, num(k), 1e6) : def;
  }
  [[nodiscard]] std::optional<Nanos> opt_us(const char* k) const {
    return has(k) ? std::optional<Nanos>{us(k)} : std::nullopt;
  }
  [[nodiscard]] std::optional<Nanos> opt_ms(const char* k) const {
    return has(k) ? std::optional<Nanos>{ms(k)} : std::nullopt;
  }
  [[nodiscard]] std::vector<Nanos> us_list(const char* k) const {
    std::vector<Nanos> out;
    for (const auto& v : p_.at(k)) out.push_back(time(k, v.get<double>(), 1e3));
    return out;
  }

  // A time in whole ns: the unit's value rounded once, so 20.3 us is exactly 20'300 ns.
  static Nanos time(const char* k, double v, double ns_per_unit) {
    const double ns = rounded_ns(v, ns_per_unit);
    if (!(std::abs(ns) < 9.2e18)) throw ParamError(k, "a time that fits in 64-bit nanoseconds (< 292 years)");
    return Nanos{static_cast<std::int64_t>(ns)};
  }

private:
  const json& p_;
};

ParamRange any() { return {}; }
ParamRange at_least(double v) { return {v, false, std::nullopt}; }
ParamRange above(double v) { return {v, true, std::nullopt}; }
ParamRange between(double lo, double hi) { return {lo, false, hi}; }

ParamSpec P(std::string name, ParamType t, bool required, std::string help, ParamRange range = any()) {
  return ParamSpec{std::move(name), t, required, std::move(help), range};
}
// An instant of the run, in a unit of ns_per_unit nanoseconds (ParamSpec::instant_ns).
ParamSpec instant(ParamSpec p, double ns_per_unit) {
  p.instant_ns = ns_per_unit;
  return p;
}
constexpr double kUs = 1e3;
constexpr double kMs = 1e6;
// A duration that must last (a timeout, a step, a probe, a tick), in a unit of ns_per_unit
// nanoseconds: at least 1 ns once rounded (ParamSpec::duration_ns), checked with the ranges.
ParamSpec duration(ParamSpec p, double ns_per_unit) {
  p.range = above(0.0);
  p.duration_ns = ns_per_unit;
  return p;
}
// A probe pulse's width in us: a pulse width, 1 ns .. 3600 s like every stimulus's
// (docs/campaigns.md, "Times").
ParamSpec probe_width(ParamSpec p) {
  p = duration(std::move(p), kUs);
  p.range.max = 3.6e9;
  return p;
}
constexpr auto Num = ParamType::Number;
constexpr auto Int = ParamType::Integer;
constexpr auto Str = ParamType::String;
constexpr auto Lvl = ParamType::Level;

void one_of(const Table& t, const char* a, const char* b) {
  if (t.has(a) == t.has(b)) throw ParamError("", fmt::format("exactly one of '{}' and '{}'", a, b));
}
void ordered(const Table& t, const char* lo, const char* hi) {
  if (t.has(lo) && t.has(hi) && t.num(lo) > t.num(hi))
    throw ParamError(hi, fmt::format("a value >= {} ({})", lo, t.num(lo)));
}

WordSpec word_spec(std::string_view name, const Table& t) {
  WordSpec s;
  s.name = name;
  s.observation = t.str("observation");
  s.lower = t.opt_num("lower");
  s.upper = t.opt_num("upper");
  s.at = t.opt_ms("at_ms");
  return s;
}

// scan_us and phase_bins: the board's scan period a check reports its phase coverage against
// (throughput, pulse_width, advance_counts: one mechanism, rig/checks/phase_coverage.hpp).
// A bin is at least 1 ns wide: times are whole ns, and a finer bin could never be hit.
std::optional<PhaseScan> phase_scan(const Table& t) {
  if (t.has("phase_bins") && !t.has("scan_us")) throw ParamError("phase_bins", "only with scan_us");
  if (!t.has("scan_us")) return std::nullopt;
  const PhaseScan s{t.us("scan_us"), t.count("phase_bins", 10)};
  if (static_cast<std::int64_t>(s.bins) > s.scan.count()) {
    const auto most = std::min<std::int64_t>(s.scan.count(), 1000);
    if (t.has("phase_bins"))
      throw ParamError("phase_bins", fmt::format("1 .. {}: at most one bin per ns of scan_us ({} ns)", most,
                                                 s.scan.count()));
    throw ParamError("scan_us",
                     fmt::format("at least 0.01 us for the default 10 phase_bins (at most one bin per ns); "
                                 "or phase_bins 1 .. {}",
                                 most));
  }
  return s;
}

// A full-scale count: 0 (none) or at least one count. Below one, setpoint + k * modulus puts
// levels closer than a count apart, which no board resolves, and a scan step then meets
// without end (1e-9: millions of crossings a step).
double modulus_of(const Table& t) {
  const double m = t.num("modulus");
  if (m != 0.0 && m < 1.0)
    throw ParamError("modulus", fmt::format("0 (none) or at least 1 count, not {}", m));
  return m;
}

CheckParams throughput(std::string_view name, const Table& t) {
  one_of(t, "crossings_us", "setpoint");
  ThroughputParams p;
  p.output = t.str("output");
  p.spec.name = name;
  p.spec.expected = t.level("level", Level::High);
  p.spec.limit = t.us("limit_us");
  p.spec.p99_limit = t.opt_us("p99_limit_us");
  p.spec.min_limit = t.opt_us("min_limit_us");
  ordered(t, "min_limit_us", "limit_us");
  // Every latency is judged against limit_us, so a p99 above it could never fail.
  if (p.spec.p99_limit && *p.spec.p99_limit > p.spec.limit)
    throw ParamError("p99_limit_us", fmt::format("at most limit_us ({}): every latency is judged against "
                                                 "limit_us, so a p99 limit above it never judges",
                                                 t.num("limit_us")));
  p.spec.quiet = t.opt_us("quiet_us");
  p.spec.early = t.opt_us("early_us");
  if (p.spec.early && p.spec.min_limit)
    throw ParamError("early_us", "not with min_limit_us (min is judged against -early_us)");
  p.spec.timeout = t.us("timeout_us", Nanos::max());
  // An edge after the timeout is missing and one before min_limit_us fails: no board passes.
  if (p.spec.min_limit && p.spec.timeout < *p.spec.min_limit)
    throw ParamError("timeout_us",
                     fmt::format("a timeout >= min_limit_us ({}): an edge before min_limit_us fails and one "
                                 "after timeout_us is missing, so no board could pass",
                                 t.num("min_limit_us")));
  p.spec.min_count = t.count("min_count", 1);
  if (t.has("crossings_us")) {
    // The scan's keys refine setpoint: with given crossings they would be ignored.
    for (const char* key : {"direction", "step_us", "modulus", "from_us", "to_us"})
      if (t.has(key)) throw ParamError(key, "only with setpoint (crossings_us are the stimulus as given)");
    p.crossings = t.us_list("crossings_us");
    // Fewer crossings than min_count: no board could pass.
    const auto& given = std::get<std::vector<Nanos>>(p.crossings);
    if (p.spec.min_count > given.size())
      throw ParamError("min_count", fmt::format("1 .. {} (the number of crossings_us)", given.size()));
  } else {
    CrossingScan s;
    s.setpoint = t.num("setpoint");
    const std::string d = t.str("direction", "both");
    if (d != "rising" && d != "falling" && d != "both")
      throw ParamError("direction", "\"rising\", \"falling\" or \"both\"");
    s.direction = d == "rising" ? Direction::Rising : d == "falling" ? Direction::Falling : Direction::Both;
    s.from = t.opt_us("from_us");
    s.to = t.opt_us("to_us");
    ordered(t, "from_us", "to_us");
    s.step = t.us("step_us", Nanos{100'000});
    s.modulus = modulus_of(t);
    p.crossings = s;
  }
  p.phase = phase_scan(t);
  return p;
}

CheckParams debounce(std::string_view name, const Table& t) {
  DebounceParams p;
  p.spec = DebounceSpec{std::string(name), t.us("filter_us"), t.us("tolerance_us")};
  p.plan = BisectionPlan{t.us("narrow_us"), t.us("wide_us"), t.us("resolution_us", Nanos{1000}),
                         t.str("input"),    t.str("output"), t.level("level", Level::High)};
  if (p.plan.narrow >= p.plan.wide)
    throw ParamError("wide_us", fmt::format("a width > narrow_us ({})", t.num("narrow_us")));
  // The limit probe a hair short of the narrowest allowed boundary must be a pulse.
  if (p.spec.shortest_rejected() <= Nanos{0})
    throw ParamError("tolerance_us",
                     fmt::format("below filter_us ({}) by more than 0.001 us", t.num("filter_us")));
  // narrow_us and wide_us bracket a board outside the limits: narrow_us must be one every board
  // within them rejects, wide_us one every such board accepts (else the bracket says nothing).
  if (p.plan.narrow > p.spec.shortest_rejected())
    throw ParamError("narrow_us", fmt::format("a width below filter_us - tolerance_us ({} us), which a board "
                                              "within the limits rejects",
                                              to_us(p.spec.filter - p.spec.tolerance)));
  if (p.plan.wide < p.spec.longest_accepted())
    throw ParamError("wide_us", fmt::format("a width of at least filter_us + tolerance_us ({} us), which a "
                                            "board within the limits accepts",
                                            to_us(p.spec.longest_accepted())));
  p.phase = phase_scan(t);
  if (t.has("probe_phases") && !p.phase) throw ParamError("probe_phases", "only with scan_us");
  if (p.phase) {
    p.probe_phases = t.count("probe_phases", p.phase->bins);
    if (Nanos{static_cast<std::int64_t>(p.probe_phases)} > p.phase->scan)
      throw ParamError("probe_phases",
                       fmt::format("at most one phase per ns of scan_us ({})", t.num("scan_us")));
  }
  return p;
}

CheckParams advance(std::string_view name, const Table& t) {
  AdvanceParams p;
  p.output = t.str("output");
  p.spec.name = name;
  p.spec.level = t.level("level", Level::High);
  p.spec.setpoint = t.num("setpoint");
  // One advance: a time (scaled by the speed at each edge) or a fixed count, not both (one
  // would silently win).
  if (t.has("advance_ms") && t.has("advance_counts"))
    throw ParamError("advance_counts", "advance_ms or advance_counts, not both");
  p.spec.advance = t.ms("advance_ms");
  p.spec.advance_counts = t.opt_num("advance_counts");
  p.spec.tolerance = t.num("tolerance_counts", 1.0);
  p.spec.modulus = modulus_of(t);
  p.spec.min_edges = t.count("min_edges", 1);
  p.phase = phase_scan(t);
  return p;
}

CheckParams edge_at(std::string_view name, const Table& t) {
  EdgeAtPositionParams p;
  p.output = t.str("output");
  p.spec.name = name;
  p.spec.level = t.level("level", Level::High);
  p.spec.position = t.num("position");
  p.spec.tolerance = t.num("tolerance_counts", 1.0);
  p.spec.modulus = modulus_of(t);
  p.spec.min_edges = t.count("min_edges", 1);
  p.spec.from = t.opt_us("from_us");
  p.spec.to = t.opt_us("to_us");
  ordered(t, "from_us", "to_us");
  return p;
}

CheckParams brake(std::string_view name, const Table& t) {
  one_of(t, "brake_line", "applied_ms");
  BrakeParams p;
  p.spec.name = name;
  p.spec.limit = t.ms("limit_ms");
  if (t.has("report_tick_ms") && t.has("report_tolerance_ms"))
    throw ParamError("report_tick_ms", "either report_tick_ms or report_tolerance_ms, not both");
  p.spec.report_tolerance_ms = t.num("report_tolerance_ms", 2.0);
  p.spec.report_tick = t.opt_ms("report_tick_ms");
  // A key that only refines another does nothing alone: refused, as a typo would be.
  if (t.has("report_tolerance_ms") && !t.has("reported"))
    throw ParamError("report_tolerance_ms", "only with reported");
  if (t.has("fault_level") && !t.has("fault_output"))
    throw ParamError("fault_level", "only with fault_output");
  // The tick places the board's report (reported) and the fault it decides from it (fault_output).
  if (t.has("report_tick_ms") && !t.has("reported") && !t.has("fault_output"))
    throw ParamError("report_tick_ms", "only with reported or fault_output");
  for (const char* key : {"applied_level", "applied_debounce"})
    if (t.has(key) && !t.has("brake_line")) throw ParamError(key, "only with brake_line");
  if (t.has("fault_from_reported") && !(t.has("reported") && t.has("fault_output")))
    throw ParamError("fault_from_reported", "only with reported and fault_output");
  p.spec.fault_level = t.level("fault_level", Level::Low);
  p.spec.fault_from_reported = t.flag("fault_from_reported");
  p.applied = t.opt_ms("applied_ms");
  p.brake_line = t.str("brake_line");
  p.applied_level = t.level("applied_level", Level::Low);
  const std::string debounce = t.str("applied_debounce", "none");
  if (debounce != "none" && debounce != "ans1") throw ParamError("applied_debounce", "\"none\" or \"ans1\"");
  p.debounce = debounce == "ans1" ? BrakeDebounce::Ans1 : BrakeDebounce::None;
  if (t.has("reported")) p.reported = t.str("reported");
  if (t.has("fault_output")) p.fault_output = t.str("fault_output");
  p.spec.check_fault = p.fault_output.has_value();
  if (t.has("stop_window_ms") && !t.has("complete_stop_count"))
    throw ParamError("stop_window_ms", "only with complete_stop_count");
  if (t.has("complete_stop_count"))
    p.stop_rule = StopCountRule{t.num("complete_stop_count"), t.ms("stop_window_ms", Nanos{125'000'000})};
  return p;
}

CheckParams pulse(std::string_view name, const Table& t) {
  ordered(t, "min_us", "max_us");
  PulseWidthParams p;
  p.line = t.str("line");
  p.spec.name = name;
  p.spec.level = t.level("level", Level::High);
  p.spec.min = t.opt_us("min_us");
  p.spec.max = t.opt_us("max_us");
  p.spec.min_pulses = t.count("min_pulses", 1);
  p.phase = phase_scan(t);
  return p;
}

CheckParams word_equals(std::string_view name, const Table& t) {
  return WordEqualsParams{word_spec(name, t), t.num("value")};
}

CheckParams word_within(std::string_view name, const Table& t) {
  if (!t.has("lower") && !t.has("upper")) throw ParamError("", "lower, upper or both");
  ordered(t, "lower", "upper");
  return WordWithinParams{word_spec(name, t)};
}

CheckParams word_bits(std::string_view name, const Table& t) {
  const auto mask = static_cast<std::uint16_t>(t.integer("mask", 0));
  const auto value = static_cast<std::uint16_t>(t.integer("value", 0));
  if ((value & ~mask) != 0)
    throw ParamError("value", fmt::format("a value with no bit outside the mask 0x{:04X}", mask));
  return WordBitsParams{word_spec(name, t), mask, value};
}

// No backend fills Capture::frames and ::decoders yet (docs/campaigns.md "Checks"): the only
// CAN frames a run records are the rig's own resolver stream, and nothing splits the serial
// bytes into messages. A check that could only err is refused, after its keys are checked.
CheckParams frames(std::string_view /*name*/, const Table& /*t*/) {
  throw ParamError("", "a check kind a backend can judge: frame_decodes has no frame source on any "
                       "backend yet (no CAN frame or serial message of the board is captured)");
}

CheckParams shaft(std::string_view name, const Table& t) {
  bool judged = false;
  for (const char* key : {"steps", "duration_min_ms", "duration_max_ms", "peak_min", "peak_max", "reversals"})
    judged = judged || t.has(key);
  if (!judged)
    throw ParamError(
        "", "at least one of steps, duration_min_ms, duration_max_ms, peak_min, peak_max, reversals");
  ordered(t, "from_ms", "to_ms");
  ordered(t, "duration_min_ms", "duration_max_ms");
  ordered(t, "peak_min", "peak_max");
  ShaftMoveParams p;
  p.step_line = t.str("step_line");
  p.dir_line = t.str("dir_line");
  p.spec.name = name;
  p.spec.from = t.ms("from_ms");
  p.to_given = t.has("to_ms");
  if (p.to_given) p.spec.to = t.ms("to_ms");
  p.spec.dir_initial = t.level("dir_initial", Level::Low);
  p.spec.steps = t.opt_num("steps");
  if (t.has("steps_tolerance") && !t.has("steps")) throw ParamError("steps_tolerance", "only with steps");
  p.spec.steps_tolerance = t.num("steps_tolerance");
  p.spec.duration_min = t.opt_ms("duration_min_ms");
  p.spec.duration_max = t.opt_ms("duration_max_ms");
  p.spec.peak_min = t.opt_num("peak_min");
  p.spec.peak_max = t.opt_num("peak_max");
  if (t.has("reversals")) p.spec.reversals = static_cast<double>(t.integer("reversals", 0));
  return p;
}

using Builder = CheckParams (*)(std::string_view, const Table&);

CheckKind kind(std::string name, std::string summary, std::vector<ParamSpec> params, Builder b) {
  return CheckKind{std::move(name), std::move(summary), std::move(params),
                   [b](std::string_view check, const json& table) { return b(check, Table(table)); },
                   b == &debounce};
}

// The phase coverage keys (phase_scan), of what `of` names.
ParamSpec phase_param(const std::string& of) {
  return P("scan_us", Num, false, "the board's scan period: reports the " + of + "' phase coverage of it",
           between(0.001, 1e6));
}
ParamSpec bins_param() {
  return P("phase_bins", Int, false, "phase coverage bins over scan_us (10)", between(1.0, 1000.0));
}

std::vector<CheckKind> make_kinds() {
  const ParamRange time = at_least(0.0);   // a time or a limit on one
  const ParamRange counts = at_least(1.0); // fewest items judged: at least one
  std::vector<CheckKind> k;
  k.push_back(kind(
      "throughput", "latency from each setpoint crossing to the output edge: count, min, median, p99, max",
      {P("output", Str, true, "the output line"), P("level", Lvl, false, "expected edge level (high)"),
       P("limit_us", Num, true, "upper limit on the max latency (inclusive)", time),
       P("p99_limit_us", Num, false, "upper limit on p99 (default limit_us)", time),
       P("min_limit_us", Num, false, "lower limit on the min latency (inclusive; default none)", time),
       duration(P("timeout_us", Num, false,
                  "longest wait for an edge, inclusive (default: until the next crossing)"),
                kUs),
       duration(P("quiet_us", Num, false,
                  "only an edge after the line was quiet this long counts (a burst's first edge; default "
                  "any edge)"),
                kUs),
       P("early_us", Num, false, "an edge up to this long before the crossing counts; min >= -early_us",
         time),
       P("min_count", Int, false, "fewest latencies (1)", counts),
       instant(P("crossings_us", ParamType::NumberList, false, "stimulus crossing times; or setpoint", time),
               kUs),
       P("setpoint", Num, false, "counts: crossings derived from the position function"),
       P("direction", Str, false, "rising, falling or both (both)"),
       duration(P("step_us", Num, false, "scan step for crossings (100); shorter than the shortest dwell"),
                kUs),
       P("modulus", Num, false,
         "full-scale count: setpoint + k * modulus are crossings too (0: none; else at least 1)", time),
       instant(P("from_us", Num, false, "scan start", time), kUs),
       instant(P("to_us", Num, false, "scan end", time), kUs), phase_param("crossings"), bins_param()},
      throughput));
  k.push_back(kind(
      "debounce", "pulses shorter than the filter rejected, longer accepted; boundary by bisection",
      {duration(P("filter_us", Num, true, "the spec's filter time"), kUs),
       P("tolerance_us", Num, true, "allowed boundary error, either side (inclusive)", time),
       probe_width(P("narrow_us", Num, true, "narrowest probe (must be rejected)")),
       probe_width(P("wide_us", Num, true, "widest probe (must be accepted)")),
       duration(P("resolution_us", Num, false, "bisection stops at this bracket (1)"), kUs),
       P("input", Str, true, "the line the pulse is driven on"),
       P("output", Str, true, "the line whose edge means accepted"),
       P("level", Lvl, false, "the pulse's active level (high)"),
       P("scan_us", Num, false,
         "the board's scan period: probes start at probe_phases phases of it, coverage reported",
         between(0.001, 1e6)),
       bins_param(),
       P("probe_phases", Int, false, "probe start phases over scan_us (phase_bins)", between(1.0, 1000.0))},
      debounce));
  k.push_back(kind(
      "advance_counts", "each output edge at speed S fires at setpoint - S*advance, in counts",
      {P("output", Str, true, "the output line"), P("level", Lvl, false, "which edges (high)"),
       P("setpoint", Num, true, "counts"), P("advance_ms", Num, false, "advance time (0)", time),
       P("advance_counts", Num, false, "fixed advance in counts instead of speed*advance_ms"),
       P("tolerance_counts", Num, false, "either side, inclusive (1)", time),
       P("modulus", Num, false, "full-scale count for wrapping positions (0: none; else at least 1)", time),
       P("min_edges", Int, false, "fewest edges (1)", counts), phase_param("expected edges"), bins_param()},
      advance));
  k.push_back(
      kind("brake_stop_time", "brake applied to standstill against the limit; reported time and fault output",
           {P("limit_ms", Num, true, "stop time limit (inclusive)", time),
            P("brake_line", Str, false, "the brake input line; or applied_ms"),
            P("applied_level", Lvl, false, "level of brake_line that applies the brake (low)"),
            P("applied_debounce", Str, false,
              "which application of brake_line the board times: none (the first; a line that returns "
              "before the standstill is an error) or ans1 (the first the ANS1 qualifies, L1038-L1040)"),
            instant(P("applied_ms", Num, false, "when the brake was applied", time), kMs),
            P("reported", Str, false, "observation holding the board's stop time, ms"),
            P("report_tolerance_ms", Num, false, "|reported - measured| allowed (2)", time),
            duration(P("report_tick_ms", Num, false,
                       "the board's stop timer tick: reported judged within [last count change - tick, "
                       "standstill + tick]"),
                     kMs),
            P("fault_output", Str, false, "the stop-time fault output line"),
            P("fault_level", Lvl, false, "the fault output's level on a fault (low)"),
            P("fault_from_reported", ParamType::Boolean, false, "expect the fault from the reported time"),
            P("complete_stop_count", Num, false,
              "the board's standstill rule: stopped once the count changed by less than this over "
              "stop_window_ms, the stop ending stop_window_ms before (ANS1 CSC, L1042, L1052); default: "
              "the shaft's own standstill",
              between(1.0, 1e9)),
            duration(P("stop_window_ms", Num, false, "with complete_stop_count: the window (125)"), kMs)},
           brake));
  k.push_back(kind(
      "edge_at_position", "every edge of an output at a position, within a tolerance",
      {P("output", Str, true, "the output line"), P("level", Lvl, false, "which edges (high)"),
       P("position", Num, true, "counts"),
       P("tolerance_counts", Num, false, "either side, inclusive (1)", time),
       P("modulus", Num, false, "full-scale count (0: none; else at least 1)", time),
       P("min_edges", Int, false, "fewest edges (1)", counts),
       instant(P("from_us", Num, false, "judge the edges from this time (inclusive; default: all)", time),
               kUs),
       instant(P("to_us", Num, false, "judge the edges up to this time (inclusive; default: all)", time),
               kUs)},
      edge_at));
  k.push_back(kind("pulse_width", "every pulse on a line between a minimum and a maximum width",
                   {P("line", Str, true, "the line"), P("level", Lvl, false, "the pulse level (high)"),
                    P("min_us", Num, false, "shortest allowed (inclusive)", time),
                    P("max_us", Num, false, "longest allowed (inclusive)", time),
                    P("min_pulses", Int, false, "fewest pulses (1)", counts), phase_param("pulse starts"),
                    bins_param()},
                   pulse));
  k.push_back(
      kind("word_equals", "an observed word equals a value",
           {P("observation", Str, true, "the observation's name"), P("value", Num, true, "expected value"),
            instant(P("at_ms", Num, false, "judge the latest observation by then (default: the last)", time),
                    kMs)},
           word_equals));
  k.push_back(kind("word_within", "an observed word within limits",
                   {P("observation", Str, true, "the observation's name"),
                    P("lower", Num, false, "inclusive"), P("upper", Num, false, "inclusive"),
                    instant(P("at_ms", Num, false, "judge the latest observation by then", time), kMs)},
                   word_within));
  k.push_back(kind("frame_decodes",
                   "every captured CAN frame or serial message decodes with no named error (no backend "
                   "captures the board's frames yet: refused)",
                   {P("source", Str, true, "the bus or link"), P("decoder", Str, true, "the decoder's name"),
                    P("id", Int, false, "only frames with this id", between(0, 0x1FFFFFFF)),
                    P("min_frames", Int, false, "fewest frames (1)", counts)},
                   frames));
  k.push_back(
      kind("shaft_move",
           "a stepper shaft seen by its step and direction lines: net steps, duration, peak speed, reversals",
           {P("step_line", Str, true, "one edge per step"), P("dir_line", Str, true, "High = CW"),
            P("dir_initial", Lvl, false,
              "dir_line before its first edge when the capture did not read its level (low)"),
            instant(P("from_ms", Num, true,
                      "window start: the command or the stop trigger; steps after it count", time),
                    kMs),
            instant(P("to_ms", Num, false, "window end (the run's end)", time), kMs),
            P("steps", Num, false, "expected net steps, CW +"),
            P("steps_tolerance", Num, false, "either side, inclusive (0)", time),
            P("duration_min_ms", Num, false, "from from_ms to the last step (0 with no step)", time),
            P("duration_max_ms", Num, false, "upper limit on that", time),
            P("peak_min", Num, false, "steps/s: 1 / shortest step interval, lower limit", time),
            P("peak_max", Num, false, "steps/s: upper limit", time),
            P("reversals", Int, false, "exact count of direction changes", at_least(0)),
            P("profile_of", Str, false,
              "the [[host]] write (its name) of the move whose profile the step rate is drawn against: a "
              "relative move, jerk 0, after a configuration; evidence, not judged")},
           shaft));
  k.push_back(
      kind("word_bits", "an observed word's bits under a mask equal a value",
           {P("observation", Str, true, "the observation's name"),
            P("mask", Int, true, "bits judged, never none", between(1, 0xFFFF)),
            P("value", Int, true, "expected (word & mask); a negative one is a two's complement INT",
              between(-32768, 0xFFFF)),
            instant(P("at_ms", Num, false, "judge the latest observation by then (default: the last)", time),
                    kMs)},
           word_bits));
  return k;
}

bool type_ok(const json& v, ParamType t) {
  switch (t) {
  case ParamType::Number:
    return v.is_number();
  case ParamType::Integer:
    return v.is_number_integer();
  case ParamType::Boolean:
    return v.is_boolean();
  case ParamType::String:
    return v.is_string();
  case ParamType::Level:
    return v.is_string() && (v == "high" || v == "low");
  case ParamType::NumberList:
    return v.is_array() && !v.empty() &&
           std::all_of(v.begin(), v.end(), [](const json& e) { return e.is_number(); });
  }
  return false;
}

bool in_range(double v, const ParamRange& r) {
  if (!std::isfinite(v)) return false;
  if (r.min && (r.min_open ? v <= *r.min : v < *r.min)) return false;
  if (r.max && v > *r.max) return false;
  return true;
}

// Every number of a value (one, or each of a list) finite and in range.
bool value_ok(const json& v, const ParamSpec& s) {
  if (s.duration_ns > 0.0)
    return in_range(v.get<double>(), s.range) && rounded_ns(v.get<double>(), s.duration_ns) >= 1.0;
  if (s.type == ParamType::Number || s.type == ParamType::Integer) return in_range(v.get<double>(), s.range);
  if (s.type == ParamType::NumberList)
    return std::all_of(v.begin(), v.end(), [&](const json& e) { return in_range(e.get<double>(), s.range); });
  return true;
}

// Run-time lookups: a line, observation or decoder the capture lacks.
struct CaptureError {
  std::string what;
};

std::span<const Edge> line(const Capture& c, const std::string& name) {
  const auto it = c.lines.find(name);
  if (it == c.lines.end()) throw CaptureError{fmt::format("no line named '{}' in the capture", name)};
  return it->second;
}
const PositionFn& position_fn(const Capture& c) {
  if (!c.position) throw CaptureError{"the capture has no position function"};
  return c.position;
}

CheckResult run(const ThroughputParams& p, const Capture& c) {
  std::vector<Nanos> crossings;
  if (const auto* given = std::get_if<std::vector<Nanos>>(&p.crossings)) {
    crossings = *given;
  } else {
    const auto& s = std::get<CrossingScan>(p.crossings);
    crossings = find_crossings(position_fn(c), s.setpoint, s.from.value_or(c.begin), s.to.value_or(c.end),
                               s.step, s.direction, s.modulus, c.held);
  }
  CheckResult r = check_throughput(crossings, line(c, p.output), p.spec, c.end);
  if (p.phase)
    r.measurements.push_back(
        phase_coverage_measurement(p.spec.name + ".phase_coverage", crossings, p.phase->scan, p.phase->bins));
  return r;
}

CheckResult run(const DebounceParams& p, const Capture& c) {
  if (c.bisections.empty())
    throw CaptureError{"no bisection: the executive must run the plan's probes first"};
  CheckResult r = check_debounce(c.bisections, p.spec);
  if (p.phase) {
    std::vector<Nanos> starts;
    for (const PhaseBisection& b : c.bisections) starts.push_back(b.start);
    r.measurements.push_back(
        phase_coverage_measurement(p.spec.name + ".phase_coverage", starts, p.phase->scan, p.phase->bins));
  }
  return r;
}

// How many times `f` (the shaft's position, or where it stands plus its advance) reached
// `level` (or level + k * modulus) in [from, to]: throughput's crossing scan, both ways. A
// touch counts (reaching is enough), and so does starting there. Stepped every 10 us: an
// excursion past the level shorter than that may be missed, read as "not reached" (an error,
// never a pass). The last reach counts only if the shaft reached an edge of the tolerance band
// after it (level +- tolerance) by the span's end: till then a board within the tolerance may
// still fire (the shaft on its way through the band, or standing in it), so its missing edge is
// not the board's.
Reaches times_reached(const Capture& c, const PositionFn& f, double level, double tolerance, double modulus,
                      std::optional<Nanos> from, std::optional<Nanos> to) {
  // Crossings are found in (a, b]: one ns before `from` makes the span [from, to].
  const Nanos start = from ? std::max(c.begin, *from) : c.begin;
  const Nanos a = from ? std::max(c.begin, *from - Nanos{1}) : c.begin;
  const Nanos b = to.value_or(c.end);
  if (b < start) return {};
  const double off = f(start) - level;
  const bool at_start = modulus > 0.0 ? std::remainder(off, modulus) == 0.0 : off == 0.0;
  const std::vector<Nanos> crossed =
      b > a ? find_crossings(f, level, a, b, Nanos{10'000}, Direction::Both, modulus, c.held)
            : std::vector<Nanos>{};
  // Standing there at the start without arriving then (already there before, or the run's
  // first instant): reached once more.
  const bool arrived_at_start = !crossed.empty() && crossed.front() == start;
  const std::size_t times = crossed.size() + (at_start && !arrived_at_start ? 1 : 0);
  if (times == 0 || tolerance <= 0.0) return {times, false};
  const Nanos last = crossed.empty() ? start : crossed.back();
  const auto band_edge_after = [&](double edge) {
    return b > last &&
           !find_crossings(f, edge, last, b, Nanos{10'000}, Direction::Both, modulus, c.held).empty();
  };
  if (band_edge_after(level + tolerance) || band_edge_after(level - tolerance)) return {times, false};
  return {times - 1, true};
}

CheckResult run(const AdvanceParams& p, const Capture& c) {
  if (!c.speed && !p.spec.advance_counts) throw CaptureError{"the capture has no speed function"};
  // An edge is due where the position plus its advance reaches the setpoint.
  const ReachedFn reached = [&] {
    const PositionFn& pos = position_fn(c);
    const double seconds = static_cast<double>(p.spec.advance.count()) / 1e9;
    const PositionFn ahead = p.spec.advance_counts
                                 ? PositionFn([&](Nanos t) { return pos(t) + *p.spec.advance_counts; })
                                 : PositionFn([&](Nanos t) { return pos(t) + c.speed(t) * seconds; });
    return times_reached(c, ahead, p.spec.setpoint, p.spec.tolerance, p.spec.modulus, std::nullopt,
                         std::nullopt);
  };
  CheckResult r = check_advance(line(c, p.output), position_fn(c), c.speed, p.spec, reached);
  if (p.phase) {
    // The stimulus of each edge: the instant the shaft stood at its expected position, the
    // middle of the edge's tolerance window (linear at the edge's speed).
    std::vector<Nanos> expected;
    const std::string edge = p.spec.name + ".edge";
    for (const Measurement& m : r.measurements)
      if (m.window && m.name.rfind(edge, 0) == 0 && m.name != p.spec.name + ".edges")
        expected.push_back(m.window->begin + (m.window->end - m.window->begin) / 2);
    r.measurements.push_back(
        phase_coverage_measurement(p.spec.name + ".phase_coverage", expected, p.phase->scan, p.phase->bins));
  }
  return r;
}

CheckResult run(const EdgeAtPositionParams& p, const Capture& c) {
  const ReachedFn reached = [&] {
    return times_reached(c, position_fn(c), p.spec.position, p.spec.tolerance, p.spec.modulus, p.spec.from,
                         p.spec.to);
  };
  return check_edge_at_position(line(c, p.output), position_fn(c), c.speed, p.spec, reached);
}

CheckResult run(const BrakeParams& p, const Capture& c) {
  BrakeSpec s = p.spec;
  const auto failed = [&](const char* what, std::string why) {
    CheckResult r;
    r.measurements.push_back(failure(s.name + what, std::move(why)));
    return r;
  };
  const auto erred = [&](std::string why) { // nothing to judge
    CheckResult r;
    r.measurements.push_back(error(s.name + ".stop_time", std::move(why)));
    return r;
  };
  Nanos applied{0};
  std::span<const Edge> brake;
  if (p.applied) {
    applied = *p.applied;
  } else {
    brake = line(c, p.brake_line);
    const auto known = c.initial.find(p.brake_line);
    const Level before = known != c.initial.end() ? known->second
                         : brake.empty()          ? !p.applied_level
                                                  : !brake.front().level;
    const BrakeApplication a = brake_application(brake, before, p.applied_level, c.begin, c.end, p.debounce);
    const std::string noise =
        a.rejected.empty()
            ? std::string{}
            : fmt::format("; the ANS1's debounce (L1038-L1040) dropped {} as noise, the first at {} ns",
                          a.rejected.size() == 1 ? std::string("one application")
                                                 : fmt::format("{} applications", a.rejected.size()),
                          a.rejected.front().count());
    if (a.depends_on_phase)
      return erred(fmt::format(
          "nothing judged: whether the ANS1's debounce (L1038-L1040) qualifies an application of '{}' "
          "(or which) depends on the phase of its 1 ms tick; give applied_ms",
          p.brake_line));
    if (!a.applied && c.rig_driven.contains(p.brake_line)) // the rig's own stimulus never came
      return erred(fmt::format(
          "nothing judged: the rig never applied the brake on its line '{}' (no {} to {}{})", p.brake_line,
          p.debounce == BrakeDebounce::None ? "edge" : "qualified edge", level_name(p.applied_level), noise));
    if (!a.applied)
      return failed(".stop_time", fmt::format("missing edge: the brake line '{}' never applied the brake{}",
                                              p.brake_line, noise));
    applied = *a.applied;
    s.applied_spread = a.latest - applied;
    if (!a.rejected.empty())
      s.application = fmt::format("the first application the ANS1's debounce qualifies, L1038-L1040; {} "
                                  "dropped as noise before it, the first at {} ns",
                                  a.rejected.size(), a.rejected.front().count());
  }
  if (p.reported) {
    const rig::Observation* last = nullptr;
    for (const auto& o : c.observations)
      if (o.name == *p.reported && (!last || o.time >= last->time)) last = &o;
    if (!last)
      return failed(".reported", fmt::format("missing word: no observation named '{}'", *p.reported));
    s.reported_ms = last->value;
  }
  std::span<const Edge> fault;
  if (p.fault_output) fault = line(c, *p.fault_output);
  // Virtual time: the rig knows the trajectory and hands the exact standstill; on hardware
  // only the count changes are evidence, an interval judged on its upper end: [last change,
  // last change + one count at the final speed bound], from count changes before the brake
  // too (a shaft that turned its last count just before it may still be turning).
  auto still = c.standstill ? exact_standstill(c.standstill(applied), c.end)
                            : standstill_interval(c.motion, c.begin, c.end);
  // A shaft already still when the brake is applied has no stop to time: its stop time of 0
  // would pass any limit having judged nothing. On hardware, still for certain: the whole
  // interval ends by then.
  if (still && still->latest <= applied)
    return erred(fmt::format(
        "nothing judged: the shaft already stood still (by {} ns) when the brake was applied at {} ns",
        still->latest.count(), applied.count()));
  // A line that leaves the applied level before the stop ends applied the brake more than once:
  // which application a board times is its debounce's, so without one named nothing is judged
  // (a glitch before the real application would otherwise time the stop from the glitch).
  if (!p.applied && p.debounce == BrakeDebounce::None) {
    const Nanos until = still ? still->latest : c.end;
    if (const auto back = next_edge(brake, applied, until, !p.applied_level))
      return erred(fmt::format(
          "nothing judged: the brake line '{}' went back to {} at {} ns after applying the brake at {} ns, "
          "before the stop ended: which application the board times is its debounce's; name it with "
          "applied_debounce (\"ans1\": L1038-L1040) or give applied_ms",
          p.brake_line, level_name(!p.applied_level), back->time.count(), applied.count()));
  }
  if (p.stop_rule) {
    // The board's standstill, not the shaft's: the count's change over the window fell below
    // the complete stop count (a creeping shaft may never stand still for the rig).
    const auto seen = stop_count_standstill(position_fn(c), *p.stop_rule, applied, c.end);
    if (seen && *seen <= applied)
      return erred(fmt::format("nothing judged: the count already changed by less than {} over {} ms when "
                               "the brake was applied at {} ns",
                               p.stop_rule->counts, to_ms(p.stop_rule->window), applied.count()));
    if (!seen) {
      // Not still by the capture's end: the board's stop ends after end - window, if at all.
      const Nanos seen_to = c.end - p.stop_rule->window;
      const std::string why =
          fmt::format("the count never changed by less than {} over {} ms between the brake applied at {} ns "
                      "and the capture's end, so the board's stop time is over {} ms",
                      p.stop_rule->counts, to_ms(p.stop_rule->window), applied.count(),
                      to_ms(std::max(seen_to - applied, Nanos{0})));
      if (seen_to - applied >= s.limit)
        return failed(".stop_time", fmt::format("no standstill: {}, the {} ms limit", why, to_ms(s.limit)));
      return erred(fmt::format("nothing judged: {}, within the {} ms limit (campaign.end cuts the stop)", why,
                               to_ms(s.limit)));
    }
    const std::string rule = fmt::format("the count changed by less than {} over the {} ms after it",
                                         p.stop_rule->counts, to_ms(p.stop_rule->window));
    return check_brake_stop(applied, Standstill{*seen, *seen, std::nullopt, rule}, c.end, fault, s);
  }
  if (still) still->earliest = std::max(still->earliest, applied);
  // What a board timing the stop from count changes sees as its end (report_window()).
  const std::vector<PositionSample>& counts = c.counts.empty() ? c.motion : c.counts;
  if (still)
    if (const auto last = standstill_after(counts, applied, c.end); last && *last <= still->latest)
      still->last_count_change = std::min(*last, still->earliest);
  return check_brake_stop(applied, still, c.end, fault, s);
}

CheckResult run(const PulseWidthParams& p, const Capture& c) {
  const std::span<const Edge> edges = line(c, p.line);
  CheckResult r = check_pulse_width(edges, p.spec, c.end);
  if (p.phase) {
    // Where each pulse started within the board's scan or tick: a width the board quantises
    // to its tick shows its extremes only for starts across the whole tick.
    std::vector<Nanos> starts;
    for (const Edge& e : edges)
      if (e.level == p.spec.level) starts.push_back(e.time);
    r.measurements.push_back(
        phase_coverage_measurement(p.spec.name + ".phase_coverage", starts, p.phase->scan, p.phase->bins));
  }
  return r;
}
CheckResult run(const WordEqualsParams& p, const Capture& c) {
  return check_word_equals(c.observations, p.spec, p.value);
}
CheckResult run(const WordWithinParams& p, const Capture& c) {
  return check_word_within(c.observations, p.spec);
}
CheckResult run(const WordBitsParams& p, const Capture& c) {
  return check_word_bits(c.observations, p.spec, p.mask, p.value);
}

CheckResult run(const FrameDecodesParams& p, const Capture& c) {
  const auto src = c.frames.find(p.source);
  const auto dec = c.decoders.find(p.decoder);
  if (dec == c.decoders.end()) throw CaptureError{fmt::format("no decoder named '{}'", p.decoder)};
  static const std::vector<RawFrame> none;
  return check_frames_decode(src == c.frames.end() ? std::span<const RawFrame>(none) : src->second,
                             dec->second, p.spec);
}

CheckResult run(const ShaftMoveParams& p, const Capture& c) {
  ShaftMoveSpec s = p.spec;
  if (!p.to_given) s.to = c.end;
  // The direction the capture saw the line start at, over the campaign's assumption.
  if (const auto it = c.initial.find(p.dir_line); it != c.initial.end()) s.dir_initial = it->second;
  s.to_given = p.to_given;
  return check_shaft_move(line(c, p.step_line), line(c, p.dir_line), s, c.end);
}

struct Lines {
  std::vector<std::string> operator()(const ThroughputParams& p) const { return {p.output}; }
  std::vector<std::string> operator()(const DebounceParams& p) const { return {p.plan.input, p.plan.output}; }
  std::vector<std::string> operator()(const AdvanceParams& p) const { return {p.output}; }
  std::vector<std::string> operator()(const EdgeAtPositionParams& p) const { return {p.output}; }
  std::vector<std::string> operator()(const BrakeParams& p) const {
    std::vector<std::string> out;
    if (!p.applied) out.push_back(p.brake_line);
    if (p.fault_output) out.push_back(*p.fault_output);
    return out;
  }
  std::vector<std::string> operator()(const PulseWidthParams& p) const { return {p.line}; }
  std::vector<std::string> operator()(const ShaftMoveParams& p) const { return {p.step_line, p.dir_line}; }
  std::vector<std::string> operator()(const auto&) const { return {}; }
};

} // namespace

const char* to_string(ParamType t) {
  switch (t) {
  case ParamType::Number:
    return "number";
  case ParamType::Integer:
    return "integer";
  case ParamType::Boolean:
    return "boolean";
  case ParamType::String:
    return "string";
  case ParamType::Level:
    return "\"high\" or \"low\"";
  case ParamType::NumberList:
    return "list of numbers";
  }
  return "?";
}

std::string expected_text(ParamType t, const ParamRange& r) {
  std::string what;
  switch (t) {
  case ParamType::Number:
    what = "a finite number";
    break;
  case ParamType::Integer:
    what = "an integer";
    break;
  case ParamType::NumberList:
    what = "a non-empty list of finite numbers";
    break;
  case ParamType::Boolean:
    return "true or false";
  case ParamType::String:
    return "a string";
  case ParamType::Level:
    return "\"high\" or \"low\"";
  }
  if (r.min && r.max) return fmt::format("{} {} .. {}", what, *r.min, *r.max);
  if (r.min) return fmt::format("{} {} {}", what, r.min_open ? ">" : ">=", *r.min);
  if (r.max) return fmt::format("{} <= {}", what, *r.max);
  return what;
}

std::string expected_text(const ParamSpec& p) {
  if (p.duration_ns == 0.0) return expected_text(p.type, p.range);
  // The least number that rounds to 1 ns: half a ns in the unit (0.0005 us, 0.0000005 ms).
  std::string least = fmt::format("{:.9f}", 0.5 / p.duration_ns);
  least.erase(least.find_last_not_of('0') + 1);
  const std::string most = p.range.max ? fmt::format(" and <= {}", *p.range.max) : std::string();
  return fmt::format("{} >= {}{} (at least 1 ns once rounded to whole ns)", expected_text(p.type, {}), least,
                     most);
}

const std::vector<CheckKind>& check_kinds() {
  static const std::vector<CheckKind> kinds = make_kinds();
  return kinds;
}

const CheckKind* find_check_kind(std::string_view name) {
  for (const auto& k : check_kinds())
    if (k.name == name) return &k;
  return nullptr;
}

CheckParams build_check_params(const CheckKind& kind, std::string_view check, const json& table) {
  if (!table.is_object()) throw ParamError("", "a table of parameters");
  for (const auto& item : table.items()) {
    // Not a structured binding: clang 14 (the fuzz build) cannot capture one in a lambda.
    const std::string& key = item.key();
    const json& value = item.value();
    const auto it = std::find_if(kind.params.begin(), kind.params.end(),
                                 [&](const ParamSpec& s) { return s.name == key; });
    if (it == kind.params.end()) {
      std::string names;
      std::vector<std::string> valid;
      for (const auto& s : kind.params) {
        names += (names.empty() ? "" : ", ") + s.name;
        valid.push_back(s.name);
      }
      throw ParamError(
          key, fmt::format("a parameter of {} (one of {}){}", kind.name, names, did_you_mean(key, valid)));
    }
    if (!type_ok(value, it->type) || !value_ok(value, *it)) throw ParamError(key, expected_text(*it));
  }
  for (const auto& s : kind.params)
    if (s.required && !table.contains(s.name))
      throw ParamError(s.name, fmt::format("missing: {} ({})", expected_text(s), s.help));
  return kind.build(check, table);
}

std::vector<Nanos> DebounceParams::probe_starts(Nanos probe_at) const {
  std::vector<Nanos> starts;
  const Nanos scan = phase ? phase->scan : Nanos{0};
  const auto n = static_cast<std::int64_t>(probe_phases);
  for (std::int64_t k = 0; k < n; ++k) starts.push_back(probe_at + Nanos{scan.count() * k / n});
  return starts;
}

std::string_view kind_of(const CheckParams& params) {
  static constexpr std::string_view names[] = {
      "throughput",  "debounce",    "advance_counts", "edge_at_position", "brake_stop_time", "pulse_width",
      "word_equals", "word_within", "word_bits",      "frame_decodes",    "shaft_move"};
  static_assert(std::size(names) == std::variant_size_v<CheckParams>);
  return names[params.index()];
}

std::vector<std::string> lines_of(const CheckParams& params) { return std::visit(Lines{}, params); }

CheckResult run_check(std::string_view check, const CheckParams& params, const Capture& capture) {
  CheckResult r;
  try {
    r = std::visit([&](const auto& p) { return run(p, capture); }, params);
  } catch (const CaptureError& e) {
    r = CheckResult{};
    r.measurements.push_back(error(std::string(check), e.what));
  }
  r.check = check;
  r.kind = kind_of(params);
  return r;
}

} // namespace hilrig::checks
