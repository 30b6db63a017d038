#include "rig/results/compare.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <stdexcept>

#include "rig/results/number_format.hpp"

namespace hilrig::rig {
namespace {

struct Entry {
  const Measurement* m;
  const CheckResult* check; // the check that measured it: its word in the run
  bool matched = false;
};

using Key = std::pair<std::string, std::string>; // run name, measurement name

std::map<Key, Entry> index_of(const CampaignResult& r, std::vector<Key>* order) {
  std::map<Key, Entry> out;
  std::map<std::string, std::size_t> seen; // a repeated run name is told apart as "name#2", "name#3"
  for (const auto& run : r.runs) {
    const std::size_t n = ++seen[run.name];
    const std::string label = n == 1 ? run.name : fmt::format("{}#{}", run.name, n);
    for (const auto& c : run.checks) {
      for (const auto& m : c.measurements) {
        Key k{label, m.name};
        if (out.emplace(k, Entry{&m, &c}).second && order) order->push_back(std::move(k));
      }
    }
  }
  return out;
}

bool matches(const std::string& pattern, const std::string& name) {
  if (pattern == name) return true;
  return name.size() > pattern.size() && name.ends_with(pattern) &&
         name[name.size() - pattern.size() - 1] == '.';
}

Threshold threshold_for(const CompareOptions& o, const std::string& name) {
  const Threshold* best = nullptr;
  for (const auto& t : o.thresholds) {
    if (matches(t.name, name) && (!best || t.name.size() > best->name.size())) best = &t;
  }
  return best ? *best : Threshold{"", o.default_rel, true};
}

// Beyond the threshold by the one comparison rule the checks use (judge(): inclusive, with
// its epsilon), so a drift of exactly 5 % against 5 % is within, not flagged by the rounding
// of 9.44065 / 188.813 = 0.05000000000000003.
bool beyond(const Threshold& t, double base, double now) {
  const double allowed = t.relative ? t.value * std::fabs(base) : t.value;
  return judge(now, base - allowed, base + allowed) != Outcome::Pass;
}

bool bad(Judgement w) { return w == Judgement::Fail || w == Judgement::Error; }

// What changed between the baseline's word and the new one, read by what the run is: in a
// fault run a failing measurement of the catching check is the fault's evidence ("caught"),
// so a check that stops catching is the regression and one that starts is an improvement;
// a nominal run's pass -> fail is the regression and fail -> pass an improvement. nullopt:
// the words tell nothing new, the values decide.
std::optional<Drift> word_change(const CheckResult& bc, Judgement base, const CheckResult& nc,
                                 Judgement now) {
  const bool was_catching = bc.judgement == Judgement::Caught;
  const bool is_catching = nc.judgement == Judgement::Caught;
  if (was_catching && !is_catching && base == Judgement::Caught) return Drift::NoLongerCatches;
  if (!was_catching && is_catching && now == Judgement::Caught) return Drift::NowCatches;
  if (!bad(base) && bad(now)) return Drift::NewlyFails;
  if (bad(base) && now == Judgement::Pass) return Drift::NowPasses;
  return std::nullopt;
}

int rank(Outcome o) { return o == Outcome::Pass ? 0 : o == Outcome::Fail ? 1 : 2; }

} // namespace

bool threshold_matches(const Threshold& t, const std::string& measurement) {
  return matches(t.name, measurement);
}

Threshold parse_threshold(std::string_view text) {
  const auto eq = text.find('=');
  if (eq == std::string_view::npos || eq == 0 || eq + 1 == text.size()) {
    throw std::invalid_argument(fmt::format("threshold '{}': expected NAME=VALUE or NAME=VALUE%", text));
  }
  Threshold t;
  t.name = std::string(text.substr(0, eq));
  std::string_view v = text.substr(eq + 1);
  if (v.ends_with('%')) {
    t.relative = true;
    v.remove_suffix(1);
  }
  double value = 0.0;
  const auto [p, ec] = std::from_chars(v.data(), v.data() + v.size(), value);
  // from_chars reads "nan" and "inf": a NaN threshold would make every drift pass unnoticed.
  if (ec != std::errc{} || p != v.data() + v.size() || !std::isfinite(value) || value < 0.0) {
    throw std::invalid_argument(fmt::format("threshold '{}': '{}' is not a non-negative number", text, v));
  }
  t.value = t.relative ? value / 100.0 : value;
  return t;
}

const char* to_string(Drift d) {
  switch (d) {
  case Drift::Same:
    return "same";
  case Drift::Within:
    return "within";
  case Drift::Beyond:
    return "DRIFT";
  case Drift::Missing:
    return "MISSING";
  case Drift::Added:
    return "added";
  case Drift::NewlyFails:
    return "NEWLY FAILS";
  case Drift::NowPasses:
    return "now passes";
  case Drift::NowCatches:
    return "now catches";
  case Drift::NoLongerCatches:
    return "NO LONGER CATCHES";
  }
  return "?";
}

std::size_t Comparison::regressions() const {
  return static_cast<std::size_t>(
      std::count_if(rows.begin(), rows.end(), [](const DriftRow& r) { return r.regression(); }));
}

std::size_t Comparison::improvements() const {
  return static_cast<std::size_t>(
      std::count_if(rows.begin(), rows.end(), [](const DriftRow& r) { return r.improvement(); }));
}

bool Comparison::regression() const { return regressions() > 0 || rank(now_verdict) > rank(base_verdict); }

Comparison compare_results(const CampaignResult& base, const CampaignResult& now,
                           const CompareOptions& options) {
  Comparison c;
  c.base_verdict = base.verdict;
  c.now_verdict = now.verdict;
  std::vector<Key> base_order;
  std::vector<Key> now_order;
  auto b = index_of(base, &base_order);
  auto n = index_of(now, &now_order);
  for (const auto& k : base_order) {
    const Entry& be = b.at(k);
    const Measurement& bm = *be.m;
    DriftRow row;
    row.run = k.first;
    row.measurement = k.second;
    row.unit = bm.unit;
    row.base = bm.value;
    row.base_word = measurement_judgement(*be.check, bm);
    row.threshold = threshold_for(options, k.second);
    const auto it = n.find(k);
    if (it == n.end()) {
      row.drift = Drift::Missing;
    } else {
      it->second.matched = true;
      const Measurement& nm = *it->second.m;
      row.now = nm.value;
      row.lower = nm.lower;
      row.upper = nm.upper;
      row.now_word = measurement_judgement(*it->second.check, nm);
      if (const auto changed = word_change(*be.check, row.base_word, *it->second.check, row.now_word)) {
        row.drift = *changed;
      } else if (bm.value == nm.value) {
        row.drift = Drift::Same;
      } else {
        row.drift = beyond(row.threshold, bm.value, nm.value) ? Drift::Beyond : Drift::Within;
      }
    }
    c.rows.push_back(std::move(row));
  }
  for (const auto& k : now_order) {
    const Entry& e = n.at(k);
    if (e.matched) continue;
    DriftRow row;
    row.run = k.first;
    row.measurement = k.second;
    row.unit = e.m->unit;
    row.now = e.m->value;
    row.lower = e.m->lower;
    row.upper = e.m->upper;
    row.now_word = measurement_judgement(*e.check, *e.m);
    row.drift = Drift::Added;
    c.rows.push_back(std::move(row));
  }
  return c;
}

namespace {

// The limit a value broke, if it broke one: the number it must be told apart from.
std::optional<double> broken_limit(const DriftRow& r) {
  return r.now ? limit_beyond(*r.now, r.lower, r.upper) : std::nullopt;
}

// A failing value's limits, as junit.xml writes them: "[- .. 21000]".
std::string limits_text(const DriftRow& r) {
  const auto end = [](const std::optional<double>& v) {
    return v ? format_number_apart(*v, std::nullopt) : "-";
  };
  return fmt::format("[{} .. {}]", end(r.lower), end(r.upper));
}

} // namespace

std::string format_comparison(const Comparison& c, bool all) {
  const auto num = [](const std::optional<double>& v, const std::optional<double>& beside = std::nullopt) {
    return v ? format_number_apart(*v, beside) : std::string("-");
  };
  std::string out = fmt::format("{:<40} {:<32} {:>12} {:>12} {:>12} {:>10}  {}\n", "run", "measurement",
                                "base", "new", "delta", "threshold", "status");
  std::size_t shown = 0;
  for (const auto& r : c.rows) {
    if (!all && (r.drift == Drift::Same || r.drift == Drift::Within)) continue;
    ++shown;
    const std::string delta = r.base && r.now ? fmt::format("{:+.6g}", *r.now - *r.base) : std::string("-");
    const std::string thr = r.drift == Drift::Added ? std::string("-")
                            : r.threshold.relative  ? fmt::format("{:g}%", r.threshold.value * 100.0)
                                                    : fmt::format("{:g}", r.threshold.value);
    const std::optional<double> broken = broken_limit(r);
    std::string note = r.unit;
    if (broken) note += (note.empty() ? "" : "; ") + std::string("limits ") + limits_text(r);
    out += fmt::format("{:<40} {:<32} {:>12} {:>12} {:>12} {:>10}  {}{}\n", r.run, r.measurement, num(r.base),
                       num(r.now, broken), delta, thr, to_string(r.drift),
                       note.empty() ? std::string() : fmt::format(" ({})", note));
  }
  if (shown == 0) out += "(no measurement drifted)\n";
  out += fmt::format("{} measurements compared, {} regressions, {} improvements; verdict {} -> {}{}\n",
                     c.rows.size(), c.regressions(), c.improvements(), to_string(c.base_verdict),
                     to_string(c.now_verdict),
                     rank(c.now_verdict) > rank(c.base_verdict)   ? " (worse)"
                     : rank(c.now_verdict) < rank(c.base_verdict) ? " (better)"
                                                                  : "");
  return out;
}

} // namespace hilrig::rig
