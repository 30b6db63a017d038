#include "rig/power/power_report.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "rig/results/number_format.hpp"
#include "rig/results/xml_escape.hpp"

namespace hilrig::power {
namespace {

nlohmann::json optional_number(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

// `beside`: the number it must not be confused with (its limit, the last passing knob value).
std::string with_unit(const std::optional<double>& v, const std::string& unit,
                      const std::optional<double>& beside = std::nullopt) {
  if (!v) return "-";
  const std::string number = rig::format_number_apart(*v, beside);
  return unit.empty() ? number : fmt::format("{} {}", number, unit);
}

// 4 significant digits: a margin of 4.8e-06 % is beyond the limit, never "0.0000 %".
std::string percent(const std::optional<double>& pct) { return pct ? fmt::format("{:.4g} %", *pct) : "-"; }

std::string margin_text(const PowerRow& r) { return percent(r.margin_pct); }

// The check's name, with the side for one of the two rows of a two-sided knob.
std::string check_text(const PowerRow& r) {
  return r.two_sided ? r.check + " (" + r.direction + ")" : r.check;
}

// The HTML table's last column: why there is no threshold, what failed without a value, and
// an incomplete or unknown phase coverage.
std::string reason_text(const PowerRow& r) {
  std::string text = r.reason.empty() && !r.margin_pct ? r.detail : r.reason;
  if (!r.phase_coverage.empty() && !r.phase_coverage_complete)
    text += (text.empty() ? "" : "; ") + r.phase_coverage;
  return text;
}

} // namespace

std::string to_power_json(const PowerResult& result) {
  nlohmann::json doc;
  doc["format"] = "hilrig-power";
  doc["version"] = kPowerFormatVersion;
  doc["campaign"] = result.campaign;
  doc["device"] = result.device;
  doc["seed"] = result.seed;
  doc["checks"] = nlohmann::json::array();
  for (const PowerRow& r : result.rows) {
    nlohmann::json j;
    j["check"] = r.check;
    j["kind"] = r.kind;
    j["knob"] = r.knob.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.knob);
    j["knob_unit"] = r.knob_unit;
    j["direction"] = r.direction;
    j["two_sided"] = r.two_sided;
    j["nominal"] = optional_number(r.nominal);
    j["threshold"] = optional_number(r.threshold);
    j["last_pass"] = optional_number(r.last_pass);
    j["probes"] = r.probes;
    j["measurement"] = r.measurement;
    j["measured"] = optional_number(r.measured);
    j["limit"] = optional_number(r.limit);
    j["unit"] = r.unit;
    j["margin_pct"] = optional_number(r.margin_pct);
    j["board_worst"] = optional_number(r.board_worst);
    j["board_margin_pct"] = optional_number(r.board_margin_pct);
    j["phase_coverage"] =
        r.phase_coverage.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.phase_coverage);
    j["phase_coverage_complete"] = r.phase_coverage_complete;
    j["detail"] = r.detail;
    j["reason"] = r.reason.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.reason);
    doc["checks"].push_back(std::move(j));
  }
  return doc.dump(2) + "\n";
}

std::string to_power_text(const PowerResult& result) {
  std::string out =
      fmt::format("detection power: {} ({}), seed {}\n", result.campaign, result.device, result.seed);
  out +=
      fmt::format("{:<20} {:<17} {:<15} {:>12} {:>14} {:>14} {:>12} {:>10} {:>14} {:>10}\n", "check", "kind",
                  "knob", "nominal", "threshold", "measured", "limit", "margin", "board worst", "margin");
  for (const PowerRow& r : result.rows) {
    if (r.threshold) {
      out += fmt::format("{:<20} {:<17} {:<15} {:>12} {:>14} {:>14} {:>12} {:>10} {:>14} {:>10}\n",
                         check_text(r), r.kind, r.knob, with_unit(r.nominal, r.knob_unit),
                         with_unit(r.threshold, r.knob_unit, r.last_pass),
                         with_unit(r.measured, r.unit, r.limit), with_unit(r.limit, r.unit), margin_text(r),
                         with_unit(r.board_worst, r.unit, r.limit), percent(r.board_margin_pct));
      if (!r.margin_pct)
        out += fmt::format("{:<20} fails without a value beyond a limit: {}\n", "", r.detail);
      if (!r.phase_coverage.empty() && !r.phase_coverage_complete)
        out += fmt::format("{:<20} {}\n", "", r.phase_coverage);
    } else {
      out += fmt::format("{:<20} {:<17} {}\n", check_text(r), r.kind, r.reason);
    }
  }
  return out;
}

std::string to_power_html(const PowerResult& result) {
  std::string out = "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>detection power: " +
                    rig::xml_escape(result.campaign) +
                    "</title>\n<style>body{font-family:sans-serif}table{border-collapse:collapse}"
                    "td,th{border:1px solid #ccc;padding:2px 6px;text-align:left}</style></head><body>\n";
  out += fmt::format("<h1>Detection power: {} ({}), seed {}</h1>\n", rig::xml_escape(result.campaign),
                     rig::xml_escape(result.device), result.seed);
  out +=
      "<p>For each check, the smallest deviation of the virtual board's knob at which the check fails, what "
      "the check measured there and how far beyond its spec limit; where the model states it, the board's "
      "own worst case at that deviation and its distance beyond the limit (docs/power.md).</p>\n";
  out += "<table id=\"power\"><tr><th>check</th><th>kind</th><th>knob</th><th>nominal</th><th>threshold</th>"
         "<th>measured</th><th>limit</th><th>margin</th><th>board worst case</th><th>board margin</th>"
         "<th>reason</th></tr>\n";
  for (const PowerRow& r : result.rows)
    out += fmt::format(
        "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td>"
        "<td>{}</td><td>{}</td><td>{}</td></tr>\n",
        rig::xml_escape(check_text(r)), rig::xml_escape(r.kind), rig::xml_escape(r.knob),
        rig::xml_escape(with_unit(r.nominal, r.knob_unit)),
        rig::xml_escape(with_unit(r.threshold, r.knob_unit, r.last_pass)),
        rig::xml_escape(with_unit(r.measured, r.unit, r.limit)), rig::xml_escape(with_unit(r.limit, r.unit)),
        rig::xml_escape(margin_text(r)), rig::xml_escape(with_unit(r.board_worst, r.unit, r.limit)),
        rig::xml_escape(percent(r.board_margin_pct)), rig::xml_escape(reason_text(r)));
  out += "</table>\n</body></html>\n";
  return out;
}

} // namespace hilrig::power
