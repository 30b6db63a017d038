// report.html (issue 18, "Reports"): a figure for every judged check, failures first, times
// in their unit and no float noise, figures drawn from what the results recorded.
#include <gtest/gtest.h>

#include <map>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <fmt/format.h>

#include "rig/results/figure_data.hpp"
#include "rig/results/number_format.hpp"
#include "rig/results/report_assets.hpp"
#include "rig/results/report_html.hpp"
#include "rig/results/results_json.hpp"
#include "rig/results/timing_figures.hpp"
#include "sample_campaign.hpp"
#include "tests/tools/scratch_files.hpp"

namespace hilrig::rig {
namespace {

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
  EXPECT_EQ(hilrig::test::count_of(html, "<details class=\"run\""), 120U);
  EXPECT_EQ(hilrig::test::count_of(html, "<details class=\"run\" id=\"r") -
                hilrig::test::count_of(html, " open>"),
            20U); // collapsed: passed
  EXPECT_EQ(hilrig::test::count_of(html, "<tr id=\"r"), 280U);
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
    EXPECT_NE(s.body.find("<script type=\"application/json\" class=\"figure-data\">"), std::string::npos)
        << s.body;
  EXPECT_EQ(hilrig::test::count_of(html, "data-kind=\"histogram\""), 3U);
  EXPECT_NE(html.find("Fault detection"), std::string::npos);
  // uPlot and the script that draws the figures are in the page, once each.
  EXPECT_EQ(hilrig::test::count_of(html, std::string(report_assets::uplot_js())), 1U);
  EXPECT_EQ(hilrig::test::count_of(html, std::string(report_assets::figures_js())), 1U);
  // Nothing fetched from elsewhere; links stay inside the page.
  for (const char* external : {"src=", "<link", "@import", "href=\"h", "href=\"f", "fetch("})
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

// A value 1 ns beyond its limit reads beyond it in the measurement table: a stop time of
// 1000.000001 ms against a 1000 ms limit is 10 significant digits, which the table's 9 would
// print as "1000 ms" beside "1000 ms", a board failed at its limit to the reader. Far from a
// limit the 9 digits stay (no float noise).
TEST(Report, AValueJustBeyondItsLimitReadsBeyondIt) {
  CampaignResult c = test::sample_campaign(1);
  Measurement late = measured("brake.stop_time", 1000.000001, std::nullopt, 1000.0, Outcome::Fail);
  late.unit = "ms";
  Measurement short_of = measured("brake.shortest", 99.9999999999, 100.0, std::nullopt, Outcome::Fail);
  short_of.unit = "ms";
  Measurement noisy = measured("brake.count", 800.0000000000018, std::nullopt, 1000.0, Outcome::Pass);
  c.runs[0].checks[0].measurements = {late, short_of, noisy};
  finalize(c);
  const std::string html = to_report_html(c);
  EXPECT_NE(html.find("<td class=\"num\">1000.000001 ms</td>"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"num\">99.9999999999 ms</td>"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"num\">800 counts</td>"), std::string::npos);
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

// The figure's marks of one class, in every chart (figure_data.hpp).
std::vector<nlohmann::json> marks(const nlohmann::json& fig, const char* list, const std::string& cls) {
  std::vector<nlohmann::json> out;
  for (const auto& chart : fig["charts"])
    for (const auto& mark : chart.value(list, nlohmann::json::array()))
      if (mark.value("cls", "") == cls) out.push_back(mark);
  return out;
}

TEST(Figure, TimingDiagramWithAndWithoutTheEdge) {
  Measurement m = measured("a.edge0", 94.0, 93.0, 95.0, Outcome::Pass);
  m.window = TraceWindow{Nanos{1'000'000}, Nanos{1'002'000}};
  m.at = Nanos{1'001'000};
  ASSERT_TRUE(has_timing(m));
  const nlohmann::json with = timing_figure(m, Judgement::Pass);
  ASSERT_EQ(with["charts"].size(), 1U); // no trace: one output lane stepping at the edge
  const auto& lane = with["charts"][0];
  // Time from the window's start: the edge 1 us after it.
  EXPECT_EQ(marks(with, "vlines", "edge").at(0)["at"], 1000.0);
  EXPECT_EQ(lane["data"][0][1], 1000.0);
  EXPECT_EQ(lane["data"][1][1], 1);
  // A position tolerance crossed in time: the window itself is the expected one, both limits.
  const auto expected = marks(with, "bands", "expected");
  ASSERT_EQ(expected.size(), 1U);
  EXPECT_EQ(expected[0]["from"], 0.0);
  EXPECT_EQ(expected[0]["to"], 2000.0);
  EXPECT_EQ(expected[0]["label"], "expected 93 counts .. 95 counts");
  EXPECT_EQ(marks(with, "vlines", "limit").size(), 2U);
  // A missing edge: the window is drawn and says so, the output in the word's colour.
  m.at.reset();
  m.outcome = Outcome::Fail;
  ASSERT_TRUE(has_timing(m));
  const nlohmann::json missing = timing_figure(m, Judgement::Fail);
  EXPECT_NE(missing["notes"].get<std::string>().find("no edge captured"), std::string::npos);
  EXPECT_EQ(missing["charts"][0]["series"][0]["colour"], "#cf222e");
  EXPECT_TRUE(marks(missing, "vlines", "edge").empty());
  // A passing window-only measurement (a handshake's write to Acknowledge) is no edge diagram.
  m.outcome = Outcome::Pass;
  EXPECT_FALSE(has_timing(m));
  // An open window (waited to the end of the trace): shaded to the figure's right edge.
  m.outcome = Outcome::Fail;
  m.window->end = Nanos::max();
  const nlohmann::json open = timing_figure(m, Judgement::Fail);
  EXPECT_EQ(marks(open, "bands", "expected").at(0)["to"], open["charts"][0]["x"]["max"]);
}

// A latency (throughput.max, limit 20 us from the crossing) that came 1 us late: the diagram
// draws the lanes the run captured, in their order, the expected window [crossing, crossing
// + 20 us] shaded with the limit at crossing + 20 us, and the count at the edge.
TEST(Figure, TimingDiagramDrawsTheCapturedLanesAndMarksTheLimit) {
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
  const nlohmann::json fig = timing_figure(m, Judgement::Fail, &w);
  ASSERT_EQ(fig["charts"].size(), 3U);
  const char* names[] = {"enc.A", "shaft.count", "ls1"};
  const char* roles[] = {"stimulus", "count", "output"};
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& lane = fig["charts"][i];
    EXPECT_EQ(lane["lane"], names[i]);
    EXPECT_EQ(lane["role"], roles[i]);
    EXPECT_EQ(lane["series"][0]["draw"], "step");
    // One time axis, relative to the window's start: -4.2 us .. 25.2 us.
    EXPECT_EQ(lane["x"]["min"], -4200.0);
    EXPECT_EQ(lane["x"]["max"], 25200.0);
    EXPECT_EQ(lane["x"]["time"], true);
  }
  // The count lane: 99 at the span's start, 100 from 1 ns before the window, held to the end.
  EXPECT_EQ(fig["charts"][1]["data"], nlohmann::json::parse("[[-4200.0, -1.0, 25200.0], [99, 100, 100]]"));
  EXPECT_NE(fig["notes"].get<std::string>().find("shaft.count: 100 at the edge"), std::string::npos);
  const auto limits = marks(fig, "vlines", "limit");
  ASSERT_EQ(limits.size(), 3U); // the upper limit only (the start is no limit), on every lane
  EXPECT_EQ(limits[0]["at"], 20000.0);
  const auto expected = marks(fig, "bands", "expected");
  EXPECT_EQ(expected.at(0)["from"], 0.0);
  EXPECT_EQ(expected.at(0)["to"], 20000.0);
  EXPECT_EQ(expected.at(0)["label"], "limit: start + 20 µs");
  EXPECT_EQ(fig["charts"][2]["x"]["label"], "time from the window start");
  // A time without a limit (the median) has no expected window: nothing shaded.
  m.upper.reset();
  EXPECT_FALSE(expected_window(m).has_value());
  const nlohmann::json median = timing_figure(m, Judgement::Pass, &w);
  EXPECT_TRUE(marks(median, "bands", "expected").empty());
  EXPECT_NE(median["notes"].get<std::string>().find("no limit: reported only"), std::string::npos);
}

// A resolver stator is an analog lane: a line through its samples in volts, on the same time
// axis as the other lanes, not a step held to the span's end.
TEST(Figure, ARealLaneIsALineThroughItsSamples) {
  Measurement m = measured("throughput.edge0", 100.0, 99.5, 100.5, Outcome::Pass);
  m.unit = "counts";
  m.window = TraceWindow{Nanos{1'000'000}, Nanos{1'100'000}};
  m.at = Nanos{1'050'000};
  const TraceWindow span = figure_span(m);
  WindowTrace w{*m.window, span, {}};
  w.lanes.push_back(
      {"resolver.sin", LaneRole::Stimulus, {{span.begin, 0, -0.25}, {Nanos{1'050'000}, 0, 0.5}}, 0, true});
  w.lanes.push_back({"shaft.count", LaneRole::Count, {{span.begin, 99}, {Nanos{1'050'000}, 100}}, 0});
  const nlohmann::json fig = timing_figure(m, Judgement::Pass, &w);
  ASSERT_EQ(fig["charts"].size(), 2U);
  const auto& sin = fig["charts"][0];
  EXPECT_EQ(sin["lane"], "resolver.sin");
  EXPECT_EQ(sin["role"], "stimulus");
  EXPECT_EQ(sin["series"][0]["draw"], "line");
  EXPECT_EQ(sin["y"]["label"], "V");
  const double x0 = static_cast<double>((span.begin - m.window->begin).count());
  EXPECT_EQ(sin["data"], nlohmann::json::array({nlohmann::json::array({x0, 50'000.0}), {-0.25, 0.5}}));
  EXPECT_EQ(sin["x"]["min"], fig["charts"][1]["x"]["min"]); // one time axis for both lanes
  EXPECT_EQ(sin["x"]["max"], fig["charts"][1]["x"]["max"]);
  EXPECT_EQ(fig["charts"][1]["series"][0]["draw"], "step");
}

// Diagrams go to the windows that did not pass, then to those with a limit, one per window.
TEST(Figure, TimingFiguresFailuresFirstThenLimitedOnePerWindow) {
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

// A pulse_width check judges its shortest pulse against min_us and its longest against
// max_us; each pulse's diagram shows the whole band. ssi7361_frame_timing.toml's clock-low
// half period inside a frame: min T/2 = 4 us at 125 kHz, max TINT - 24.5 T = 304 us (the
// ssi7361 manual, L1090-L1091 and L1123, as the campaign cites it).
TEST(Figure, PulseWidthPulseShowsTheWholeMinMaxBand) {
  CheckResult c;
  c.kind = "pulse_width";
  const auto pulse = [](const char* name, std::optional<double> lo, std::optional<double> hi) {
    Measurement m = measured(name, 4.0, lo, hi, Outcome::Pass);
    m.unit = "us";
    m.window = TraceWindow{Nanos{100'000}, Nanos{104'000}};
    m.at = Nanos{104'000};
    return m;
  };
  c.measurements = {measured("clk.count", 25.0, 1.0, std::nullopt, Outcome::Pass),
                    pulse("clk.shortest", 4.0, std::nullopt), pulse("clk.longest", std::nullopt, 304.0)};
  for (const Measurement& m : {c.measurements[1], c.measurements[2]}) {
    const Measurement drawn = as_drawn(c, m);
    EXPECT_EQ(drawn.lower, 4.0);
    EXPECT_EQ(drawn.upper, 304.0);
    const auto want = expected_window(drawn);
    ASSERT_TRUE(want.has_value());
    EXPECT_EQ(want->begin, Nanos{104'000});
    EXPECT_EQ(want->end, Nanos{404'000});
    // The diagram's span holds the band's far end, so both limits are on it.
    EXPECT_GT(figure_span(drawn).end, want->end);
    EXPECT_EQ(marks(timing_figure(drawn, Judgement::Pass), "vlines", "limit").size(), 2U);
  }
  // Another kind's measurement keeps its own limits.
  c.kind = "throughput";
  EXPECT_FALSE(as_drawn(c, c.measurements[1]).upper.has_value());
}

// smd23e_homing.toml's creep at the starting speed v_s = 1000 steps/s, peak within 1 %: the
// rate lane shades 990 .. 1010 steps/s and its axis holds the band.
TEST(Figure, ShaftMoveRateLaneShowsTheExpectedPeak) {
  CheckResult c;
  c.kind = "shaft_move";
  Measurement peak = measured("creep.peak_speed", 1000.0, 990.0, 1010.0, Outcome::Pass);
  peak.unit = "steps/s";
  peak.window = TraceWindow{Nanos{0}, Nanos{1'000'000}};
  peak.at = Nanos{1'000'000};
  c.measurements = {measured("creep.steps", 160.0, 158.0, 162.0, Outcome::Pass), peak};
  const auto band = expected_rate(c);
  ASSERT_TRUE(band.has_value());
  EXPECT_EQ(band->lower, 990.0);
  EXPECT_EQ(band->upper, 1010.0);
  WindowTrace w{*peak.window, figure_span(peak), {}};
  w.lanes.push_back({"step rate", LaneRole::Rate, {{w.span.begin, 0}, {Nanos{1'000'000}, 1000}}, 0});
  const nlohmann::json fig = timing_figure(peak, Judgement::Pass, &w, band);
  const auto& lane = fig["charts"][0];
  ASSERT_EQ(lane["hbands"].size(), 1U);
  EXPECT_EQ(lane["hbands"][0]["from"], 990.0);
  EXPECT_EQ(lane["hbands"][0]["to"], 1010.0);
  EXPECT_GE(lane["y"]["max"].get<double>(), 1010.0);
  EXPECT_EQ(lane["y"]["min"], 0.0);
  // A check without a peak limit, or of another kind, shades none.
  c.measurements.pop_back();
  EXPECT_FALSE(expected_rate(c).has_value());
}

// smd23e_profile.toml's trapezoid (knots 10, 100, 401, 491 ms at 1000, 10000, 10000, 1000
// steps/s; seeds/003 L919-928) over its measured rate: one x array for both series (uPlot's),
// each knot at its own time, the lane holding its level there, the profile on its line
// between its knots at the lane's points and nothing outside them; the axis holds its peak.
TEST(Figure, ShaftMoveRateLaneCarriesTheMovesExpectedProfile) {
  Measurement m = measured("trapezoid.steps", 4000.0, 4000.0, 4000.0, Outcome::Pass);
  m.unit = "steps";
  m.window = TraceWindow{Nanos{10'000'000}, Nanos{492'000'000}};
  m.at = Nanos{492'000'000};
  WindowTrace w{*m.window, TraceWindow{Nanos{0}, Nanos{600'000'000}}, {}};
  w.lanes.push_back(
      {"shaft.step rate",
       LaneRole::Rate,
       {{Nanos{0}, 0}, {Nanos{11'000'000}, 1000}, {Nanos{250'000'000}, 10000}, {Nanos{495'000'000}, 0}},
       0});
  const std::vector<RatePoint> profile = {{Nanos{10'000'000}, 1000.0},
                                          {Nanos{100'000'000}, 10000.0},
                                          {Nanos{401'000'000}, 10000.0},
                                          {Nanos{491'000'000}, 1000.0}};
  const nlohmann::json fig = timing_figure(m, Judgement::Pass, &w, std::nullopt, profile);
  const auto& lane = fig["charts"][0];
  ASSERT_EQ(lane["series"].size(), 2U);
  EXPECT_EQ(lane["series"][1]["cls"], "expected");
  EXPECT_EQ(lane["series"][1]["draw"], "line");
  const auto& d = lane["data"];
  ASSERT_EQ(d.size(), 3U);
  // Times from the window start (10 ms): the lane's 0, 11, 250, 495 ms and the span's end
  // 600 ms, merged with the knots' 10, 100, 401, 491 ms.
  const std::vector<double> xs = {-10e6, 0.0, 1e6, 90e6, 240e6, 391e6, 481e6, 485e6, 590e6};
  ASSERT_EQ(d[0].size(), xs.size());
  for (std::size_t i = 0; i < xs.size(); ++i) EXPECT_EQ(d[0][i].get<double>(), xs[i]) << i;
  // The lane: its own points, and at a knot its level there.
  EXPECT_EQ(d[1], nlohmann::json::parse("[0, 0, 1000, 1000, 10000, 10000, 10000, 0, 0]"));
  // The profile: null before its start and after its end; at 11 ms on the ramp
  // 1000 + 9000 * 1/90; at 250 ms cruising.
  EXPECT_TRUE(d[2][0].is_null());
  EXPECT_EQ(d[2][1], 1000.0);
  EXPECT_NEAR(d[2][2].get<double>(), 1100.0, 1e-9);
  EXPECT_EQ(d[2][3], 10000.0);
  EXPECT_EQ(d[2][4], 10000.0);
  EXPECT_EQ(d[2][5], 10000.0);
  EXPECT_EQ(d[2][6], 1000.0);
  EXPECT_TRUE(d[2][7].is_null());
  EXPECT_TRUE(d[2][8].is_null());
  EXPECT_EQ(lane["y"]["min"], 0.0);
  EXPECT_GE(lane["y"]["max"].get<double>(), 10000.0);
  EXPECT_NE(fig["notes"].get<std::string>().find("expected profile"), std::string::npos);
  // Without a profile the lane has its one series.
  EXPECT_EQ(timing_figure(m, Judgement::Pass, &w)["charts"][0]["series"].size(), 1U);
}

TEST(Figure, HistogramKeepsEveryLimitOnTheCanvasAndHasEnoughBins) {
  // Values 1..4 us, limits far beyond (100 us) and below (-50 us): both inside the x range.
  const std::vector<double> v{1.0, 2.0, 3.0, 4.0};
  const std::vector<LimitLine> limits{{"max", 100.0}, {"min", -50.0}};
  const nlohmann::json fig = histogram_figure(v, "us", limits);
  const auto& chart = fig["charts"][0];
  const double lo = chart["x"]["min"], hi = chart["x"]["max"];
  EXPECT_LT(lo, -50.0);
  EXPECT_GT(hi, 100.0);
  const auto lines = marks(fig, "vlines", "limit");
  ASSERT_EQ(lines.size(), 2U);
  EXPECT_EQ(lines[0]["label"], "max limit 100 µs");
  // At least 10 bins whatever the sample count: 4 values in bins of (4 - 1) / 10 = 0.3 us, so
  // 1, 2 and 3 (floor(3.33), floor(6.67)) and 4 (the last bin) one each.
  EXPECT_EQ(fig["notes"], "4 samples in 10 bins of 0.3 µs");
  EXPECT_EQ(chart["data"][1], nlohmann::json::parse("[1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0]"));
  EXPECT_EQ(chart["y"]["label"], "count");
  EXPECT_TRUE(histogram_figure({}, "us", limits).is_null());
}

TEST(Figure, LimitsChartPerLimitedMeasurement) {
  const Measurement a = measured("a", 96.0, 93.0, 95.0, Outcome::Fail);
  const Measurement b = measured("b", 2.0, 1.0, std::nullopt, Outcome::Pass);
  const Measurement c = measured("c", 7.0, std::nullopt, std::nullopt, Outcome::Pass);
  const std::vector<ShownMeasurement> rows{
      {&a, Judgement::Fail}, {&b, Judgement::Pass}, {&c, Judgement::Pass}};
  const nlohmann::json fig = limits_figure(rows);
  ASSERT_EQ(fig["charts"].size(), 2U); // c has no limit: no chart
  const auto& first = fig["charts"][0];
  EXPECT_EQ(first["series"][0]["colour"], "#cf222e");
  EXPECT_EQ(first["x"]["label"], "a: 96 counts");
  EXPECT_EQ(first["data"][0][0], 96.0);
  // 93 .. 96 padded by a quarter of the span: every limit and the value on the axis.
  EXPECT_EQ(first["x"]["min"], 92.25);
  EXPECT_EQ(first["x"]["max"], 96.75);
  EXPECT_EQ(marks(fig, "vlines", "limit").size(), 3U);
  const std::vector<ShownMeasurement> none{{&c, Judgement::Pass}};
  EXPECT_TRUE(limits_figure(none).is_null());
}

TEST(Figure, ProbesOnePointEachAgainstTheBand) {
  const std::vector<Probe> probes{{Nanos{20'000}, false}, {Nanos{40'000}, true}, {Nanos{30'000}, true}};
  const nlohmann::json fig = probes_figure(probes, 26'500.0, 28'500.0);
  const auto& chart = fig["charts"][0];
  // By width, numbered in the order they ran.
  EXPECT_EQ(chart["data"][0], nlohmann::json::parse("[20000, 30000, 40000]"));
  EXPECT_EQ(chart["data"][1], nlohmann::json::parse("[null, 1, 1]"));
  EXPECT_EQ(chart["data"][2], nlohmann::json::parse("[0, null, null]"));
  EXPECT_EQ(chart["series"][0]["numbers"], nlohmann::json::parse(R"(["1", "3", "2"])"));
  const auto band = marks(fig, "bands", "expected");
  ASSERT_EQ(band.size(), 1U);
  EXPECT_EQ(band[0]["label"], "filter band");
  EXPECT_EQ(band[0]["from"], 26'500.0);
  EXPECT_EQ(band[0]["to"], 28'500.0);
}

TEST(Figure, MotionPlotsSpeedAndPositionWithEventsAndMarkers) {
  MotionRecord m;
  // Constant deceleration from 1000 counts/s to rest over 100 ms: 50 counts.
  for (int i = 0; i <= 10; ++i) {
    const double t = 0.01 * i;
    m.points.push_back(
        {Nanos{static_cast<std::int64_t>(t * 1e9)}, 1000.0 * t - 5000.0 * t * t, 1000.0 - 10000.0 * t});
  }
  m.events.push_back({Nanos{0}, "valve off: brake applied, clutch released"});
  const std::vector<Marker> marks_at{{Nanos{100'000'000}, "standstill", "#1a7f37", "event"},
                                     {Nanos{90'000'000}, "limit", "#cf222e", "limit"}};
  const nlohmann::json fig = motion_figure(m, marks_at);
  const auto& chart = fig["charts"][0];
  EXPECT_EQ(chart["series"].size(), 2U);
  EXPECT_EQ(chart["series"][1]["scale"], "y2"); // position on its own axis
  EXPECT_EQ(chart["data"][1][10], 0.0);         // at rest at 100 ms
  EXPECT_EQ(chart["data"][2][10], 50.0);        // 50 counts travelled
  const auto events = marks(fig, "vlines", "event");
  ASSERT_EQ(events.size(), 2U);
  EXPECT_EQ(events[0]["label"], "valve off: brake applied, clutch released 0 ns");
  EXPECT_EQ(events[1]["label"], "standstill 100 ms");
  EXPECT_EQ(marks(fig, "vlines", "limit").at(0)["at"], 90'000'000.0);
  // Time from `origin`: the brake's applied instant at 0.
  const nlohmann::json from_applied =
      motion_figure(m, marks_at, Nanos{0}, Nanos{100'000'000}, Nanos{10'000'000});
  EXPECT_EQ(from_applied["charts"][0]["x"]["min"], -10'000'000.0);
  EXPECT_TRUE(motion_figure(MotionRecord{}, marks_at).is_null());
}

TEST(Figure, TrendKeepsTheLimitsOnTheCanvas) {
  const std::vector<TrendPoint> nights{{"mon", 10.0, Judgement::Pass},
                                       {"tue", std::nullopt, Judgement::Error},
                                       {"wed", 30.0, Judgement::Fail}};
  const nlohmann::json fig = trend_figure(nights, "us", 0.0, 100.0);
  const auto& chart = fig["charts"][0];
  EXPECT_LE(chart["y"]["min"].get<double>(), 0.0);
  EXPECT_GE(chart["y"]["max"].get<double>(), 100.0);
  EXPECT_EQ(marks(fig, "hlines", "limit").size(), 2U);
  EXPECT_EQ(chart["data"][1], nlohmann::json::parse("[10.0, null, 30.0]"));
  EXPECT_EQ(chart["data"][2], nlohmann::json::parse("[10.0, null, null]")); // pass
  EXPECT_EQ(chart["data"][3], nlohmann::json::parse("[null, null, 30.0]")); // fail
  EXPECT_EQ(chart["x"]["names"], nlohmann::json::parse(R"(["mon", "tue", "wed"])"));
}

// docs/campaigns.md (report): "a failing measurement of a catching check reads caught, in
// blue; a not-judged check's not judged, in grey; red is only fail". The trend draws each
// point in the word report.html shows for it (measurement_judgement()), so a fault caught
// every night is blue, never in the fail series.
TEST(Figure, TrendDrawsEachPointInItsWordsSeries) {
  const std::vector<TrendPoint> nights{{"mon", 35.0, Judgement::Caught}, {"tue", 36.0, Judgement::NotJudged}};
  const nlohmann::json chart = trend_figure(nights, "us", std::nullopt, 20.0)["charts"][0];
  std::map<std::string, std::pair<std::string, nlohmann::json>> by_label;
  for (std::size_t k = 0; k < chart["series"].size(); ++k)
    by_label[chart["series"][k]["label"]] = {chart["series"][k]["colour"], chart["data"][k + 1]};
  EXPECT_EQ(by_label["caught"].first, outcome_colour(Judgement::Caught));
  EXPECT_EQ(by_label["caught"].second, nlohmann::json::parse("[35.0, null]"));
  EXPECT_EQ(by_label["not judged"].second, nlohmann::json::parse("[null, 36.0]"));
  EXPECT_EQ(by_label["fail"].second, nlohmann::json::parse("[null, null]"));
}

// The caught fault of a sample campaign: its failing throughput.max (35 us over 20) reads
// caught, the same word in report.html and in the shared routine the trend uses.
TEST(Figure, AFaultsEvidenceReadsCaughtInEveryOutput) {
  const CampaignResult c = test::sample_campaign(3); // run 2: fault "slow_output", caught
  const CheckResult& throughput = c.runs[2].checks[0];
  ASSERT_EQ(throughput.judgement, Judgement::Caught);
  EXPECT_EQ(measurement_judgement(throughput, throughput.measurements[1]), Judgement::Caught);
  EXPECT_EQ(measurement_judgement(throughput, throughput.measurements[0]), Judgement::Pass); // count 3 >= 1
  EXPECT_EQ(measurement_judgement(c.runs[0].checks[0], c.runs[0].checks[0].measurements[1]), Judgement::Pass);
}

} // namespace
} // namespace hilrig::rig
