#include "rig/results/suite_index.hpp"

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

// hilrig's exit status in words (rig/cli/exit_status.hpp).
const char* status_words(int status) {
  switch (status) {
  case 0:
    return "passed";
  case 1:
    return "a check failed";
  case 2:
    return "bad input";
  default:
    return "rig fault";
  }
}

const char* status_class(int status) { return status == 0 ? "pass" : status == 1 ? "fail" : "error"; }

} // namespace

std::string to_suite_index_html(const std::string& title, const std::vector<SuiteRow>& rows,
                                int exit_status) {
  std::size_t by_status[4] = {0, 0, 0, 0};
  for (const SuiteRow& r : rows) ++by_status[std::min(std::max(r.exit_status, 0), 3)];
  std::string s = fmt::format("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>{}</title>"
                              "<style>{}</style></head><body>\n<h1>{}</h1>\n",
                              xml_escape(title), kStyle, xml_escape(title));
  s += fmt::format("<p>Suite: <span class=\"{}\">exit {} ({})</span>: {} campaign(s), {} passed, {} with a "
                   "failed check, {} bad input, {} rig fault</p>\n",
                   status_class(exit_status), exit_status, status_words(exit_status), rows.size(),
                   by_status[0], by_status[1], by_status[2], by_status[3]);
  // Failures first: the campaigns to look at, then the rest in suite order.
  s += "<table><tr><th>campaign</th><th>file</th><th>status</th><th>runs</th><th>passed</th><th>failed</th>"
       "<th>errored</th><th>faults caught</th><th>report</th></tr>\n";
  for (const bool failing : {true, false}) {
    for (const SuiteRow& r : rows) {
      if ((r.exit_status != 0) != failing) continue;
      const std::string name = r.result ? r.result->campaign : r.subdir;
      s += fmt::format("<tr><td>{}</td><td>{}</td><td class=\"{}\">{}</td>", xml_escape(name),
                       xml_escape(r.file), status_class(r.exit_status), status_words(r.exit_status));
      if (r.result) {
        const Totals& t = r.result->totals;
        s += fmt::format("<td class=\"num\">{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td>"
                         "<td class=\"num\">{}</td><td class=\"num\">{}/{}</td>"
                         "<td><a href=\"{}/report.html\">report</a></td></tr>\n",
                         t.runs, t.runs_passed, t.runs_failed, t.runs_errored, t.faults_caught, t.faults,
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
