#include "rig/cli/trace_files.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "rig/results/results_json.hpp"

namespace hilrig::cli {

namespace {

// A dot would open a VCD scope, a space split a VCD name, a slash a path: a check's name keeps
// its letters, digits, '-' and '_', and everything else becomes '_'.
std::string plain_name(std::string text) {
  for (char& c : text)
    if (!(std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '-' || c == '_')) c = '_';
  return text;
}

// The check's measurement windows, sorted and joined where they overlap or touch. A window of
// no length is widened to 1 ns, so its marker is seen.
// A measurement's window as the trace can show it: from 0 on (an expected window can begin, or
// lie wholly, before the run: an edge due before the shaft reached the setpoint's count) and at
// least a nanosecond long.
rig::TraceWindow shown(const rig::TraceWindow& w) {
  const Nanos begin = std::max(w.begin, Nanos{0});
  return {begin, std::max(w.end, begin + Nanos{1})};
}

std::vector<rig::TraceWindow> windows_of(const rig::CheckResult& check) {
  std::vector<rig::TraceWindow> w;
  for (const rig::Measurement& m : check.measurements)
    if (m.window) w.push_back(shown(*m.window));
  std::sort(w.begin(), w.end(), [](const auto& a, const auto& b) { return a.begin < b.begin; });
  std::vector<rig::TraceWindow> joined;
  for (const rig::TraceWindow& x : w) {
    if (!joined.empty() && x.begin <= joined.back().end)
      joined.back().end = std::max(joined.back().end, x.end);
    else
      joined.push_back(x);
  }
  return joined;
}

bool failed(const rig::RunResult& run, const rig::CheckResult& check) {
  const rig::Judgement j = rig::judgement_in(run, check);
  return j == rig::Judgement::Fail || j == rig::Judgement::Error;
}

// The save file opens on the first measurement that failed and has a window (its captured
// edge, when it has one, is the primary marker); else on all the check's windows; a check
// that judged no window at all (e.g. it saw no edge) opens on the whole run.
GtkwView view_of(const rig::CheckResult& check, const TraceRecorder& trace) {
  for (const rig::Measurement& m : check.measurements)
    if (m.outcome != rig::Outcome::Pass && m.window) {
      const rig::TraceWindow w = shown(*m.window);
      return GtkwView{w.begin, w.end, m.at};
    }
  const std::vector<rig::TraceWindow> windows = windows_of(check);
  if (!windows.empty()) return GtkwView{windows.front().begin, windows.back().end, std::nullopt};
  return GtkwView{Nanos{0}, std::max(Nanos{1}, trace.latest_sample_time()), std::nullopt};
}

const char* gtkw_flags(SignalKind kind) {
  // GTKWave trace flags (hex): 28 binary, right-justified; 24 decimal; 8420 a signed analog
  // step plot, which draws a real as a waveform.
  switch (kind) {
  case SignalKind::Wire:
    return "@28";
  case SignalKind::Integer:
    return "@24";
  case SignalKind::Real:
    return "@8420";
  }
  return "@28";
}

} // namespace

std::string gtkw_text(const std::string& vcd_name, const std::string& title, const GtkwView& view,
                      const std::vector<SignalInfo>& signals) {
  // The window and the captured edge (which may lie outside it: that is the failure), with a
  // quarter of their length either side, so the edges are seen in context.
  const std::int64_t first = std::min(view.begin, view.at.value_or(view.begin)).count();
  const std::int64_t last = std::max(view.end, view.at.value_or(view.end)).count();
  const std::int64_t margin = std::max<std::int64_t>(1, (last - first) / 4);
  const std::int64_t start = std::max<std::int64_t>(0, first - margin);
  const std::int64_t span = last + margin - start;
  // GTKWave draws 2^-zoom time units (ns) per pixel; the wave pane of [size] below is ~1000 px.
  const double zoom = -std::log2(static_cast<double>(span) / 1000.0);
  std::string text = fmt::format("[*]\n[*] {}\n[*]\n[dumpfile] \"{}\"\n[timestart] {}\n[size] 1400 700\n"
                                 "[signals_width] 260\n[sst_expanded] 0\n",
                                 title, vcd_name, start);
  text += fmt::format("*{:.6f} {} {} {}", zoom, view.at.value_or(view.begin).count(), view.begin.count(),
                      view.end.count());
  for (int i = 2; i < 26; ++i) text += " -1";
  text += '\n';
  for (const SignalInfo& s : signals) {
    text += gtkw_flags(s.kind);
    text += '\n';
    text += s.name;
    text += '\n';
  }
  return text;
}

namespace {

// STEM.<check>.gtkw for each check of `run` that failed (or erred).
void write_gtkw_files(const std::filesystem::path& dir, const std::string& stem, const TraceRecorder& trace,
                      const rig::RunResult& run) {
  for (const rig::CheckResult& check : run.checks) {
    if (!failed(run, check)) continue;
    const GtkwView view = view_of(check, trace);
    const std::string title = fmt::format("run {} ({}): check {} {}", run.index, run.name, check.check,
                                          rig::to_string(rig::judgement_in(run, check)));
    rig::write_file_atomically(dir / fmt::format("{}.{}.gtkw", stem, plain_name(check.check)),
                               gtkw_text(stem + ".vcd", title, view, trace.signals()));
  }
}

} // namespace

void write_trace_files(const std::filesystem::path& dir, const std::string& stem, TraceRecorder& trace,
                       const rig::RunResult& run, bool gtkw_for_failures, std::optional<Nanos> end) {
  std::vector<TraceSample> marks;
  for (const rig::CheckResult& check : run.checks) {
    const std::vector<rig::TraceWindow> windows = windows_of(check);
    if (windows.empty()) continue;
    const std::uint32_t signal = trace.declare("check." + plain_name(check.check));
    trace.set_initial(signal, 0);
    for (const rig::TraceWindow& w : windows) {
      marks.push_back(TraceSample{w.begin, signal, 1, 0.0});
      marks.push_back(TraceSample{w.end, signal, 0, 0.0});
    }
  }
  // The run's end as a last time stamp when nothing changed at it: a viewer then draws the
  // levels held to the end, and a reader tells a quiet end from a run cut short.
  Nanos last = std::max(trace.latest_sample_time(), Nanos{0});
  for (const TraceSample& m : marks) last = std::max(last, m.time);
  rig::write_file_atomically(dir / (stem + ".vcd"), [&](std::ostream& vcd) {
    write_vcd(trace, vcd, "", marks);
    if (end && *end > last) vcd << '#' << end->count() << '\n';
  });
  if (gtkw_for_failures) write_gtkw_files(dir, stem, trace, run);
}

void link_trace_files(const std::filesystem::path& dir, const std::string& written_stem,
                      const std::string& stem, const TraceRecorder& trace, const rig::RunResult& run) {
  rig::link_file_atomically(dir / (written_stem + ".vcd"), dir / (stem + ".vcd"));
  write_gtkw_files(dir, stem, trace, run);
}

} // namespace hilrig::cli
