#include "rig/checks/registry.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "rig/checks/crossings.hpp"
#include "rig/checks/edge_position.hpp"
#include "rig/checks/pulse_width.hpp"
#include "rig/checks/shaft_move.hpp"
#include "rig/checks/throughput.hpp"
#include "rig/checks/word_bits.hpp"
#include "rig/checks/words.hpp"

namespace hilrig::checks {
namespace {

using nlohmann::json;

// Thrown inside a check's run function for a problem the schema cannot see (no such line);
// run_check turns it into an Error measurement.
struct CaptureError {
  std::string what;
};

bool has(const json& p, const char* k) { return p.contains(k); }
double num(const json& p, const char* k, double def) { return has(p, k) ? p.at(k).get<double>() : def; }
std::optional<double> opt_num(const json& p, const char* k) {
  return has(p, k) ? std::optional<double>{p.at(k).get<double>()} : std::nullopt;
}
std::string str(const json& p, const char* k, std::string def = {}) {
  return has(p, k) ? p.at(k).get<std::string>() : def;
}
std::size_t count(const json& p, const char* k, std::size_t def) {
  return has(p, k) ? p.at(k).get<std::size_t>() : def;
}
Level level(const json& p, const char* k, Level def) {
  return has(p, k) ? level_of(p.at(k).get<std::string>() == "high") : def;
}
Nanos from_unit(double v, double ns_per_unit) { return Nanos{std::llround(v * ns_per_unit)}; }
Nanos us(const json& p, const char* k, Nanos def = Nanos{0}) {
  return has(p, k) ? from_unit(p.at(k).get<double>(), 1e3) : def;
}
Nanos ms(const json& p, const char* k, Nanos def = Nanos{0}) {
  return has(p, k) ? from_unit(p.at(k).get<double>(), 1e6) : def;
}
std::optional<Nanos> opt_us(const json& p, const char* k) {
  return has(p, k) ? std::optional<Nanos>{us(p, k)} : std::nullopt;
}

std::span<const Edge> line(const Capture& c, const std::string& name) {
  const auto it = c.lines.find(name);
  if (it == c.lines.end()) throw CaptureError{fmt::format("no line named '{}' in the capture", name)};
  return it->second;
}
const PositionFn& position_fn(const Capture& c) {
  if (!c.position) throw CaptureError{"the capture has no position function"};
  return c.position;
}

ParamSpec P(std::string name, ParamType t, bool required, std::string help) {
  return ParamSpec{std::move(name), t, required, std::move(help)};
}
constexpr auto Num = ParamType::Number;
constexpr auto Int = ParamType::Integer;
constexpr auto Str = ParamType::String;
constexpr auto Lvl = ParamType::Level;

CheckResult throughput(std::string_view name, const Capture& c, const json& p) {
  ThroughputSpec s;
  s.name = name;
  s.expected = level(p, "level", Level::High);
  s.limit = us(p, "limit_us");
  s.p99_limit = opt_us(p, "p99_limit_us");
  s.timeout = us(p, "timeout_us", Nanos::max());
  s.min_count = count(p, "min_count", 1);
  std::vector<Nanos> crossings;
  if (has(p, "crossings_us")) {
    for (const auto& v : p.at("crossings_us")) crossings.push_back(from_unit(v.get<double>(), 1e3));
  } else {
    const std::string d = str(p, "direction", "both");
    const Direction dir = d == "rising"    ? Direction::Rising
                          : d == "falling" ? Direction::Falling
                                           : Direction::Both;
    crossings =
        find_crossings(position_fn(c), num(p, "setpoint", 0.0), us(p, "from_us", c.begin),
                       us(p, "to_us", c.end), us(p, "step_us", Nanos{100'000}), dir, num(p, "modulus", 0.0));
  }
  return check_throughput(crossings, line(c, str(p, "output")), s);
}

CheckResult debounce(std::string_view name, const Capture& c, const json& p) {
  if (!c.bisection) throw CaptureError{"no bisection: the executive must run debounce_plan() probes first"};
  return check_debounce(*c.bisection,
                        DebounceSpec{std::string(name), us(p, "filter_us"), us(p, "tolerance_us")});
}

CheckResult advance(std::string_view name, const Capture& c, const json& p) {
  AdvanceSpec s;
  s.name = name;
  s.level = level(p, "level", Level::High);
  s.setpoint = num(p, "setpoint", 0.0);
  s.advance = ms(p, "advance_ms");
  s.advance_counts = opt_num(p, "advance_counts");
  s.tolerance = num(p, "tolerance_counts", 1.0);
  s.modulus = num(p, "modulus", 0.0);
  s.min_edges = count(p, "min_edges", 1);
  if (!c.speed && !s.advance_counts) throw CaptureError{"the capture has no speed function"};
  return check_advance(line(c, str(p, "output")), position_fn(c), c.speed, s);
}

CheckResult edge_at(std::string_view name, const Capture& c, const json& p) {
  EdgeAtPositionSpec s;
  s.name = name;
  s.level = level(p, "level", Level::High);
  s.position = num(p, "position", 0.0);
  s.tolerance = num(p, "tolerance_counts", 1.0);
  s.modulus = num(p, "modulus", 0.0);
  s.min_edges = count(p, "min_edges", 1);
  return check_edge_at_position(line(c, str(p, "output")), position_fn(c), c.speed, s);
}

CheckResult brake(std::string_view name, const Capture& c, const json& p) {
  BrakeSpec s;
  s.name = name;
  s.limit = ms(p, "limit_ms");
  s.report_tolerance_ms = num(p, "report_tolerance_ms", 2.0);
  s.fault_level = level(p, "fault_level", Level::Low);
  s.fault_from_reported = has(p, "fault_from_reported") && p.at("fault_from_reported").get<bool>();
  Nanos applied{0};
  if (has(p, "applied_ms")) {
    applied = ms(p, "applied_ms");
  } else {
    const auto e = next_edge(line(c, str(p, "brake_line")), c.begin, Nanos::max(),
                             level(p, "applied_level", Level::Low));
    if (!e) {
      CheckResult r;
      r.kind = "brake_stop_time";
      r.measurements.push_back(failure(
          std::string(name) + ".stop_time",
          fmt::format("missing edge: the brake line '{}' never applied the brake", str(p, "brake_line"))));
      return r;
    }
    applied = e->time;
  }
  if (has(p, "reported")) {
    const std::string obs = str(p, "reported");
    const rig::Observation* last = nullptr;
    for (const auto& o : c.observations) {
      if (o.name == obs && (!last || o.time >= last->time)) last = &o;
    }
    if (!last) {
      CheckResult r;
      r.kind = "brake_stop_time";
      r.measurements.push_back(failure(std::string(name) + ".reported",
                                       fmt::format("missing word: no observation named '{}'", obs)));
      return r;
    }
    s.reported_ms = last->value;
  }
  std::span<const Edge> fault;
  if (has(p, "fault_output")) {
    s.check_fault = true;
    fault = line(c, str(p, "fault_output"));
  }
  return check_brake_stop(applied, c.motion, c.end, fault, s);
}

CheckResult pulse(std::string_view name, const Capture& c, const json& p) {
  PulseWidthSpec s;
  s.name = name;
  s.level = level(p, "level", Level::High);
  s.min = opt_us(p, "min_us");
  s.max = opt_us(p, "max_us");
  s.min_pulses = count(p, "min_pulses", 1);
  return check_pulse_width(line(c, str(p, "line")), s);
}

WordSpec word_spec(std::string_view name, const json& p) {
  WordSpec s;
  s.name = name;
  s.observation = str(p, "observation");
  s.lower = opt_num(p, "lower");
  s.upper = opt_num(p, "upper");
  if (has(p, "at_ms")) s.at = ms(p, "at_ms");
  return s;
}

CheckResult frames(std::string_view name, const Capture& c, const json& p) {
  FrameSpec s;
  s.name = name;
  if (has(p, "id")) s.id = p.at("id").get<std::uint32_t>();
  s.min_frames = count(p, "min_frames", 1);
  const auto src = c.frames.find(str(p, "source"));
  const auto dec = c.decoders.find(str(p, "decoder"));
  if (dec == c.decoders.end()) throw CaptureError{fmt::format("no decoder named '{}'", str(p, "decoder"))};
  static const std::vector<RawFrame> none;
  return check_frames_decode(src == c.frames.end() ? std::span<const RawFrame>(none) : src->second,
                             dec->second, s);
}

CheckResult shaft(std::string_view name, const Capture& c, const json& p) {
  ShaftMoveSpec s;
  s.name = name;
  s.from = ms(p, "from_ms");
  s.to = has(p, "to_ms") ? ms(p, "to_ms") : c.end;
  s.dir_initial = level(p, "dir_initial", Level::Low);
  s.steps = opt_num(p, "steps");
  s.steps_tolerance = num(p, "steps_tolerance", 0.0);
  s.duration_min_ms = opt_num(p, "duration_min_ms");
  s.duration_max_ms = opt_num(p, "duration_max_ms");
  s.peak_min = opt_num(p, "peak_min");
  s.peak_max = opt_num(p, "peak_max");
  s.reversals = opt_num(p, "reversals");
  return check_shaft_move(line(c, str(p, "step_line")), line(c, str(p, "dir_line")), s);
}

std::vector<std::string> one_of(const json& p, const char* a, const char* b) {
  if (has(p, a) == has(p, b)) return {fmt::format("give exactly one of '{}' and '{}'", a, b)};
  return {};
}

std::vector<CheckKind> make_kinds() {
  const auto bind = [](CheckResult (*f)(std::string_view, const Capture&, const json&)) {
    // The check's name is filled in by run_check; the function gets it through params["__name"].
    return [f](const Capture& c, const json& p) { return f(p.value("__name", std::string()), c, p); };
  };
  std::vector<CheckKind> k;
  k.push_back(
      {"throughput",
       "latency from each setpoint crossing to the output edge: count, min, median, p99, max",
       {P("output", Str, true, "the output line"), P("level", Lvl, false, "expected edge level (high)"),
        P("limit_us", Num, true, "upper limit on the max latency"),
        P("p99_limit_us", Num, false, "upper limit on p99 (default limit_us)"),
        P("timeout_us", Num, false, "longest wait for an edge (default: until the next crossing)"),
        P("min_count", Int, false, "fewest latencies (1)"),
        P("crossings_us", ParamType::NumberList, false, "stimulus crossing times; or setpoint"),
        P("setpoint", Num, false, "counts: crossings derived from the position function"),
        P("direction", Str, false, "rising, falling or both (both)"),
        P("step_us", Num, false, "scan step for crossings (100); shorter than the shortest dwell"),
        P("modulus", Num, false, "full-scale count: setpoint + k * modulus are crossings too (0: none)"),
        P("from_us", Num, false, "scan start"), P("to_us", Num, false, "scan end")},
       bind(throughput),
       false,
       [](const json& p) { return one_of(p, "crossings_us", "setpoint"); }});
  k.push_back({"debounce",
               "pulses shorter than the filter rejected, longer accepted; boundary by bisection",
               {P("filter_us", Num, true, "the spec's filter time"),
                P("tolerance_us", Num, true, "allowed boundary error"),
                P("narrow_us", Num, true, "narrowest probe (must be rejected)"),
                P("wide_us", Num, true, "widest probe (must be accepted)"),
                P("resolution_us", Num, false, "bisection stops at this bracket (1)"),
                P("input", Str, true, "the line the pulse is driven on"),
                P("output", Str, true, "the line whose edge means accepted"),
                P("level", Lvl, false, "the pulse's active level (high)")},
               bind(debounce),
               true,
               nullptr});
  k.push_back({"advance_counts",
               "each output edge at speed S fires at setpoint - S*advance, in counts",
               {P("output", Str, true, "the output line"), P("level", Lvl, false, "which edges (high)"),
                P("setpoint", Num, true, "counts"), P("advance_ms", Num, false, "advance time (0)"),
                P("advance_counts", Num, false, "fixed advance in counts instead of speed*advance_ms"),
                P("tolerance_counts", Num, false, "either side (1)"),
                P("modulus", Num, false, "full-scale count for wrapping positions (0: none)"),
                P("min_edges", Int, false, "fewest edges (1)")},
               bind(advance),
               false,
               nullptr});
  k.push_back(
      {"brake_stop_time",
       "brake applied to standstill against the limit; reported time and fault output",
       {P("limit_ms", Num, true, "stop time limit"),
        P("brake_line", Str, false, "the brake input line; or applied_ms"),
        P("applied_level", Lvl, false, "level of brake_line that applies the brake (low)"),
        P("applied_ms", Num, false, "when the brake was applied"),
        P("reported", Str, false, "observation holding the board's stop time, ms"),
        P("report_tolerance_ms", Num, false, "|reported - measured| allowed (2)"),
        P("fault_output", Str, false, "the stop-time fault output line"),
        P("fault_level", Lvl, false, "the fault output's level on a fault (low)"),
        P("fault_from_reported", ParamType::Boolean, false, "expect the fault from the reported time")},
       bind(brake),
       false,
       [](const json& p) { return one_of(p, "brake_line", "applied_ms"); }});
  k.push_back({"edge_at_position",
               "every edge of an output at a position, within a tolerance",
               {P("output", Str, true, "the output line"), P("level", Lvl, false, "which edges (high)"),
                P("position", Num, true, "counts"), P("tolerance_counts", Num, false, "either side (1)"),
                P("modulus", Num, false, "full-scale count (0: none)"),
                P("min_edges", Int, false, "fewest edges (1)")},
               bind(edge_at),
               false,
               nullptr});
  k.push_back({"pulse_width",
               "every pulse on a line between a minimum and a maximum width",
               {P("line", Str, true, "the line"), P("level", Lvl, false, "the pulse level (high)"),
                P("min_us", Num, false, "shortest allowed"), P("max_us", Num, false, "longest allowed"),
                P("min_pulses", Int, false, "fewest pulses (1)")},
               bind(pulse),
               false,
               nullptr});
  k.push_back(
      {"word_equals",
       "an observed word equals a value",
       {P("observation", Str, true, "the observation's name"), P("value", Num, true, "expected value"),
        P("at_ms", Num, false, "judge the latest observation by then (default: the last)")},
       [](const Capture& c, const json& p) {
         return check_word_equals(c.observations, word_spec(p.value("__name", std::string()), p),
                                  p.at("value").get<double>());
       },
       false,
       nullptr});
  k.push_back(
      {"word_within",
       "an observed word within limits",
       {P("observation", Str, true, "the observation's name"), P("lower", Num, false, "inclusive"),
        P("upper", Num, false, "inclusive"), P("at_ms", Num, false, "judge the latest observation by then")},
       [](const Capture& c, const json& p) {
         return check_word_within(c.observations, word_spec(p.value("__name", std::string()), p));
       },
       false,
       [](const json& p) {
         return has(p, "lower") || has(p, "upper") ? std::vector<std::string>{}
                                                   : std::vector<std::string>{"give lower, upper or both"};
       }});
  k.push_back(
      {"frame_decodes",
       "every captured CAN frame or serial message decodes with no named error",
       {P("source", Str, true, "the bus or link"), P("decoder", Str, true, "the decoder's name"),
        P("id", Int, false, "only frames with this id"), P("min_frames", Int, false, "fewest frames (1)")},
       bind(frames),
       false,
       nullptr});
  k.push_back(
      {"shaft_move",
       "a stepper shaft seen by its step and direction lines: net steps, duration, peak speed, reversals",
       {P("step_line", Str, true, "one edge per step"), P("dir_line", Str, true, "High = CW"),
        P("dir_initial", Lvl, false, "dir_line before its first edge (low)"),
        P("from_ms", Num, true, "window start: the command or the stop trigger; steps after it count"),
        P("to_ms", Num, false, "window end (the run's end)"),
        P("steps", Num, false, "expected net steps, CW +"),
        P("steps_tolerance", Num, false, "either side (0)"),
        P("duration_min_ms", Num, false, "from from_ms to the last step (0 with no step)"),
        P("duration_max_ms", Num, false, "upper limit on that"),
        P("peak_min", Num, false, "steps/s: 1 / shortest step interval, lower limit"),
        P("peak_max", Num, false, "steps/s: upper limit"),
        P("reversals", Int, false, "exact count of direction changes")},
       bind(shaft),
       false,
       [](const json& p) {
         for (const char* key :
              {"steps", "duration_min_ms", "duration_max_ms", "peak_min", "peak_max", "reversals"})
           if (has(p, key)) return std::vector<std::string>{};
         return std::vector<std::string>{"give at least one of steps, duration_*, peak_*, reversals"};
       }});
  k.push_back(
      {"word_bits",
       "an observed word's bits under a mask equal a value",
       {P("observation", Str, true, "the observation's name"), P("mask", Int, true, "bits judged (0..65535)"),
        P("value", Int, true, "expected (word & mask)"),
        P("at_ms", Num, false, "judge the latest observation by then (default: the last)")},
       [](const Capture& c, const json& p) {
         return check_word_bits(c.observations, word_spec(p.value("__name", std::string()), p),
                                static_cast<std::uint16_t>(p.at("mask").get<std::uint64_t>() & 0xFFFFU),
                                static_cast<std::uint16_t>(p.at("value").get<std::uint64_t>() & 0xFFFFU));
       },
       false,
       [](const json& p) {
         if (p.at("mask").get<std::uint64_t>() > 0xFFFFU || p.at("value").get<std::uint64_t>() > 0xFFFFU)
           return std::vector<std::string>{"mask and value are 16-bit words (0..65535)"};
         if ((p.at("value").get<std::uint64_t>() & ~p.at("mask").get<std::uint64_t>()) != 0U)
           return std::vector<std::string>{"value has bits outside the mask"};
         return std::vector<std::string>{};
       }});
  return k;
}

bool type_ok(const json& v, ParamType t) {
  switch (t) {
  case ParamType::Number:
    return v.is_number();
  case ParamType::Integer:
    return v.is_number_integer() && !(v.is_number_integer() && v.get<std::int64_t>() < 0);
  case ParamType::Boolean:
    return v.is_boolean();
  case ParamType::String:
    return v.is_string();
  case ParamType::Level:
    return v.is_string() && (v == "high" || v == "low");
  case ParamType::NumberList:
    return v.is_array() && std::all_of(v.begin(), v.end(), [](const json& e) { return e.is_number(); });
  }
  return false;
}

} // namespace

const char* to_string(ParamType t) {
  switch (t) {
  case ParamType::Number:
    return "number";
  case ParamType::Integer:
    return "non-negative integer";
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

const std::vector<CheckKind>& check_kinds() {
  static const std::vector<CheckKind> kinds = make_kinds();
  return kinds;
}

const CheckKind* find_check_kind(std::string_view name) {
  for (const auto& k : check_kinds()) {
    if (k.name == name) return &k;
  }
  return nullptr;
}

std::vector<std::string> validate_check_params(const CheckKind& kind, const json& params) {
  std::vector<std::string> errors;
  if (!params.is_object()) return {"parameters must be a table"};
  for (const auto& item : params.items()) {
    // Not a structured binding: clang 14 (the fuzz build) cannot capture one in a lambda.
    const std::string& key = item.key();
    const json& value = item.value();
    const auto it = std::find_if(kind.params.begin(), kind.params.end(),
                                 [&](const ParamSpec& s) { return s.name == key; });
    if (it == kind.params.end()) {
      errors.push_back(fmt::format("{}: unknown parameter '{}'", kind.name, key));
    } else if (!type_ok(value, it->type)) {
      errors.push_back(fmt::format("{}: parameter '{}' must be a {}", kind.name, key, to_string(it->type)));
    }
  }
  for (const auto& s : kind.params) {
    if (s.required && !params.contains(s.name)) {
      errors.push_back(fmt::format("{}: missing parameter '{}' ({})", kind.name, s.name, s.help));
    }
  }
  if (errors.empty() && kind.cross_check) {
    for (auto& e : kind.cross_check(params)) errors.push_back(fmt::format("{}: {}", kind.name, e));
  }
  return errors;
}

CheckResult run_check(std::string_view check, std::string_view kind, const Capture& capture,
                      const json& params) {
  const auto fail_with = [&](std::string why) {
    CheckResult r;
    r.check = check;
    r.kind = kind;
    r.measurements.push_back(error(std::string(check), std::move(why)));
    return r;
  };
  const CheckKind* k = find_check_kind(kind);
  if (!k) return fail_with(fmt::format("unknown check kind '{}'", kind));
  const auto errors = validate_check_params(*k, params);
  if (!errors.empty()) return fail_with(errors.front());
  json named = params;
  named["__name"] = std::string(check);
  try {
    CheckResult r = k->run(capture, named);
    r.check = check;
    r.kind = kind;
    return r;
  } catch (const CaptureError& e) {
    return fail_with(e.what);
  }
}

BisectionPlan debounce_plan(const json& p) {
  return BisectionPlan{us(p, "narrow_us"), us(p, "wide_us"), us(p, "resolution_us", Nanos{1000}),
                       str(p, "input"),    str(p, "output"), level(p, "level", Level::High)};
}

} // namespace hilrig::checks
