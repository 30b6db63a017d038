// report.html (issue 18, "Reports"): a figure for every judged check, failures first, times
// in their unit and no float noise, figures drawn from what the results recorded.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <regex>

#include <fmt/format.h>

#include "rig/results/number_format.hpp"
#include "rig/results/report_html.hpp"
#include "rig/results/results_json.hpp"
#include "rig/results/svg.hpp"
#include "sample_campaign.hpp"

namespace hilrig::rig {
namespace {

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

// The check sections of a report, each with its judgement word and body.
struct Section {
  std::string judgement, body;
};
// Found by hand, not with std::regex: libstdc++'s matcher recurses once per character of a
// lazy `[\s\S]*?`, which overflows the stack on a section of figures under ASan.
std::vector<Section> sections(const std::string& html) {
  std::vector<Section> out;
  const std::string open = "<section class=\"check\" id=\"";
  const std::string judgement = "\" data-judgement=\"";
  for (auto p = html.find(open); p != std::string::npos; p = html.find(open, p + 1)) {
    const auto j = html.find(judgement, p + open.size());
    const auto word_end = html.find("\">", j + judgement.size());
    const auto end = html.find("</section>", word_end);
    if (j == std::string::npos || word_end == std::string::npos || end == std::string::npos) break;
    out.push_back({html.substr(j + judgement.size(), word_end - j - judgement.size()),
                   html.substr(word_end + 2, end - word_end - 2)});
  }
  return out;
}

Measurement measured(const std::string& name, double value, std::optional<double> lo,
                     std::optional<double> hi, Outcome o) {
  Measurement m;
  m.name = name;
  m.value = value;
  m.unit = "counts";
  m.lower = lo;
  m.upper = hi;
  m.outcome = o;
  return m;
}

// Every x coordinate the markup draws at.
std::vector<double> xs(const std::string& svg) {
  std::vector<double> out;
  const std::regex re("\\b(?:x|x1|x2|cx)=\"(-?[0-9.]+)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), re); it != std::sregex_iterator(); ++it)
    out.push_back(std::stod((*it)[1]));
  return out;
}

// A long campaign's report (issue 19, "Runs: scale linearly"): the first 100 runs that did not
// pass and the first 20 that passed in full, every other run one row of a table, each summary
// list its first 100 entries and a count of the rest, and every link lands on an anchor.
// sample_campaign(400): runs i % 3 == 2 inject a fault their throughput check catches (133,
// pass); the nominal runs' throughput max is 10 + i us against 20 us, so the nominal runs
// 0, 1, 3, 4, 6, 7, 9, 10 pass (8) and the other 259 fail: 141 pass, 259 do not.
TEST(Report, LongCampaignShowsFailuresInFullAndTheRestAsRows) {
  const CampaignResult c = test::sample_campaign(400);
  ASSERT_EQ(c.totals.runs_passed, 141U);
  ASSERT_EQ(c.totals.runs_failed, 259U);
  const std::string html = to_report_html(c);
  EXPECT_EQ(count_of(html, "<details class=\"run\""), 120U);
  EXPECT_EQ(count_of(html, "<details class=\"run\" id=\"r") - count_of(html, " open>"),
            20U); // collapsed: passed
  EXPECT_EQ(count_of(html, "<tr id=\"r"), 280U);
  EXPECT_NE(html.find("<h3 id=\"more-runs\">280 more runs</h3>"), std::string::npos);
  // The failing run 10 + 100th: runs 11, 12, 13, 15, ... fail; the 100th of them is shown, the 101st is a
  // row.
  std::vector<std::uint64_t> failing;
  for (std::uint64_t i = 0; i < 400; ++i)
    if (i % 3 != 2 && i > 10) failing.push_back(i);
  EXPECT_NE(html.find(fmt::format("<details class=\"run\" id=\"r{}\" open>", failing[99])),
            std::string::npos);
  EXPECT_NE(html.find(fmt::format("<tr id=\"r{}\">", failing[100])), std::string::npos);
  EXPECT_NE(html.find("<li>and 159 more failed or errored checks"), std::string::npos);
  EXPECT_NE(html.find("<li>and 33 more checks that caught their fault"), std::string::npos);
  // The 20 passing runs in full are 0..11, 14, 17, ..., 35: run 38 is a row, and the summary's
  // "caught" entry for it links the row.
  EXPECT_NE(html.find("<details class=\"run\" id=\"r35\">"), std::string::npos);
  EXPECT_NE(html.find("<tr id=\"r38\">"), std::string::npos);
  EXPECT_NE(html.find("<a href=\"#r38\">run 38:"), std::string::npos);
  for (auto p = html.find("href=\"#"); p != std::string::npos; p = html.find("href=\"#", p + 1)) {
    const std::string target = html.substr(p + 7, html.find('"', p + 7) - p - 7);
    EXPECT_NE(html.find("id=\"" + target + "\""), std::string::npos) << target;
  }
}

TEST(Report, SelfContainedWithAFigureForEveryCheck) {
  const CampaignResult c = test::sample_campaign(3);
  const std::string html = to_report_html(c);
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0U);
  EXPECT_NE(html.find("Verdict: <span class=\"pass\">pass</span>"), std::string::npos);
  const auto secs = sections(html);
  ASSERT_EQ(secs.size(), 6U); // 3 runs x (throughput, advance)
  for (const auto& s : secs)
    EXPECT_NE(s.body.find("<figure class=\"evidence\"><svg"), std::string::npos) << s.body;
  EXPECT_EQ(count_of(html, "histogram of "), 3U);
  EXPECT_NE(html.find("Fault detection"), std::string::npos);
  // Nothing fetched from elsewhere; links stay inside the page.
  for (const char* external : {"src=", "<link", "<script", "@import", "url(", "href=\"h", "href=\"f"})
    EXPECT_EQ(html.find(external), std::string::npos) << external;
}

TEST(Report, FailuresFirstWithLinksAndPassingRunsCollapsed) {
  CampaignResult c = test::sample_campaign(2);
  c.runs[1] = test::nominal_run(1, 25.0); // over the 20 us limit
  finalize(c);
  ASSERT_EQ(c.verdict, Outcome::Fail);
  const std::string html = to_report_html(c);
  const auto summary = html.find("<ul class=\"summary failures\">");
  ASSERT_NE(summary, std::string::npos);
  EXPECT_LT(summary, html.find("<h2>Runs</h2>"));
  // The link points at the failed check's section, which exists.
  EXPECT_NE(html.find("<a href=\"#r1-c0\">", summary), std::string::npos);
  EXPECT_NE(html.find("<section class=\"check\" id=\"r1-c0\" data-judgement=\"fail\">"), std::string::npos);
  EXPECT_NE(html.find("<details class=\"run\" id=\"r0\">"), std::string::npos);      // passed: collapsed
  EXPECT_NE(html.find("<details class=\"run\" id=\"r1\" open>"), std::string::npos); // failed: open
}

TEST(Report, EachRunLinksItsTraceFile) {
  CampaignResult c = test::sample_campaign(2);
  c.runs[0].trace = "trace.vcd";
  finalize(c);
  const std::string html = to_report_html(c);
  EXPECT_NE(html.find("trace: <a href=\"trace.vcd\">trace.vcd</a>"), std::string::npos);
  EXPECT_NE(html.find("trace: none kept for this run"), std::string::npos); // run 1 kept none
  // results.json keeps the name, so a merged or re-rendered report links it too.
  EXPECT_EQ(campaign_from_json(to_json(c)).runs[0].trace, "trace.vcd");
}

TEST(Report, CheckThatMeasuredNothingStillHasAFigureSayingSo) {
  CampaignResult c = test::sample_campaign(1);
  CheckResult empty;
  empty.check = "empty";
  empty.kind = "pulse_width";
  c.runs[0].checks.push_back(empty);
  finalize(c);
  const auto secs = sections(to_report_html(c));
  ASSERT_EQ(secs.size(), 3U);
  EXPECT_EQ(secs[2].judgement, "error");
  EXPECT_NE(secs[2].body.find("the check measured nothing"), std::string::npos);
}

TEST(NumberFormat, NoFloatNoiseAndTimesInTheirUnit) {
  EXPECT_EQ(format_number(800.0000000000018), "800");
  EXPECT_EQ(format_number(94.00686600000006), "94.006866");
  EXPECT_EQ(format_number(-0.0), "0");
  EXPECT_EQ(format_ns(1'500'000.0), "1.5 ms");
  EXPECT_EQ(format_ns(750'000.0), "750 µs");
  EXPECT_EQ(format_ns(999.0), "999 ns");
  EXPECT_EQ(format_ns(2e9), "2 s");
  EXPECT_EQ(format_value(100.0, "us"), "100 µs");
  EXPECT_EQ(format_value(3.0, ""), "3");
}

TEST(Svg, TimingDiagramWithAndWithoutTheEdge) {
  Measurement m = measured("a.edge0", 94.0, 93.0, 95.0, Outcome::Pass);
  m.window = TraceWindow{Nanos{1'000'000}, Nanos{1'002'000}};
  m.at = Nanos{1'001'000};
  ASSERT_TRUE(has_timing(m));
  const std::string with = timing_diagram_svg(m, Judgement::Pass);
  EXPECT_NE(with.find("edge 1.001 ms"), std::string::npos) << with;
  // A position tolerance crossed in time: the window itself is the expected one, both limits.
  EXPECT_NE(with.find("expected 93 counts .. 95 counts"), std::string::npos) << with;
  EXPECT_EQ(count_of(with, "class=\"limit\""), 2U) << with;
  // A missing edge: the window is drawn and says so, in the word's colour.
  m.at.reset();
  m.outcome = Outcome::Fail;
  ASSERT_TRUE(has_timing(m));
  const std::string missing = timing_diagram_svg(m, Judgement::Fail);
  EXPECT_NE(missing.find("no edge captured"), std::string::npos);
  EXPECT_NE(missing.find("stroke=\"#cf222e\" stroke-width=\"1.5\""), std::string::npos);
  // A passing window-only measurement (a handshake's write to Acknowledge) is no edge diagram.
  m.outcome = Outcome::Pass;
  EXPECT_FALSE(has_timing(m));
  // An open window (waited to the end of the trace) stays on the canvas.
  m.outcome = Outcome::Fail;
  m.window->end = Nanos::max();
  for (const double x : xs(timing_diagram_svg(m, Judgement::Fail))) EXPECT_LE(x, 600.0);
}

// A latency (throughput.max, limit 20 us from the crossing) that came 1 us late: the diagram
// draws the lanes the run captured, in their order, the expected window [crossing, crossing
// + 20 us] shaded with the limit dashed at crossing + 20 us, and the count at the edge.
TEST(Svg, TimingDiagramDrawsTheCapturedLanesAndMarksTheLimit) {
  Measurement m = measured("on.max", 21.0, std::nullopt, 20.0, Outcome::Fail);
  m.unit = "us";
  m.window = TraceWindow{Nanos{1'000'000}, Nanos{1'021'000}};
  m.at = Nanos{1'021'000};
  const auto want = expected_window(m);
  ASSERT_TRUE(want.has_value());
  EXPECT_EQ(want->begin, Nanos{1'000'000});
  EXPECT_EQ(want->end, Nanos{1'020'000});
  // The figure spans the window and the limit with a fifth of their 21 us either side.
  const TraceWindow span = figure_span(m);
  EXPECT_EQ(span.begin, Nanos{1'000'000 - 4'200});
  EXPECT_EQ(span.end, Nanos{1'021'000 + 4'200});
  WindowTrace w{*m.window, span, {}};
  w.lanes.push_back({"enc.A", LaneRole::Stimulus, {{span.begin, 0}, {Nanos{999'999}, 1}}, 0});
  w.lanes.push_back({"shaft.count", LaneRole::Count, {{span.begin, 99}, {Nanos{999'999}, 100}}, 0});
  w.lanes.push_back({"ls1", LaneRole::Output, {{span.begin, 0}, {Nanos{1'021'000}, 1}}, 0});
  const std::string svg = timing_diagram_svg(m, Judgement::Fail, &w);
  const auto a = svg.find("data-lane=\"enc.A\""), c = svg.find("data-lane=\"shaft.count\""),
             o = svg.find("data-lane=\"ls1\"");
  ASSERT_NE(a, std::string::npos) << svg;
  ASSERT_NE(c, std::string::npos);
  ASSERT_NE(o, std::string::npos);
  EXPECT_LT(a, c);
  EXPECT_LT(c, o);
  EXPECT_NE(svg.find("class=\"lane stimulus\""), std::string::npos);
  EXPECT_NE(svg.find("limit: start + 20 µs"), std::string::npos) << svg;
  EXPECT_NE(svg.find("count 100 at the edge"), std::string::npos) << svg;
  // x of crossing + 20 us on the 70..580 px plot of [995.8, 1025.2] us: 70 + 24.2/29.4 * 510.
  const double limit_x = 70.0 + 24.2 / 29.4 * 510.0;
  EXPECT_NE(svg.find(fmt::format("class=\"limit\" x1=\"{:.1f}\"", limit_x)), std::string::npos) << svg;
  EXPECT_EQ(count_of(svg, "class=\"limit\""), 1U); // no lower limit: the start is no limit
  EXPECT_NE(svg.find(fmt::format("class=\"expected\" x=\"{:.1f}\"", 70.0 + 4.2 / 29.4 * 510.0)),
            std::string::npos);
  for (const double x : xs(svg)) EXPECT_LE(x, 600.0);
  // A time without a limit (the median) has no expected window: nothing shaded.
  m.upper.reset();
  EXPECT_FALSE(expected_window(m).has_value());
  const std::string median = timing_diagram_svg(m, Judgement::Pass, &w);
  EXPECT_EQ(median.find("class=\"expected\""), std::string::npos);
  EXPECT_NE(median.find("no limit: reported only"), std::string::npos);
}

// Diagrams go to the windows that did not pass, then to those with a limit, one per window.
TEST(Svg, TimingFiguresFailuresFirstThenLimitedOnePerWindow) {
  CheckResult c;
  const auto latency = [](const char* name, std::optional<double> upper, Outcome o, std::int64_t end) {
    Measurement m = measured(name, 1.0, std::nullopt, upper, o);
    m.unit = "us";
    m.window = TraceWindow{Nanos{1000}, Nanos{end}};
    m.at = Nanos{end};
    return m;
  };
  c.measurements = {latency("min", std::nullopt, Outcome::Pass, 2000),
                    latency("p99", 20.0, Outcome::Pass, 3000), latency("max", 20.0, Outcome::Fail, 3000),
                    latency("other", 20.0, Outcome::Pass, 4000)};
  const auto drawn = timing_figures(c);
  ASSERT_EQ(drawn.size(), 3U);
  EXPECT_EQ(drawn[0]->name, "max");   // failed
  EXPECT_EQ(drawn[1]->name, "other"); // limited (p99 is max's window)
  EXPECT_EQ(drawn[2]->name, "min");
}

TEST(Svg, HistogramKeepsEveryLimitOnTheCanvasAndHasEnoughBins) {
  // Values 1..4 us, limits far beyond (100 us) and below (-50 us): both on the 600 px canvas.
  const std::vector<double> v{1.0, 2.0, 3.0, 4.0};
  const std::vector<LimitLine> limits{{"max", 100.0}, {"min", -50.0}};
  const std::string svg = histogram_svg(v, "us", limits);
  for (const double x : xs(svg)) {
    EXPECT_GE(x, 0.0);
    EXPECT_LE(x, 600.0);
  }
  EXPECT_NE(svg.find("max limit 100 µs"), std::string::npos);
  // At least 10 bins whatever the sample count: 4 values in bins of (4 - 1) / 10 = 0.3 us.
  EXPECT_NE(svg.find("4 samples in 10 bins of 0.3 µs"), std::string::npos) << svg;
  EXPECT_EQ(count_of(svg, "<rect "), 4U);
  EXPECT_NE(svg.find(">count<"), std::string::npos); // the y axis
}

TEST(Svg, LimitsRowPerLimitedMeasurement) {
  const Measurement a = measured("a", 96.0, 93.0, 95.0, Outcome::Fail);
  const Measurement b = measured("b", 2.0, 1.0, std::nullopt, Outcome::Pass);
  const Measurement c = measured("c", 7.0, std::nullopt, std::nullopt, Outcome::Pass);
  const std::vector<ShownMeasurement> rows{
      {&a, Judgement::Fail}, {&b, Judgement::Pass}, {&c, Judgement::Pass}};
  const std::string svg = limits_svg(rows);
  EXPECT_EQ(count_of(svg, "<circle "), 2U); // c has no limit: no row
  EXPECT_NE(svg.find("fill=\"#cf222e\">96 counts</text>"), std::string::npos) << svg;
  for (const double x : xs(svg)) EXPECT_LE(x, 600.0);
}

TEST(Svg, ProbesOnePointEachAgainstTheBand) {
  const std::vector<Probe> probes{{Nanos{20'000}, false}, {Nanos{40'000}, true}, {Nanos{30'000}, true}};
  const std::string svg = probes_svg(probes, 26'500.0, 28'500.0);
  EXPECT_EQ(count_of(svg, "<circle "), 3U);
  EXPECT_NE(svg.find("probe 1: 20 µs rejected"), std::string::npos);
  EXPECT_NE(svg.find("filter band"), std::string::npos);
}

TEST(Svg, MotionPlotsSpeedAndPositionWithEventsAndMarkers) {
  MotionRecord m;
  // Constant deceleration from 1000 counts/s to rest over 100 ms: 50 counts.
  for (int i = 0; i <= 10; ++i) {
    const double t = 0.01 * i;
    m.points.push_back(
        {Nanos{static_cast<std::int64_t>(t * 1e9)}, 1000.0 * t - 5000.0 * t * t, 1000.0 - 10000.0 * t});
  }
  m.events.push_back({Nanos{0}, "valve off: brake applied, clutch released"});
  const std::vector<Marker> marks{{Nanos{100'000'000}, "standstill", "#1a7f37"}};
  const std::string svg = motion_svg(m, marks);
  EXPECT_EQ(count_of(svg, "<polyline "), 2U);
  EXPECT_NE(svg.find("valve off: brake applied, clutch released 0 ns"), std::string::npos);
  EXPECT_NE(svg.find("standstill 100 ms"), std::string::npos);
  EXPECT_TRUE(motion_svg(MotionRecord{}, marks).empty());
}

} // namespace
} // namespace hilrig::rig
