#include "rig/results/results_json.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <type_traits>
#include <utility>

#include "rig/results/atomic_file.hpp"
#include "rig/results/run_log.hpp"

namespace hilrig::rig {
namespace {

using nlohmann::json;

json opt(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }
json opt_str(const std::string& s) { return s.empty() ? json(nullptr) : json(s); }

Outcome outcome_from(const std::string& s) {
  if (s == "pass") return Outcome::Pass;
  if (s == "fail") return Outcome::Fail;
  if (s == "error") return Outcome::Error;
  throw std::runtime_error(fmt::format("results: unknown outcome '{}'", s));
}

const json& field(const json& j, const char* key, const char* where) {
  if (!j.is_object() || !j.contains(key))
    throw std::runtime_error(fmt::format("results: {} has no '{}'", where, key));
  return j.at(key);
}

template <class T> T get(const json& j, const char* key, const char* where) {
  const json& v = field(j, key, where);
  if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
    // nlohmann converts any number to any integer type without a word: a run index of -1 would
    // read 18446744073709551615, a seed of 1e20 read 0.
    using Limits = std::numeric_limits<T>;
    const bool fits =
        v.is_number_unsigned() ? v.get<std::uint64_t>() <= static_cast<std::uint64_t>(Limits::max())
        : v.is_number_integer()
            ? std::is_signed_v<T> && v.get<std::int64_t>() >= static_cast<std::int64_t>(Limits::min())
            : false;
    if (!fits)
      throw std::runtime_error(fmt::format("results: {}.{}: {} is not a whole number {} .. {}", where, key,
                                           v.dump(), Limits::min(), Limits::max()));
  }
  try {
    return v.get<T>();
  } catch (const json::exception& e) {
    throw std::runtime_error(fmt::format("results: {}.{}: {}", where, key, e.what()));
  }
}

// A number our writer wrote: nlohmann writes a double that is not finite (NaN, +-inf) as null,
// so every reader of a double takes null back as NaN (a NaN reads "not a number" in every
// output and is never judged a pass); anything else that is not a number is refused.
double real_or_nan(const json& v, const char* what) {
  if (v.is_null()) return std::numeric_limits<double>::quiet_NaN();
  if (!v.is_number())
    throw std::runtime_error(fmt::format("results: {} is {}, not a number", what, v.type_name()));
  return v.get<double>();
}

// An array field: iterating anything else would take an object's values, or a single value,
// as if they were its elements.
const json& array_field(const json& j, const char* key, const char* where) {
  const json& v = field(j, key, where);
  if (!v.is_array())
    throw std::runtime_error(fmt::format("results: {}.{} is {}, not an array", where, key, v.type_name()));
  return v;
}

// Runs f(element, i) for each element, naming the element ("checks[2]: ...") in what it throws.
template <class F> void each_of(const json& array, const char* key, F f) {
  std::size_t i = 0;
  for (const auto& e : array) {
    try {
      f(e);
    } catch (const std::exception& x) {
      throw std::runtime_error(fmt::format("{}[{}]: {}", key, i, x.what()));
    }
    ++i;
  }
}

std::optional<double> get_opt(const json& j, const char* key, const char* where) {
  const json& v = field(j, key, where);
  if (v.is_null()) return std::nullopt;
  return get<double>(j, key, where);
}

json measurement_json(const Measurement& m) {
  json w = nullptr;
  if (m.window) w = json{{"begin_ns", m.window->begin.count()}, {"end_ns", m.window->end.count()}};
  // A value that is not a number (a broken position function) is written as null, not as an
  // invalid JSON token; the reader gives it back as NaN.
  const json value = std::isfinite(m.value) ? json(m.value) : json(nullptr);
  return json{{"name", m.name},
              {"value", value},
              {"unit", m.unit},
              {"lower", opt(m.lower)},
              {"upper", opt(m.upper)},
              {"outcome", to_string(m.outcome)},
              {"detail", m.detail},
              {"window", std::move(w)},
              {"at_ns", m.at ? json(m.at->count()) : json(nullptr)}};
}

Measurement measurement_from(const json& j) {
  const char* w = "measurement";
  Measurement m;
  m.name = get<std::string>(j, "name", w);
  m.value = real_or_nan(field(j, "value", w), "a measurement's value");
  m.unit = get<std::string>(j, "unit", w);
  m.lower = get_opt(j, "lower", w);
  m.upper = get_opt(j, "upper", w);
  m.outcome = outcome_from(get<std::string>(j, "outcome", w));
  // A value that is not a number judged nothing (judge()): a file saying it passed was edited.
  if (m.outcome == Outcome::Pass && !std::isfinite(m.value))
    throw std::runtime_error(
        fmt::format("results: measurement '{}' has no value (null) but outcome 'pass': a "
                    "value that is not a number is never a pass",
                    m.name));
  m.detail = get<std::string>(j, "detail", w);
  const json& win = field(j, "window", w);
  if (!win.is_null()) {
    m.window = TraceWindow{Nanos{get<std::int64_t>(win, "begin_ns", "window")},
                           Nanos{get<std::int64_t>(win, "end_ns", "window")}};
  }
  const json& at = field(j, "at_ns", w);
  if (!at.is_null()) m.at = Nanos{get<std::int64_t>(j, "at_ns", w)};
  return m;
}

json window_json(const TraceWindow& w) {
  return json{{"begin_ns", w.begin.count()}, {"end_ns", w.end.count()}};
}

TraceWindow window_from(const json& j, const char* where) {
  return TraceWindow{Nanos{get<std::int64_t>(j, "begin_ns", where)},
                     Nanos{get<std::int64_t>(j, "end_ns", where)}};
}

// Changes as [time_ns, value] pairs: the bulk of a timing check's entry.
json traces_json(const std::vector<WindowTrace>& traces) {
  json out = json::array();
  for (const auto& t : traces) {
    json lanes = json::array();
    for (const auto& l : t.lanes) {
      json changes = json::array();
      for (const auto& c : l.changes)
        changes.push_back(l.real ? json::array({c.time.count(), c.real})
                                 : json::array({c.time.count(), c.value}));
      json lane{{"name", l.name},
                {"role", to_string(l.role)},
                {"changes", std::move(changes)},
                {"thinned", l.thinned}};
      if (l.real) lane["real"] = true; // only an analog lane says so: the others stay as they were
      lanes.push_back(std::move(lane));
    }
    out.push_back(
        json{{"around", window_json(t.around)}, {"span", window_json(t.span)}, {"lanes", std::move(lanes)}});
  }
  return out;
}

LaneRole role_from(const std::string& s) {
  for (const LaneRole r : {LaneRole::Stimulus, LaneRole::Count, LaneRole::Output, LaneRole::Rate})
    if (s == to_string(r)) return r;
  throw std::runtime_error(fmt::format("results: unknown lane role '{}'", s));
}

std::vector<WindowTrace> traces_from(const json& j) {
  std::vector<WindowTrace> out;
  if (!j.is_array()) throw std::runtime_error("results: a check's 'traces' is not an array");
  for (const auto& t : j) {
    WindowTrace w{window_from(field(t, "around", "trace"), "trace around"),
                  window_from(field(t, "span", "trace"), "trace span"),
                  {}};
    for (const auto& l : array_field(t, "lanes", "trace")) {
      TraceLane lane{get<std::string>(l, "name", "lane"),
                     role_from(get<std::string>(l, "role", "lane")),
                     {},
                     get<std::size_t>(l, "thinned", "lane")};
      if (const auto r = l.find("real"); r != l.end()) {
        if (!r->is_boolean()) throw std::runtime_error("results: a lane's 'real' is not true or false");
        lane.real = r->get<bool>();
      }
      for (const auto& c : array_field(l, "changes", "lane")) {
        if (!c.is_array() || c.size() != 2 || !c[0].is_number_integer() ||
            !(lane.real ? c[1].is_number() || c[1].is_null() : c[1].is_number_integer()))
          throw std::runtime_error("results: a lane change is not [time_ns, value]");
        lane.changes.push_back(
            lane.real
                ? LaneChange{Nanos{c[0].get<std::int64_t>()}, 0, real_or_nan(c[1], "a real lane's value")}
                : LaneChange{Nanos{c[0].get<std::int64_t>()}, c[1].get<std::int64_t>()});
      }
      w.lanes.push_back(std::move(lane));
    }
    out.push_back(std::move(w));
  }
  return out;
}

json check_json(const CheckResult& c) {
  json ms = json::array();
  for (const auto& m : c.measurements) ms.push_back(measurement_json(m));
  json ss = json::array();
  for (const auto& s : c.series) ss.push_back(json{{"name", s.name}, {"unit", s.unit}, {"values", s.values}});
  json j{{"check", c.check},
         {"kind", c.kind},
         {"outcome", to_string(c.judgement)},
         {"measured", to_string(c.outcome())},
         {"measurements", std::move(ms)},
         {"series", std::move(ss)}};
  if (!c.probes.empty()) { // only when there are: other checks keep their bytes
    json ps = json::array();
    for (const auto& p : c.probes) {
      json probe{{"width_ns", p.width.count()}, {"accepted", p.accepted}};
      if (p.start) probe["start_ns"] = p.start->count();
      ps.push_back(std::move(probe));
    }
    j["probes"] = std::move(ps);
  }
  if (!c.traces.empty()) j["traces"] = traces_json(c.traces);
  if (!c.expected_rate.empty()) { // only a check that names its move: the others keep their bytes
    json knots = json::array();
    for (const auto& k : c.expected_rate) knots.push_back(json::array({k.time.count(), k.rate}));
    j["expected_rate"] = std::move(knots);
  }
  return j;
}

CheckResult check_from(const json& j) {
  const char* w = "check";
  CheckResult c;
  c.check = get<std::string>(j, "check", w);
  c.kind = get<std::string>(j, "kind", w);
  each_of(array_field(j, "measurements", w), "measurements",
          [&](const json& m) { c.measurements.push_back(measurement_from(m)); });
  each_of(array_field(j, "series", w), "series", [&](const json& s) {
    Series series{get<std::string>(s, "name", "series"), get<std::string>(s, "unit", "series"), {}};
    for (const auto& v : array_field(s, "values", "series"))
      series.values.push_back(real_or_nan(v, "a series value"));
    c.series.push_back(std::move(series));
  });
  if (j.contains("probes"))
    for (const auto& p : array_field(j, "probes", w)) {
      Probe probe{Nanos{get<std::int64_t>(p, "width_ns", "probe")}, get<bool>(p, "accepted", "probe")};
      if (p.contains("start_ns")) probe.start = Nanos{get<std::int64_t>(p, "start_ns", "probe")};
      c.probes.push_back(probe);
    }
  if (j.contains("traces")) c.traces = traces_from(j.at("traces"));
  if (j.contains("expected_rate"))
    for (const auto& k : array_field(j, "expected_rate", w)) {
      if (!k.is_array() || k.size() != 2 || !k[0].is_number_integer() ||
          !(k[1].is_number() || k[1].is_null()))
        throw std::runtime_error("results: an expected_rate knot is not [time_ns, steps/s]");
      c.expected_rate.push_back(
          RatePoint{Nanos{k[0].get<std::int64_t>()}, real_or_nan(k[1], "an expected_rate knot's rate")});
    }
  return c;
}

// Points as [time_ns, position, speed] triples: the bulk of a plant run's entry.
json motion_json(const MotionRecord& m) {
  json points = json::array();
  for (const auto& p : m.points) points.push_back(json::array({p.time.count(), p.position, p.speed}));
  json events = json::array();
  for (const auto& e : m.events) events.push_back(json{{"time_ns", e.time.count()}, {"what", e.what}});
  return json{{"position_unit", "counts"},
              {"speed_unit", "counts/s"},
              {"points", std::move(points)},
              {"events", std::move(events)}};
}

MotionRecord motion_from(const json& j) {
  MotionRecord m;
  for (const auto& p : array_field(j, "points", "motion")) {
    if (!p.is_array() || p.size() != 3 || !p[0].is_number_integer())
      throw std::runtime_error("results: a motion point is not [time_ns, position, speed]");
    m.points.push_back(MotionPoint{Nanos{p[0].get<std::int64_t>()},
                                   real_or_nan(p[1], "a motion point's position"),
                                   real_or_nan(p[2], "a motion point's speed")});
  }
  for (const auto& e : array_field(j, "events", "motion"))
    m.events.push_back(MotionEvent{Nanos{get<std::int64_t>(e, "time_ns", "motion event")},
                                   get<std::string>(e, "what", "motion event")});
  return m;
}

} // namespace

json run_to_json(const RunResult& r) {
  json checks = json::array();
  for (const auto& c : r.checks) checks.push_back(check_json(c));
  json obs = json::array();
  for (const auto& o : r.observations) {
    obs.push_back(json{{"name", o.name}, {"value", o.value}, {"unit", o.unit}, {"time_ns", o.time.count()}});
  }
  json j{{"index", r.index},
         {"name", r.name},
         {"seed", r.seed},
         {"fault", opt_str(r.fault)},
         {"must_catch", r.must_catch},
         {"error", opt_str(r.error)},
         {"outcome", to_string(r.outcome)},
         {"caught", r.fault.empty() ? json(nullptr) : json(caught(r))},
         {"checks", std::move(checks)},
         {"observations", std::move(obs)}};
  if (r.interrupted) j["interrupted"] = true; // only when set: uninterrupted results keep their bytes
  if (!r.motion.empty()) j["motion"] = motion_json(r.motion);
  if (!r.trace.empty()) j["trace"] = r.trace;
  return j;
}

namespace {

std::string str_or_empty(const json& j, const char* key, const char* where) {
  const json& v = field(j, key, where);
  return v.is_null() ? std::string() : get<std::string>(j, key, where);
}

} // namespace

RunResult run_from_json(const json& j) {
  const char* w = "run";
  RunResult r;
  r.index = get<std::uint64_t>(j, "index", w);
  r.name = get<std::string>(j, "name", w);
  r.seed = get<std::uint64_t>(j, "seed", w);
  r.fault = str_or_empty(j, "fault", w);
  r.must_catch = get<std::vector<std::string>>(j, "must_catch", w);
  r.error = str_or_empty(j, "error", w);
  if (j.contains("interrupted")) r.interrupted = get<bool>(j, "interrupted", w);
  each_of(array_field(j, "checks", w), "checks", [&](const json& c) { r.checks.push_back(check_from(c)); });
  each_of(array_field(j, "observations", w), "observations", [&](const json& o) {
    r.observations.push_back(Observation{
        get<std::string>(o, "name", "observation"),
        real_or_nan(field(o, "value", "observation"), "an observation's value"),
        get<std::string>(o, "unit", "observation"), Nanos{get<std::int64_t>(o, "time_ns", "observation")}});
  });
  if (j.contains("motion")) r.motion = motion_from(j.at("motion"));
  if (j.contains("trace")) r.trace = get<std::string>(j, "trace", w);
  return r;
}

namespace {

// The document; its runs array only when with_runs (to_json_text splices them in one by one).
json document(const CampaignResult& r, bool with_runs) {
  json runs = json::array();
  if (with_runs)
    for (const auto& run : r.runs) runs.push_back(run_to_json(run));
  json faults = json::array();
  for (const auto& f : r.faults) {
    faults.push_back(json{{"fault", f.fault},
                          {"must_catch", f.must_catch},
                          {"runs", f.runs},
                          {"caught_runs", f.caught_runs},
                          {"caught", f.caught()}});
  }
  const Totals& t = r.totals;
  json j{{"format", kResultsFormat},
         {"version", kResultsVersion},
         {"campaign", r.campaign},
         {"device", r.device},
         {"campaign_sha256", r.campaign_sha256},
         {"tool_version", r.tool_version},
         {"seed", r.seed},
         {"shard", json{{"index", r.shard.index}, {"count", r.shard.count}}},
         {"campaign_file", r.campaign_file},
         {"dut_serial", opt_str(r.dut_serial)},
         {"station", opt_str(r.station)},
         {"host_link", r.host_link},
         {"backend", r.backend},
         {"trace_policy", to_string(r.trace_policy)},
         {"planned_runs", r.planned_runs},
         {"complete", r.complete},
         {"runs", std::move(runs)},
         {"faults", std::move(faults)},
         {"totals", json{{"runs", t.runs},
                         {"runs_passed", t.runs_passed},
                         {"runs_failed", t.runs_failed},
                         {"runs_errored", t.runs_errored},
                         {"checks", t.checks},
                         {"checks_passed", t.checks_passed},
                         {"checks_failed", t.checks_failed},
                         {"checks_caught", t.checks_caught},
                         {"checks_not_judged", t.checks_not_judged},
                         {"checks_errored", t.checks_errored},
                         {"measurements", t.measurements},
                         {"faults", t.faults},
                         {"faults_caught", t.faults_caught}}},
         {"verdict", to_string(r.verdict)}};
  if (r.interrupted) j["interrupted"] = *r.interrupted;
  if (r.started_at || r.host) {
    json wc = json::object();
    if (r.started_at) wc["started_at"] = *r.started_at;
    if (r.host) wc["host"] = *r.host;
    j["wall_clock"] = std::move(wc);
  }
  return j;
}

} // namespace

json to_json(const CampaignResult& r) { return document(r, true); }

CampaignResult campaign_from_json(const json& j) {
  const char* w = "results";
  if (get<std::string>(j, "format", w) != kResultsFormat)
    throw std::runtime_error("results: not a hilrig results file");
  if (const int version = get<int>(j, "version", w); version != kResultsVersion)
    throw std::runtime_error(fmt::format("results: unsupported version {}: hilrig {} reads version {}",
                                         version, tool_version(), kResultsVersion));
  CampaignResult r;
  r.campaign = get<std::string>(j, "campaign", w);
  r.device = get<std::string>(j, "device", w);
  r.campaign_sha256 = get<std::string>(j, "campaign_sha256", w);
  r.tool_version = get<std::string>(j, "tool_version", w);
  r.seed = get<std::uint64_t>(j, "seed", w);
  const json& shard = field(j, "shard", w);
  r.shard = Shard{get<std::uint32_t>(shard, "index", "shard"), get<std::uint32_t>(shard, "count", "shard")};
  r.planned_runs = get<std::size_t>(j, "planned_runs", w);
  // Traceability: read when present (results written before it was recorded have none).
  if (j.contains("campaign_file")) r.campaign_file = get<std::string>(j, "campaign_file", w);
  if (j.contains("dut_serial")) r.dut_serial = str_or_empty(j, "dut_serial", w);
  if (j.contains("station")) r.station = str_or_empty(j, "station", w);
  if (j.contains("host_link")) r.host_link = get<std::string>(j, "host_link", w);
  if (j.contains("backend")) r.backend = get<std::string>(j, "backend", w);
  if (j.contains("trace_policy")) { // results written before --trace kept every trace they could
    const auto name = get<std::string>(j, "trace_policy", w);
    const std::optional<TracePolicy> policy = trace_policy_named(name);
    if (!policy)
      throw std::runtime_error("results: trace_policy \"" + name + "\" is not all, failed or none");
    r.trace_policy = *policy;
  }
  each_of(array_field(j, "runs", w), "runs", [&](const json& run) { r.runs.push_back(run_from_json(run)); });
  // A run is one index of the plan: a file holding one twice (hand-edited, or two files pasted
  // together) would be counted twice by compare and trend.
  std::set<std::uint64_t> indices;
  for (const RunResult& run : r.runs)
    if (!indices.insert(run.index).second)
      throw std::runtime_error(fmt::format("results: run {} appears twice", run.index));
  if (j.contains("interrupted")) r.interrupted = get<std::string>(j, "interrupted", w);
  if (j.contains("wall_clock")) {
    const json& wc = j.at("wall_clock");
    if (wc.contains("started_at")) r.started_at = get<std::string>(wc, "started_at", "wall_clock");
    if (wc.contains("host")) r.host = get<std::string>(wc, "host", "wall_clock");
  }
  finalize(r);
  return r;
}

const char* tool_version() { return HILRIG_VERSION; }

RunDumpSource dumps_of(const RunSource& runs) {
  return [runs](const RunDumpVisitor& visit) {
    runs([&](const RunResult& run) { visit(run_to_json(run).dump(2)); });
  };
}

std::string compact_json_text(std::string_view indented) {
  std::string out(indented.size(), '\0');
  char* w = out.data();
  const char* p = indented.data();
  const char* const end = p + indented.size();
  while (p < end) {
    const char c = *p++;
    if (c == '"') { // a string, through its closing quote, escapes (\" and \\ too) as they are
      *w++ = c;
      while (p < end) {
        const char d = *p++;
        *w++ = d;
        if (d == '\\') {
          if (p < end) *w++ = *p++;
        } else if (d == '"') {
          break;
        }
      }
    } else if (c != ' ' && c != '\n') {
      *w++ = c;
    }
  }
  out.resize(static_cast<std::size_t>(w - out.data()));
  return out;
}

void write_json_text(const CampaignResult& header, const RunSource& runs, const TextSink& out) {
  write_json_dumps(header, dumps_of(runs), out);
}

void write_json_dumps(const CampaignResult& header, const RunDumpSource& runs, const TextSink& out) {
  // The same bytes as to_json(r).dump(2), but each run's DOM is built and dumped alone and
  // spliced in (the runs are nearly all of the file): writing a long campaign's results.json
  // holds one run's DOM, not the whole document's.
  const std::string text = document(header, false).dump(2);
  const std::string empty = "\n  \"runs\": []";
  const std::size_t at = text.find(empty);
  if (at == std::string::npos) throw std::logic_error("results: no runs array to fill");
  out(std::string_view(text).substr(0, at));
  out("\n  \"runs\": [");
  bool first = true;
  runs([&](std::string_view dump) {
    std::string piece = first ? "\n    " : ",\n    ";
    first = false;
    piece.reserve(piece.size() + dump.size() + dump.size() / 4);
    // Indented two levels deeper: each line break gains four spaces.
    for (std::size_t from = 0; from < dump.size();) {
      const std::size_t nl = std::min(dump.find('\n', from), dump.size());
      piece.append(dump, from, nl - from);
      if (nl < dump.size()) piece += "\n    ";
      from = nl + 1;
    }
    out(piece);
  });
  out(first ? "]" : "\n  ]");
  out(std::string_view(text).substr(at + empty.size()));
  out("\n");
}

std::string to_json_text(const CampaignResult& r) {
  std::string text;
  write_json_text(r, runs_of(r), [&](std::string_view piece) { text += piece; });
  return text;
}

void write_results_file(const std::filesystem::path& path, const CampaignResult& result) {
  write_results_file(path, result, runs_of(result));
}

void write_results_file(const std::filesystem::path& path, const CampaignResult& header,
                        const RunSource& runs) {
  write_file_atomically(path, [&](std::ostream& out) { write_json_text(header, runs, sink_to(out)); });
}

void write_results_dumps(const std::filesystem::path& path, const CampaignResult& header,
                         const RunDumpSource& runs) {
  write_file_atomically(path, [&](std::ostream& out) { write_json_dumps(header, runs, sink_to(out)); });
}

CampaignResult read_results_file(const std::filesystem::path& path) {
  // A stream over a directory opens, then fails to read with a library's words: name the file.
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw std::runtime_error(fmt::format("{}: a directory, not a results.json or runs.jsonl", path.string()));
  if (path.extension() == ".jsonl") return read_run_log(path);
  std::ifstream in(path);
  if (!in) throw std::runtime_error(fmt::format("cannot read {}", path.string()));
  json j;
  try {
    in >> j;
  } catch (const json::exception& e) {
    throw std::runtime_error(fmt::format("{}: not JSON: {}", path.string(), e.what()));
  }
  try {
    return campaign_from_json(j);
  } catch (const std::exception& e) { // a mistyped value nlohmann finds first, too
    throw std::runtime_error(fmt::format("{}: {}", path.string(), e.what()));
  }
}

} // namespace hilrig::rig
