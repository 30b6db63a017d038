#include "rig/results/report_html.hpp"

#include <algorithm>
#include <fmt/format.h>

#include "rig/results/figure_data.hpp"
#include "rig/results/figure_html.hpp"
#include "rig/results/number_format.hpp"
#include "rig/results/timing_figures.hpp"
#include "rig/results/xml_escape.hpp"

namespace hilrig::rig {
namespace {

constexpr const char* kStyle =
    "body{font-family:sans-serif;margin:1.5em;color:#1f2328}"
    "table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #d0d7de;padding:2px "
    "6px;text-align:left}"
    "th{background:#f6f8fa}.pass{color:#1a7f37;font-weight:bold}.fail{color:#cf222e;font-weight:bold}"
    ".error{color:#9a6700;font-weight:bold}.caught{color:#0969da;font-weight:bold}"
    ".not-judged{color:#57606a}.verdict{font-size:1.6em}figure{margin:.3em 0}"
    "figcaption{font-size:.85em;color:#57606a}td.num{text-align:right;font-variant-numeric:tabular-nums}"
    "details.run{border:1px solid #d0d7de;border-radius:6px;margin:.4em 0;padding:.2em .6em}"
    "details.run>summary{cursor:pointer;font-weight:bold}section.check{margin-left:.5em}"
    "ul.summary li{margin:.15em 0}";

// Measurement rows shown per check before the rest is only in the table (timing diagrams:
// timing_figures.hpp).
constexpr std::size_t kLimitRows = 16;

std::string badge_of(const char* word) {
  const std::string cls = std::string(word) == "not judged" ? "not-judged" : word;
  return fmt::format("<span class=\"{}\">{}</span>", cls, word);
}
std::string badge(Outcome o) { return badge_of(to_string(o)); }
std::string badge(Judgement j) { return badge_of(to_string(j)); }

std::string limit_cell(const std::optional<double>& v, const std::string& unit) {
  return v ? format_value(*v, unit) : "&#8212;";
}

std::string anchor(const RunResult& run, std::size_t check) {
  return fmt::format("r{}-c{}", run.index, check);
}

std::string figure(const nlohmann::json& data, const std::string& caption) {
  return figure_html(data, caption);
}

// The measurements with those not passing first (stable: in recorded order otherwise).
std::vector<ShownMeasurement> failing_first(const CheckResult& c) {
  std::vector<ShownMeasurement> rows;
  for (const auto& m : c.measurements) rows.push_back({&m, measurement_judgement(c, m)});
  std::stable_partition(rows.begin(), rows.end(),
                        [](const ShownMeasurement& r) { return r.shown != Judgement::Pass; });
  return rows;
}

// The brake's stop time on the run's motion: applied, standstill and the limit marked.
std::string brake_figures(const CheckResult& c, const RunResult& run) {
  std::string s;
  for (const auto& m : c.measurements) {
    if (!m.window || m.unit != "ms") continue;
    std::vector<Marker> marks{{m.window->begin, "applied", "#9a6700", "event"}};
    Nanos right = m.window->end;
    if (m.upper) {
      const Nanos limit = m.window->begin + Nanos{static_cast<std::int64_t>(*m.upper * 1e6)};
      marks.push_back({limit, "limit", "#cf222e", "limit"});
      right = std::max(right, limit);
    }
    if (m.at) marks.push_back({*m.at, "standstill", outcome_colour(measurement_judgement(c, m)), "event"});
    const Nanos span = std::max(right - m.window->begin, Nanos{1'000'000});
    s += figure(
        motion_figure(run.motion, marks, m.window->begin - span / 4, right + span / 4, m.window->begin),
        fmt::format("{}: speed and position around the stop; applied, standstill and the limit "
                    "(applied + {})",
                    xml_escape(m.name), m.upper ? format_value(*m.upper, m.unit) : "no limit"));
  }
  return s;
}

std::string throughput_figures(const CheckResult& c) {
  std::string s;
  for (const auto& series : c.series) {
    std::vector<LimitLine> limits;
    for (const auto& m : c.measurements) {
      if (m.unit != series.unit) continue;
      for (const auto& l : {m.lower, m.upper})
        if (l)
          limits.push_back({m.name.substr(c.check.size() + (m.name.starts_with(c.check + ".") ? 1 : 0)), *l});
    }
    s += figure(
        histogram_figure(series.values, series.unit, limits),
        fmt::format("{} of {}: histogram, dashed: the limits", xml_escape(series.name), xml_escape(c.check)));
  }
  return s;
}

std::string debounce_figures(const CheckResult& c) {
  std::optional<double> lo, hi;
  for (const auto& m : c.measurements) {
    if (m.unit == "us" && m.lower && m.upper) {
      lo = *m.lower * 1e3;
      hi = *m.upper * 1e3;
      break;
    }
  }
  return figure(
      probes_figure(c.probes, lo, hi),
      "every probe pulse by width, numbered in the order played: accepted above, rejected below; shaded: "
      "the filter time ± its tolerance");
}

std::string check_figures(const CheckResult& c, const RunResult& run) {
  std::string s;
  // A brake's window is the stop it measured, drawn on the motion: no edge diagram besides.
  const bool on_motion = c.kind == "brake_stop_time" && !run.motion.empty();
  if (on_motion) s += brake_figures(c, run);
  if (!c.series.empty()) s += throughput_figures(c);
  if (!c.probes.empty()) s += debounce_figures(c);
  const auto rows = failing_first(c);
  if (!on_motion) {
    for (const Measurement* m : timing_figures(c)) {
      const WindowTrace* trace = trace_for(c, *m);
      s += figure(timing_figure(as_drawn(c, *m), measurement_judgement(c, *m), trace, expected_rate(c),
                                c.expected_rate),
                  fmt::format("{}: {}the expected window (shaded, limits dashed) and the captured edge",
                              xml_escape(m->name),
                              trace ? "the stimulus, the shaft's count and the output as captured; " : ""));
    }
  }
  const std::span<const ShownMeasurement> gauge(rows.data(), std::min(rows.size(), kLimitRows));
  s += figure(limits_figure(gauge),
              rows.size() > kLimitRows
                  ? fmt::format("the first {} of {} measurements (those not passing first) "
                                "against their limits; the rest are in the table",
                                kLimitRows, rows.size())
                  : std::string("each measurement against its limits (shaded: passes)"));
  if (s.empty()) {
    const std::string why = c.measurements.empty()
                                ? "the check measured nothing: it judged nothing (an error)"
                                : "no measurement of this check has a limit or a window";
    // Nothing to draw: the reason, where the figure would be.
    s = fmt::format("<figure class=\"evidence note\"><p style=\"color:{}\">{}</p></figure>\n",
                    outcome_colour(c.judgement), why);
  }
  return s;
}

std::string check_section(const RunResult& run, const CheckResult& c, std::size_t i) {
  std::string s = fmt::format(
      "<section class=\"check\" id=\"{}\" data-judgement=\"{}\">\n<h4>{} <small>({})</small> "
      "{}</h4>\n",
      anchor(run, i), to_string(c.judgement), xml_escape(c.check), xml_escape(c.kind), badge(c.judgement));
  s += check_figures(c, run);
  s += "<table><tr><th>measurement</th><th>value</th><th>lower</th><th>upper</th><th>outcome</th>"
       "<th>window</th><th>detail</th></tr>\n";
  for (const auto& m : c.measurements) {
    const std::string window =
        m.window
            ? fmt::format("{} .. {}", format_time(m.window->begin),
                          m.window->end == Nanos::max() ? std::string("open") : format_time(m.window->end))
            : "&#8212;";
    s += fmt::format("<tr><td>{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td>"
                     "<td class=\"num\">{}</td><td>{}</td><td>{}</td><td>{}</td></tr>\n",
                     xml_escape(m.name),
                     xml_escape(format_value(m.value, m.unit, limit_beyond(m.value, m.lower, m.upper))),
                     limit_cell(m.lower, m.unit), limit_cell(m.upper, m.unit),
                     badge(measurement_judgement(c, m)), window, xml_escape(m.detail));
  }
  return s + "</table>\n</section>\n";
}

// Which runs kept a trace file, in the reader's words (hilrig run --trace).
std::string trace_policy_text(TracePolicy policy) {
  switch (policy) {
  case TracePolicy::All:
    return "all: the first run's and each run's that did not pass (--trace all)";
  case TracePolicy::Failed:
    return "failed: each run's that did not pass (--trace failed)";
  case TracePolicy::None:
    return "none (--trace none)";
  }
  return to_string(policy);
}

std::string traceability(const CampaignResult& r) {
  const auto row = [](const char* name, const std::string& value) {
    return fmt::format("<tr><th>{}</th><td>{}</td></tr>", name, xml_escape(value));
  };
  const auto given = [](const std::string& v) { return v.empty() ? std::string("not given") : v; };
  std::string s = "<table class=\"trace\">";
  // The start time is the one wall-clock fact (the row's class says so): the rest is the same
  // bytes for the same campaign, seed, shard and command line. The host is in results.json's
  // wall_clock and junit.xml.
  if (r.started_at)
    s += fmt::format("<tr class=\"wall-clock\"><th>started</th><td>{}</td></tr>", xml_escape(*r.started_at));
  s += row("tool version", "hilrig " + r.tool_version);
  s += row("campaign file", r.campaign_file);
  s += row("campaign SHA-256", r.campaign_sha256);
  s += row("device", r.device);
  s += row("DUT serial", given(r.dut_serial));
  s += row("station", given(r.station));
  s += row("seed", std::to_string(r.seed));
  s += row("shard", fmt::format("{} of {}", r.shard.index + 1, r.shard.count));
  s += row("backend", r.backend);
  s += row("host link", r.host_link);
  s += row("traces kept", trace_policy_text(r.trace_policy));
  return s + "</table>\n";
}

// Which runs get a full section: a report of 10,000 runs is read for its failures, so the first
// kDetailedNotPassing runs that did not pass and the first kDetailedPassing that did are shown
// in full (the latter as examples of a good run); every other run is one row of a table. Each
// pass over the runs makes the same choice: the choice depends on the runs before only.
constexpr std::size_t kDetailedNotPassing = 100;
constexpr std::size_t kDetailedPassing = 20;
// Entries per summary list; the rest are counted ("and N more").
constexpr std::size_t kListed = 100;

class DetailChoice {
public:
  bool detailed(const RunResult& run) {
    std::size_t& shown = run.outcome == Outcome::Pass ? passing_ : not_passing_;
    const std::size_t cap = run.outcome == Outcome::Pass ? kDetailedPassing : kDetailedNotPassing;
    if (shown == cap) return false;
    ++shown;
    return true;
  }

private:
  std::size_t passing_ = 0, not_passing_ = 0;
};

// A summary list holding its first kListed entries and counting the rest.
struct Listed {
  std::string items;
  std::size_t count = 0;
  void add(const std::string& item) {
    if (count++ < kListed) items += item;
  }
  [[nodiscard]] std::string text(const char* more) const {
    return count > kListed ? items + fmt::format("<li>and {} more {}</li>\n", count - kListed, more) : items;
  }
};

// Failures first: every check that failed or erred (and every run a rig error stopped), linked;
// then the checks that caught their fault.
std::string summary(const CampaignResult& r, const RunSource& runs) {
  Listed bad, caught_list;
  DetailChoice choice;
  runs([&](const RunResult& run) {
    // A run without a full section has its row in the table: the link goes there.
    const bool detailed = choice.detailed(run);
    if (!run.error.empty())
      bad.add(fmt::format("<li><a href=\"#r{}\">run {}: {}</a> {}: {}</li>\n", run.index, run.index,
                          xml_escape(run.name), badge(Judgement::Error), xml_escape(run.error)));
    for (std::size_t i = 0; i < run.checks.size(); ++i) {
      const CheckResult& c = run.checks[i];
      if (c.judgement != Judgement::Fail && c.judgement != Judgement::Error &&
          c.judgement != Judgement::Caught)
        continue;
      const std::string item =
          fmt::format("<li><a href=\"#{}\">run {}: {} / {}</a> ({}) {}</li>\n",
                      detailed ? anchor(run, i) : fmt::format("r{}", run.index), run.index,
                      xml_escape(run.name), xml_escape(c.check), xml_escape(c.kind), badge(c.judgement));
      (c.judgement == Judgement::Caught ? caught_list : bad).add(item);
    }
  });
  std::string not_caught;
  for (const auto& f : r.faults)
    if (!f.caught())
      not_caught += fmt::format("<li>fault <b>{}</b> <span class=\"fail\">not caught</span></li>\n",
                                xml_escape(f.fault));
  std::string s = "<h2 id=\"summary\">Summary</h2>\n";
  const std::string bad_text =
      bad.text("failed or errored checks: see the runs below and results.json") + not_caught;
  s += bad_text.empty()
           ? "<p>No check failed or erred.</p>\n"
           : "<p>Failed and errored checks:</p>\n<ul class=\"summary failures\">\n" + bad_text + "</ul>\n";
  if (caught_list.count > 0)
    s += "<p>Faults caught by:</p>\n<ul class=\"summary caught\">\n" +
         caught_list.text("checks that caught their fault: see results.json") + "</ul>\n";
  return s;
}

// One table row for a run without a full section: what a reader scans at 10,000 runs.
std::string run_row(const RunResult& run) {
  std::size_t by[5] = {0, 0, 0, 0, 0}; // pass, fail, caught, not judged, error
  for (const auto& c : run.checks) ++by[static_cast<std::size_t>(c.judgement)];
  return fmt::format(
      "<tr id=\"r{0}\"><td class=\"num\">{0}</td><td>{1}</td><td class=\"num\">{2}</td>"
      "<td>{3}</td><td>{4}</td><td class=\"num\">{5} / {6} / {7} / {8} / {9}</td><td>{10}</td></tr>\n",
      run.index, xml_escape(run.name), run.seed, run.fault.empty() ? "&#8212;" : xml_escape(run.fault),
      badge(run.outcome), by[0], by[1], by[2], by[3], by[4],
      run.trace.empty() ? std::string("&#8212;")
                        : fmt::format("<a href=\"{0}\">{0}</a>", xml_escape(run.trace)));
}

std::string run_section(const RunResult& run, TracePolicy policy) {
  // A run that passed is collapsed: the failures are what a reader opens the report for.
  std::string s = fmt::format(
      "<details class=\"run\" id=\"r{}\"{}>\n<summary>run {}: {} {}</summary>\n<p>seed {}{}{}</p>\n",
      run.index, run.outcome == Outcome::Pass ? "" : " open", run.index, xml_escape(run.name),
      badge(run.outcome), run.seed,
      run.fault.empty() ? std::string()
                        : fmt::format("; fault <b>{}</b> ({})", xml_escape(run.fault),
                                      caught(run) ? "caught" : "not caught"),
      run.error.empty() ? std::string() : fmt::format("; rig error: {}", xml_escape(run.error)));
  s += run.trace.empty() ? fmt::format("<p>trace: none kept for this run (traces kept: {})</p>\n",
                                       xml_escape(trace_policy_text(policy)))
                         : fmt::format("<p>trace: <a href=\"{0}\">{0}</a> (GTKWave, PulseView)</p>\n",
                                       xml_escape(run.trace));
  if (!run.motion.empty()) {
    s += figure(motion_figure(run.motion, {}),
                "the shaft's speed and position over the run, with the events that acted on it (grey)");
  }
  for (std::size_t i = 0; i < run.checks.size(); ++i) s += check_section(run, run.checks[i], i);
  if (!run.observations.empty()) {
    s += "<h4>observations</h4>\n<table><tr><th>name</th><th>value</th><th>time</th></tr>\n";
    for (const auto& o : run.observations) {
      s += fmt::format("<tr><td>{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td></tr>\n",
                       xml_escape(o.name), xml_escape(format_value(o.value, o.unit)), format_time(o.time));
    }
    s += "</table>\n";
  }
  return s + "</details>\n";
}

} // namespace

void write_report_html(const CampaignResult& r, const RunSource& runs, const TextSink& out) {
  const Totals& t = r.totals;
  std::string s = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  s += fmt::format("<title>hilrig: {}</title>\n<style>{}</style>\n{}</head>\n<body>\n",
                   xml_escape(r.campaign), kStyle, figure_styles());
  s += fmt::format("<h1>{}</h1>\n<p class=\"verdict\">Verdict: {}</p>\n", xml_escape(r.campaign),
                   badge(r.verdict));
  if (r.interrupted)
    s += fmt::format(
        "<p class=\"error\">Interrupted by {}: the runs done are below, the last one stopped early "
        "with every rig-driven line at its inactive level.</p>\n",
        xml_escape(*r.interrupted));
  else if (!r.complete) // killed and folded from its run log: say why the verdict is an error
    s += fmt::format("<p class=\"error\">Verdict error: {}.</p>\n", xml_escape(incomplete_reason(r)));
  s += summary(r, runs);
  s += traceability(r);
  s += fmt::format(
      "<table><tr><th>runs</th><td>{} of {} planned{}</td></tr>"
      "<tr><th>runs passed / failed / errored</th><td>{} / {} / {}</td></tr>"
      "<tr><th>checks passed / failed / caught / not judged / errored</th><td>{} / {} / {} / {} / "
      "{}</td></tr>"
      "<tr><th>faults caught</th><td>{} of {}</td></tr></table>\n",
      t.runs, r.planned_runs, r.complete ? "" : " (incomplete)", t.runs_passed, t.runs_failed, t.runs_errored,
      t.checks_passed, t.checks_failed, t.checks_caught, t.checks_not_judged, t.checks_errored,
      t.faults_caught, t.faults);
  if (!r.faults.empty()) {
    s += "<h2>Fault detection</h2>\n<table><tr><th>fault</th><th>must be caught by</th><th>runs</th>"
         "<th>caught in</th><th>caught?</th></tr>\n";
    for (const auto& f : r.faults) {
      std::string by;
      for (const auto& m : f.must_catch) by += (by.empty() ? "" : ", ") + xml_escape(m);
      s += fmt::format(
          "<tr><td>{}</td><td>{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td><td>{}</td></tr>\n",
          xml_escape(f.fault), by, f.runs.size(), f.caught_runs,
          f.caught() ? badge(Judgement::Caught) : std::string("<span class=\"fail\">not caught</span>"));
    }
    s += "</table>\n";
  }
  s += "<h2>Runs</h2>\n";
  out(s);
  std::size_t rows = 0;
  {
    DetailChoice choice;
    runs([&](const RunResult& run) {
      if (choice.detailed(run))
        out(run_section(run, r.trace_policy));
      else
        ++rows;
    });
  }
  if (rows > 0) {
    out(fmt::format("<h3 id=\"more-runs\">{} more runs</h3>\n<p>Shown in full above: the first {} runs that "
                    "did not pass and the first {} that passed. Every run's measurements are in results.json "
                    "and junit.xml.</p>\n<table class=\"runs\"><tr><th>run</th><th>name</th><th>seed</th>"
                    "<th>fault</th><th>outcome</th><th>checks passed / failed / caught / not judged / "
                    "errored</th><th>trace</th></tr>\n",
                    rows, kDetailedNotPassing, kDetailedPassing));
    DetailChoice choice;
    runs([&](const RunResult& run) {
      if (!choice.detailed(run)) out(run_row(run));
    });
    out("</table>\n");
  }
  out(figure_scripts());
  out("</body>\n</html>\n");
}

std::string to_report_html(const CampaignResult& r) {
  std::string text;
  write_report_html(r, runs_of(r), [&](std::string_view piece) { text += piece; });
  return text;
}

} // namespace hilrig::rig
