#include "rig/results/trend_html.hpp"

#include <map>
#include <optional>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "rig/results/figure_data.hpp"
#include "rig/results/figure_html.hpp"
#include "rig/results/xml_escape.hpp"

namespace hilrig::rig {

namespace {

struct MeasurementTrend {
  std::string run, name, unit;
  std::optional<double> lower, upper; // the last night's
  std::vector<TrendPoint> points;     // one per night
};

// A night in a message: its file and its label, or the label alone.
std::string where(const Night& n) {
  return n.file.empty() ? n.label : fmt::format("{} ({})", n.file, n.label);
}

} // namespace

std::string to_trend_html(std::span<const Night> nights) {
  if (nights.empty()) throw std::invalid_argument("no results to show");
  const CampaignResult& first = *nights.front().result;
  for (const Night& n : nights)
    if (n.result->campaign != first.campaign || n.result->device != first.device)
      throw std::invalid_argument(fmt::format(
          "{} is campaign \"{}\" on {}, {} is campaign \"{}\" on {}: a trend is one campaign on one device",
          where(nights.front()), first.campaign, first.device, where(n), n.result->campaign,
          n.result->device));
  // MeasurementTrend in the order they first appear, each with a point per night.
  std::vector<MeasurementTrend> series;
  std::map<std::pair<std::string, std::string>, std::size_t> index;
  for (std::size_t night = 0; night < nights.size(); ++night) {
    for (const RunResult& run : nights[night].result->runs)
      for (const CheckResult& check : run.checks)
        for (const Measurement& m : check.measurements) {
          const auto key = std::make_pair(run.name, m.name);
          auto it = index.find(key);
          if (it == index.end()) {
            it = index.emplace(key, series.size()).first;
            MeasurementTrend s{run.name, m.name, m.unit, {}, {}, {}};
            for (const Night& n : nights)
              s.points.push_back(TrendPoint{n.label, std::nullopt, Judgement::Error});
            series.push_back(std::move(s));
          }
          MeasurementTrend& s = series[it->second];
          s.points[night].value = m.value;
          s.points[night].word = measurement_judgement(check, m);
          s.lower = m.lower;
          s.upper = m.upper;
          s.unit = m.unit;
        }
  }
  std::string html =
      fmt::format("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>trend: {0}</title>"
                  "<style>body{{font-family:sans-serif;margin:1.5em}}table{{border-collapse:collapse}}"
                  "td,th{{border:1px solid #d0d7de;padding:2px 6px;text-align:left}}section{{margin:1em 0}}"
                  "</style>{3}</head><body>\n<h1>trend: {0} on {1}</h1>\n<p>{2} night(s), oldest first: ",
                  xml_escape(first.campaign), xml_escape(first.device), nights.size(), figure_styles());
  for (std::size_t i = 0; i < nights.size(); ++i)
    html += fmt::format("{}{} ({})", i == 0 ? "" : ", ", xml_escape(nights[i].label),
                        to_string(nights[i].result->verdict));
  html +=
      fmt::format(".</p>\n<p>{} measurement(s); each point is one night's value in the colour of the word it "
                  "read (a fault's evidence is blue caught, a check not judged grey), the dashed lines the "
                  "last night's limits.</p>\n",
                  series.size());
  for (const MeasurementTrend& s : series) {
    const auto limit = [](const std::optional<double>& v) {
      return v ? fmt::format("{}", *v) : std::string("-");
    };
    html += fmt::format(
        "<section><h3>{} <small>({})</small></h3><p>limits [{} .. {}] {}; values:", xml_escape(s.name),
        xml_escape(s.run), limit(s.lower), limit(s.upper), xml_escape(s.unit));
    for (const TrendPoint& p : s.points)
      html += p.value ? fmt::format(" {} ({})", *p.value, to_string(p.word)) : std::string(" -");
    html += "</p>\n" +
            figure_html(trend_figure(s.points, s.unit, s.lower, s.upper),
                        "each night's value (coloured by its word) and the last night's limits (dashed)") +
            "</section>\n";
  }
  html += figure_scripts() + "</body></html>\n";
  return html;
}

} // namespace hilrig::rig
