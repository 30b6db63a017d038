#include "rig/results/report_html.hpp"

#include <fmt/format.h>

#include "rig/results/svg.hpp"
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
    "figcaption{font-size:.85em;color:#57606a}td.num{text-align:right;font-variant-numeric:tabular-nums}";

std::string badge_of(const char* word) {
  const std::string cls = std::string(word) == "not judged" ? "not-judged" : word;
  return fmt::format("<span class=\"{}\">{}</span>", cls, word);
}
std::string badge(Outcome o) { return badge_of(to_string(o)); }
std::string badge(Judgement j) { return badge_of(to_string(j)); }

// A measurement shown in its check's word: in a fault run a failing measurement of the check
// that caught the fault is "caught", any of a check not judged "not judged", never "fail".
Judgement shown(const CheckResult& c, const Measurement& m) {
  if (c.judgement == Judgement::Caught || c.judgement == Judgement::NotJudged)
    return m.outcome == Outcome::Pass ? Judgement::Pass : c.judgement;
  return m.outcome == Outcome::Pass   ? Judgement::Pass
         : m.outcome == Outcome::Fail ? Judgement::Fail
                                      : Judgement::Error;
}

std::string limit_cell(const std::optional<double>& v) { return v ? fmt::format("{}", *v) : "&#8212;"; }

std::string check_section(const CheckResult& c) {
  std::string s = fmt::format("<h4>{} <small>({})</small> {}</h4>\n", xml_escape(c.check), xml_escape(c.kind),
                              badge(c.judgement));
  s +=
      "<table><tr><th>measurement</th><th>value</th><th>unit</th><th>lower</th><th>upper</th><th>outcome</th>"
      "<th>detail</th></tr>\n";
  for (const auto& m : c.measurements) {
    s += fmt::format("<tr><td>{}</td><td class=\"num\">{}</td><td>{}</td><td class=\"num\">{}</td>"
                     "<td class=\"num\">{}</td><td>{}</td><td>{}</td></tr>\n",
                     xml_escape(m.name), m.value, xml_escape(m.unit), limit_cell(m.lower),
                     limit_cell(m.upper), badge(shown(c, m)), xml_escape(m.detail));
  }
  s += "</table>\n";
  if (c.kind == "advance_counts" || c.kind == "edge_at_position") {
    for (const auto& m : c.measurements) {
      const std::string svg = timing_diagram_svg(m, shown(c, m));
      if (svg.empty()) continue;
      s += fmt::format(
          "<figure>{}<figcaption>{}: expected window (green) against captured edge</figcaption></figure>\n",
          svg, xml_escape(m.name));
    }
  }
  if (c.kind == "throughput") {
    std::optional<double> limit;
    for (const auto& m : c.measurements) {
      if (m.name.ends_with(".max")) limit = m.upper;
    }
    for (const auto& series : c.series) {
      const std::string svg = histogram_svg(series.values, series.unit, limit);
      if (svg.empty()) continue;
      s +=
          fmt::format("<figure>{}<figcaption>{} histogram ({}), dashed: limit on max</figcaption></figure>\n",
                      svg, xml_escape(series.name), xml_escape(series.unit));
    }
  }
  return s;
}

} // namespace

std::string to_report_html(const CampaignResult& r) {
  const Totals& t = r.totals;
  std::string s = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  s += fmt::format("<title>hilrig: {}</title>\n<style>{}</style>\n</head>\n<body>\n", xml_escape(r.campaign),
                   kStyle);
  s += fmt::format("<h1>{}</h1>\n<p class=\"verdict\">Verdict: {}</p>\n", xml_escape(r.campaign),
                   badge(r.verdict));
  if (r.interrupted)
    s += fmt::format(
        "<p class=\"error\">Interrupted by {}: the runs done are below, the last one stopped early "
        "with every rig-driven line at its inactive level.</p>\n",
        xml_escape(*r.interrupted));
  s += fmt::format(
      "<table><tr><th>device</th><td>{}</td></tr><tr><th>seed</th><td>{}</td></tr>"
      "<tr><th>shard</th><td>{} of {}</td></tr><tr><th>runs</th><td>{} of {} planned{}</td></tr>"
      "<tr><th>runs passed / failed / errored</th><td>{} / {} / {}</td></tr>"
      "<tr><th>checks passed / failed / caught / not judged / errored</th><td>{} / {} / {} / {} / "
      "{}</td></tr>"
      "<tr><th>faults caught</th><td>{} of {}</td></tr></table>\n",
      xml_escape(r.device), r.seed, r.shard.index + 1, r.shard.count, t.runs, r.planned_runs,
      r.complete ? "" : " (incomplete)", t.runs_passed, t.runs_failed, t.runs_errored, t.checks_passed,
      t.checks_failed, t.checks_caught, t.checks_not_judged, t.checks_errored, t.faults_caught, t.faults);
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
  for (const auto& run : r.runs) {
    s += fmt::format("<section>\n<h3>run {}: {} {}</h3>\n<p>seed {}{}{}</p>\n", run.index,
                     xml_escape(run.name), badge(run.outcome), run.seed,
                     run.fault.empty() ? std::string()
                                       : fmt::format("; fault <b>{}</b> ({})", xml_escape(run.fault),
                                                     caught(run) ? "caught" : "not caught"),
                     run.error.empty() ? std::string()
                                       : fmt::format("; rig error: {}", xml_escape(run.error)));
    for (const auto& c : run.checks) s += check_section(c);
    if (!run.observations.empty()) {
      s += "<h4>observations</h4>\n<table><tr><th>name</th><th>value</th><th>unit</th><th>time "
           "(us)</th></tr>\n";
      for (const auto& o : run.observations) {
        s += fmt::format(
            "<tr><td>{}</td><td class=\"num\">{}</td><td>{}</td><td class=\"num\">{:.3f}</td></tr>\n",
            xml_escape(o.name), o.value, xml_escape(o.unit), static_cast<double>(o.time.count()) / 1e3);
      }
      s += "</table>\n";
    }
    s += "</section>\n";
  }
  s += "</body>\n</html>\n";
  return s;
}

} // namespace hilrig::rig
