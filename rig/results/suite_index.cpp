#include "rig/results/suite_index.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "rig/results/xml_escape.hpp"

namespace hilrig::rig {
namespace {

constexpr const char* kStyle =
    "body{font-family:sans-serif;margin:1.5em;color:#1f2328}"
    "table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #d0d7de;padding:2px "
    "6px;text-align:left}"
    "th{background:#f6f8fa}.pass{color:#1a7f37;font-weight:bold}.fail{color:#cf222e;font-weight:bold}"
    ".error{color:#9a6700;font-weight:bold}td.num{text-align:right;font-variant-numeric:tabular-nums}";

const char* status_class(int status, std::optional<Outcome> verdict = std::nullopt) {
  return status == 0 ? "pass" : status == 1 && verdict != Outcome::Error ? "fail" : "error";
}

// The verdict a row's exit 1 stands for.
std::optional<Outcome> verdict_of(const SuiteRow& r) {
  return r.result ? std::optional<Outcome>(r.result->verdict) : std::nullopt;
}

} // namespace

const char* exit_words(int status, std::optional<Outcome> verdict) {
  switch (status) {
  case 0:
    return "passed";
  case 1:
    return verdict == Outcome::Error ? "a check could not be judged" : "a check failed";
  case 2:
    return "bad input";
  default:
    return "rig fault";
  }
}

std::string SuiteTally::text() const {
  return fmt::format("{} campaign(s), {} passed, {} with a failed check, {} with a check that could not be "
                     "judged, {} bad input, {} rig fault",
                     campaigns, passed, failed, not_judged, bad_input, rig_fault);
}

std::string SuiteTally::exit_text(int status) const {
  if (status != 1 || failed == 0 || not_judged == 0)
    return exit_words(status, status == 1 && failed == 0 && not_judged > 0 ? std::optional(Outcome::Error)
                                                                           : std::nullopt);
  return "a check failed, another could not be judged";
}

SuiteTally tally(const std::vector<SuiteRow>& rows) {
  SuiteTally t;
  t.campaigns = rows.size();
  for (const SuiteRow& r : rows) {
    switch (std::min(std::max(r.exit_status, 0), 3)) {
    case 0:
      ++t.passed;
      break;
    case 1:
      ++(verdict_of(r) == Outcome::Error ? t.not_judged : t.failed);
      break;
    case 2:
      ++t.bad_input;
      break;
    default:
      ++t.rig_fault;
    }
  }
  return t;
}

std::string to_suite_index_html(const std::string& title, const std::vector<SuiteRow>& rows,
                                int exit_status) {
  const SuiteTally t = tally(rows);
  std::string s = fmt::format("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>{}</title>"
                              "<style>{}</style></head><body>\n<h1>{}</h1>\n",
                              xml_escape(title), kStyle, xml_escape(title));
  const std::optional<Outcome> worst =
      t.failed == 0 && t.not_judged > 0 ? std::optional(Outcome::Error) : std::nullopt;
  s += fmt::format("<p>Suite: <span class=\"{}\">exit {} ({})</span>: {}</p>\n",
                   status_class(exit_status, worst), exit_status, t.exit_text(exit_status), t.text());
  // Failures first: the campaigns to look at, then the rest in suite order.
  s += "<table><tr><th>campaign</th><th>file</th><th>status</th><th>runs</th><th>passed</th><th>failed</th>"
       "<th>errored</th><th>faults caught</th><th>report</th></tr>\n";
  for (const bool failing : {true, false}) {
    for (const SuiteRow& r : rows) {
      if ((r.exit_status != 0) != failing) continue;
      const std::string name = r.result ? r.result->campaign : r.subdir;
      s += fmt::format("<tr><td>{}</td><td>{}</td><td class=\"{}\">{}</td>", xml_escape(name),
                       xml_escape(r.file), status_class(r.exit_status, verdict_of(r)),
                       exit_words(r.exit_status, verdict_of(r)));
      if (r.result) {
        const Totals& n = r.result->totals;
        s += fmt::format("<td class=\"num\">{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td>"
                         "<td class=\"num\">{}</td><td class=\"num\">{}/{}</td>"
                         "<td><a href=\"{}/report.html\">report</a></td></tr>\n",
                         n.runs, n.runs_passed, n.runs_failed, n.runs_errored, n.faults_caught, n.faults,
                         xml_escape(r.subdir));
      } else {
        s += fmt::format("<td colspan=\"6\">{}</td></tr>\n", xml_escape(r.message));
      }
    }
  }
  s += "</table>\n</body></html>\n";
  return s;
}

} // namespace hilrig::rig
