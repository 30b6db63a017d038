#!/usr/bin/env python3
"""report.html as a person opens it (issue 18, "Done when"): every shipped campaign is run
as one suite and each campaign's report is loaded in one headless Chromium (driven over its
DevTools pipe, so one browser start serves every page). After the page's scripts ran (the
embedded uPlot and figures.js), with every run expanded, each check section that was judged
(data-judgement is not "not judged") must hold a figure drawn by uPlot: a canvas laid out with
a size (a check with no limit and no window in results.json: a note saying so). Each timing
diagram has a lane per captured trace lane, its expected window and limit drawn on the canvas
(figures.js records what landed inside the plot). The page must throw no JavaScript error;
the sections must be as many as results.json's checks; a failing campaign's summary must link
each failed check. The marks' words (limits, windows, edges) must be legible: none drawn on
another, on a plot's traces or cut off (also in a crowded diagram: the SMD23E's trapezoid with
the wrong acceleration). The trend page of two nights is checked the same way. A screenshot of
each report is written beside it (report.png).

Usage: check_report_browser.py HILRIG SOURCE_DIR SCRATCH_DIR CHROMIUM
"""
import base64
import json
import os
import pathlib
import shutil
import subprocess
import sys

# Installed before the page's own scripts: every uncaught error and rejected promise recorded.
CATCH_ERRORS = """window.__errors = [];
window.addEventListener('error', e => window.__errors.push(String(e.message || e.error)));
window.addEventListener('unhandledrejection', e => window.__errors.push(String(e.reason)));"""

# Per check section: its word, how many figures hold a uPlot canvas laid out with a size (or
# are a note), and its timing diagrams. Then the summary's links to failed checks, each
# pointing at a section that exists, and the page's errors.
INSPECT = """JSON.stringify((() => {
  document.querySelectorAll('details').forEach(d => { d.open = true; });
  const laidOut = e => e.getBoundingClientRect().width > 0 && e.getBoundingClientRect().height > 0;
  const drawn = f => [...f.querySelectorAll('.uplot canvas')].some(laidOut);
  // A timing diagram: its lanes by role (each a uPlot canvas), and how many expected windows
  // and limit lines the top lane drew inside its plot.
  const timing = f => {
    const lanes = role => [...f.querySelectorAll('div.chart.lane.' + role)]
      .filter(d => [...d.querySelectorAll('canvas')].some(laidOut)).map(d => d.dataset.lane);
    const top = f.querySelector('div.chart.lane');
    return {stimulus: lanes('stimulus'), count: lanes('count'), output: lanes('output'), rate: lanes('rate'),
            analog: lanes('analog'),
            expected: Number(top.dataset.expected), limits: Number(top.dataset.limits),
            rate_expected: [...f.querySelectorAll('div.chart.lane.rate')].map(d => Number(d.dataset.rateExpected)),
            profile: [...f.querySelectorAll('div.chart.lane.rate')].map(d => Number(d.dataset.profile))};
  };
  const figures = s => [...s.querySelectorAll('figure.evidence')];
  // Any other figure: its kind, whether uPlot drew it, the limits its data has and those drawn
  // inside its plots (every limit always on the canvas).
  const others = f => {
    const data = JSON.parse(f.querySelector('script.figure-data').textContent);
    const limits = data.charts.flatMap(c => (c.vlines || []).concat(c.hlines || [])).filter(l => l.cls === 'limit');
    const onCanvas = [...f.querySelectorAll('div.chart')].reduce((n, d) => n + Number(d.dataset.limits), 0);
    return [f.dataset.kind, drawn(f) ? 1 : 0, limits.length, onCanvas];
  };
  const sections = [...document.querySelectorAll('section.check')].map(s => [
    s.dataset.judgement,
    figures(s).filter(f => drawn(f)).length,
    figures(s).filter(f => f.classList.contains('note')).length,
    figures(s).filter(f => f.dataset.kind === 'timing').map(timing),
    figures(s).filter(f => f.dataset.kind !== 'timing' && !f.classList.contains('note')).map(others)]);
  // The marks' words (figures.js records each chart's in data-labels: its box and the line
  // drawn up to it, CSS px on the canvas), on the page: in each figure no two boxes overlap, no
  // box lies on a plot (where the traces are) or a lane's title, and no line crosses a box.
  const labels = f => {
    const boxes = [], leaders = [], keepOut = [], clashes = [];
    for (const d of f.querySelectorAll('div.chart')) {
      const canvas = d.querySelector('.uplot canvas');
      if (!canvas || !laidOut(canvas)) continue;
      const c = canvas.getBoundingClientRect();
      const o = d.querySelector('.u-over').getBoundingClientRect();
      const where = d.dataset.lane || 'the plot';
      keepOut.push([o.left, o.top, o.right, o.bottom, where + "'s plot"]);
      const title = d.querySelector('.lane-title');
      if (title) {
        const t = title.getBoundingClientRect();
        keepOut.push([t.left, t.top, t.right, t.bottom, where + "'s title"]);
      }
      for (const l of JSON.parse(d.dataset.labels || '[]')) {
        const b = [c.left + l.x, c.top + l.y, c.left + l.x + l.w, c.top + l.y + l.h, '"' + l.text + '"'];
        if (b[0] < c.left - 0.5 || b[2] > c.right + 0.5 || b[1] < c.top - 0.5 || b[3] > c.bottom + 0.5)
          clashes.push(b[4] + ' is cut off by the edge of ' + where + "'s canvas");
        boxes.push(b);
        if (l.leader) leaders.push([c.left + l.leader[0], c.top + l.leader[1], c.top + l.leader[2], b[4]]);
      }
    }
    const hit = (a, b) => a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3];
    boxes.forEach((a, i) => {
      boxes.slice(i + 1).forEach(b => { if (hit(a, b)) clashes.push(a[4] + ' overlaps ' + b[4]); });
      keepOut.forEach(k => { if (hit(a, k)) clashes.push(a[4] + ' lies on ' + k[4]); });
      leaders.forEach(([x, y0, y1, of]) => {
        if (of !== a[4] && x > a[0] && x < a[2] && y0 < a[3] && a[1] < y1) clashes.push(a[4] + ' crossed by the line of ' + of);
      });
    });
    return {count: boxes.length, clashes};
  };
  const figureLabels = [...document.querySelectorAll('figure.evidence')].map(f => {
    const found = labels(f);
    const section = f.closest('section.check');
    return {check: section ? section.id : f.dataset.kind, count: found.count, clashes: found.clashes};
  });
  const links = [...document.querySelectorAll('ul.failures a')].map(a => a.getAttribute('href'));
  const dangling = links.filter(h => !document.getElementById(h.slice(1)));
  const trend = [...document.querySelectorAll('figure.evidence[data-kind=trend]')].map(others);
  return {sections, links, dangling, trend, errors: window.__errors, labels: figureLabels,
          undrawn: [...document.querySelectorAll('figure.evidence[data-kind]')].filter(f => !f.dataset.drawn).length};
})())"""


# Checks judged against the shaft: their diagrams show the encoder (stimulus) and the count.
ON_SHAFT = ("throughput", "edge_at_position", "advance_counts")


def timing_problems(name, check, timings, encoder, resolver):
    """Each window results.json cut a trace for is one diagram with the run's lanes in it: the
    stimulus (enc.A/enc.B, when the campaign wires the encoder; a resolver board's stators,
    resolver.sin/resolver.cos, as analog lanes drawn as lines) and shaft.count for a check on
    the shaft, the check's output line,
    and its expected window and limit drawn inside the figure (a limitless time: none); a
    shaft_move also its step rate against time with the expected peak rate shaded (when the
    check limits it) and, when it names its move (profile_of: results.json's expected_rate),
    the move's whole expected profile drawn over it inside the plot, every knot in the span
    at least; a pulse_width each pulse against the whole [min, max] band."""
    traces = check.get("traces", [])
    out = []
    given = lambda m, key: m.get(key) is not None  # noqa: E731 - results.json writes null
    peak_limited = any(m["name"].endswith(".peak_speed") and (given(m, "lower") or given(m, "upper"))
                       for m in check["measurements"])
    band = (any(given(m, "lower") for m in check["measurements"] if m.get("unit") == "us")
            and any(given(m, "upper") for m in check["measurements"] if m.get("unit") == "us"))
    if len(timings) != len(traces):
        return [f"{name}: {check['check']}: {len(timings)} timing diagrams for {len(traces)} cut windows"]
    for t, cut in zip(timings, traces):
        want = {role: [l["name"] for l in cut["lanes"] if l["role"] == role]
                for role in ("stimulus", "count", "output", "rate")}
        for role, lanes in want.items():
            if t[role] != lanes:
                out.append(f"{name}: {check['check']}: {role} lanes drawn {t[role]}, captured {lanes}")
        if check["kind"] in ON_SHAFT and t["count"] != ["shaft.count"]:
            out.append(f"{name}: {check['check']}: no count lane in its timing diagram")
        stimulus = (["enc.A", "enc.B"] if encoder else []) + (["resolver.sin", "resolver.cos"] if resolver else [])
        if check["kind"] in ON_SHAFT and t["stimulus"] != stimulus:
            out.append(f"{name}: {check['check']}: stimulus lanes {t['stimulus']}, not the encoder's A/B "
                       f"and the resolver's stators as wired: {stimulus}")
        analog = [l["name"] for l in cut["lanes"] if l.get("real")]
        if t["analog"] != analog:
            out.append(f"{name}: {check['check']}: analog lanes drawn as lines {t['analog']}, captured {analog}")
        if check["kind"] == "shaft_move" and len(t["rate"]) != 1:
            out.append(f"{name}: {check['check']}: no step rate against time in its timing diagram")
        if check["kind"] == "shaft_move" and peak_limited and t["rate_expected"] != [1]:
            out.append(f"{name}: {check['check']}: its expected peak step rate is not drawn on the rate lane")
        knots = check.get("expected_rate", [])
        inside = sum(1 for k in knots if cut["span"]["begin_ns"] <= k[0] <= cut["span"]["end_ns"])
        if check["kind"] == "shaft_move" and knots and not (len(t["profile"]) == 1
                                                            and t["profile"][0] >= max(1, inside)):
            out.append(f"{name}: {check['check']}: its expected profile is not drawn over the rate lane "
                       f"(points on the canvas {t['profile']}, knots in the span {inside})")
        if check["kind"] == "pulse_width" and band and (t["expected"], t["limits"]) != (1, 2):
            out.append(f"{name}: {check['check']}: the [min, max] band is not drawn whole: expected window "
                       f"{t['expected']}, limit lines {t['limits']}")
        if not t["output"]:
            out.append(f"{name}: {check['check']}: no output lane in its timing diagram")
        if t["expected"] > 1 or (t["expected"] == 1) != (t["limits"] > 0):
            out.append(f"{name}: {check['check']}: expected window {t['expected']}, limit lines {t['limits']}")
    return out


def figure_problems(name, check, others):
    """Every figure other than a timing diagram drawn by uPlot, each limit in its data drawn
    inside its plot (a histogram's limit line is on the canvas however far it is)."""
    out = []
    for kind, drawn, limits, on_canvas in others:
        if not drawn:
            out.append(f"{name}: {check}: its {kind} figure has no uPlot canvas")
        if on_canvas != limits:
            out.append(f"{name}: {check}: {kind} figure draws {on_canvas} of its {limits} limits on the canvas")
    return out


def label_problems(name, figures):
    """The marks' words of each figure legible: none on another, on a plot or a lane's title, cut
    off, or crossed by a mark's line drawn up to other words."""
    return [f"{name}: {f['check']}: {clash}" for f in figures for clash in f["clashes"]]


def child_fds(read_end, write_end):
    """In the child: the pipe ends as fds 3 and 4, inheritable (os.pipe's are close-on-exec)."""
    r, w = os.dup(read_end), os.dup(write_end)  # above 4: neither dup2 below clobbers the other
    os.dup2(r, 3, inheritable=True)
    os.dup2(w, 4, inheritable=True)


class Browser:
    """One headless Chromium over --remote-debugging-pipe (fd 3 in, fd 4 out, NUL-framed JSON)."""

    def __init__(self, chromium, profile):
        # The child's fds 3 and 4 are set by dup2 after the fork (close_fds would close them).
        to_chrome_r, self.to_chrome = os.pipe()
        self.from_chrome, from_chrome_w = os.pipe()
        self.proc = subprocess.Popen(
            [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars", "--no-first-run",
             f"--user-data-dir={profile}", "--remote-debugging-pipe", "about:blank"],
            close_fds=False, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
            preexec_fn=lambda: child_fds(to_chrome_r, from_chrome_w))
        os.close(to_chrome_r)
        os.close(from_chrome_w)
        self.buffer = b""
        self.next_id = 0
        target = self.call("Target.createTarget", {"url": "about:blank"})["targetId"]
        self.session = self.call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        self.call("Page.enable", session=True)
        self.call("Page.addScriptToEvaluateOnNewDocument", {"source": CATCH_ERRORS}, session=True)
        self.call("Emulation.setDeviceMetricsOverride",
                  {"width": 900, "height": 1400, "deviceScaleFactor": 1, "mobile": False}, session=True)

    def send(self, method, params, session):
        self.next_id += 1
        msg = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            msg["sessionId"] = self.session
        os.write(self.to_chrome, json.dumps(msg).encode() + b"\0")
        return self.next_id

    def receive(self):
        while b"\0" not in self.buffer:
            chunk = os.read(self.from_chrome, 1 << 20)
            if not chunk:
                raise RuntimeError("chromium closed its DevTools pipe")
            self.buffer += chunk
        msg, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(msg)

    def call(self, method, params=None, session=False, until_event=None):
        wanted = self.send(method, params, session)
        result, seen_event = None, until_event is None
        while result is None or not seen_event:
            msg = self.receive()
            if msg.get("id") == wanted:
                if "error" in msg:
                    raise RuntimeError(f"{method}: {msg['error']}")
                result = msg["result"]
            elif msg.get("method") == until_event:
                seen_event = True
        return result

    def inspect(self, report, png):
        self.call("Page.navigate", {"url": report.resolve().as_uri()}, session=True,
                  until_event="Page.loadEventFired")
        found = json.loads(self.call("Runtime.evaluate", {"expression": INSPECT, "returnByValue": True},
                                     session=True)["result"]["value"])
        shot = self.call("Page.captureScreenshot", {"format": "png"}, session=True)
        png.write_bytes(base64.b64decode(shot["data"]))
        return found

    def close(self):
        try:
            self.send("Browser.close", {}, False)
            self.proc.wait(timeout=20)
        except Exception:  # noqa: BLE001 - a browser that will not close is killed
            self.proc.kill()


def trend_problems(hilrig, browser, scratch, reports):
    """hilrig trend over two nights of one campaign (the same results in two files: one file
    given twice is refused): a figure per measurement, each drawn with its limits on the
    canvas, and no JavaScript error."""
    night = next(r for r in reports if r.parent.name == "ans1_throughput").parent / "results.json"
    second = scratch / "second-night.json"
    shutil.copyfile(night, second)
    page = scratch / "trend.html"
    subprocess.run([hilrig, "trend", str(night), str(second), "--out", str(page)], capture_output=True)
    if not page.exists():
        return ["hilrig trend wrote no page"]
    found = browser.inspect(page, scratch / "trend.png")
    measurements = sum(len(c["measurements"]) for run in json.loads(night.read_text())["runs"] for c in run["checks"])
    out = figure_problems("trend", "trend", found["trend"])
    out += label_problems("trend", found["labels"])
    out += [f"trend: JavaScript error: {e}" for e in found["errors"]]
    if len(found["trend"]) != measurements:
        out.append(f"trend: {len(found['trend'])} figures for {measurements} measurements")
    return out


def main():
    hilrig, src, scratch, chromium = sys.argv[1:5]
    scratch = pathlib.Path(scratch)
    shutil.rmtree(scratch, ignore_errors=True)
    scratch.mkdir(parents=True)
    subprocess.run([hilrig, "run", f"{src}/campaigns", "--out", str(scratch / "suite"), "--backend", "virtual",
                    "--jobs", "2"], capture_output=True, check=False)
    reports = sorted(p for p in (scratch / "suite").rglob("report.html") if (p.parent / "results.json").exists())
    shipped = len(list(pathlib.Path(src, "campaigns").rglob("*.toml")))
    problems = []
    if len(reports) != shipped:
        problems.append(f"{len(reports)} campaign reports for {shipped} shipped campaigns")
    def run_variant(campaign, name):
        """Runs a campaign made here; its report joins the ones checked."""
        subprocess.run([hilrig, "run", str(campaign), "--out", str(scratch / name)], capture_output=True)
        if not (scratch / name / "report.html").exists():
            problems.append(f"the {name} campaign wrote no report")
        else:
            reports.append(scratch / name / "report.html")

    # A failing campaign (none is shipped): ans1_brake with the rig's stop-time limit below
    # the 100 ms stop the board makes, so the check fails and its figure must be there.
    failing = scratch / "failing.toml"
    failing.write_text(pathlib.Path(src, "campaigns/ans1/ans1_brake.toml").read_text().replace(
        "limit_ms = 150", "limit_ms = 50", 1))
    run_variant(failing, "failing")
    # Crowded marks (issue: labels drawn over each other): the SMD23E with the wrong acceleration
    # and no faults injected, so its trapezoid's narrow expected window (two limit lines close
    # together), its words and the far edge all fall in one top lane.
    crowded = scratch / "crowded.toml"
    faults = pathlib.Path(src, "campaigns/smd23e/smd23e_faults.toml").read_text()
    crowded.write_text(faults.split("\n[[fault]]")[0].replace(
        'model = "smd23e"', 'model = "smd23e"\nvariant = "wrong-acceleration"', 1))
    run_variant(crowded, "crowded")

    sources = {p.stem: p for p in pathlib.Path(src, "campaigns").rglob("*.toml")}
    sources.update(failing=failing, crowded=crowded)
    browser = Browser(chromium, scratch / "chromium-profile")
    judged_total = 0
    drawn_traces = 0
    analog_drawn = 0  # resolver stator lanes drawn as lines, over every report
    profiles_drawn = 0  # shaft_move diagrams with their move's expected profile drawn
    labels_checked = 0  # the marks' words laid out, over every report
    try:
        for report in reports:
            name = report.parent.name
            found = browser.inspect(report, report.parent / "report.png")
            results = json.loads((report.parent / "results.json").read_text())
            checks = [c for run in results["runs"] for c in run["checks"]]
            toml = sources.get(name)
            encoder = toml is not None and 'rig = "enc.A"' in toml.read_text()
            resolver = toml is not None and "[resolver]" in toml.read_text()
            if len(found["sections"]) != len(checks):
                problems.append(f"{name}: {len(found['sections'])} check sections, {len(checks)} in results.json")
            for (word, figures, notes, timings, others), c in zip(found["sections"], checks):
                problems += timing_problems(name, c, timings, encoder, resolver)
                analog_drawn += sum(len(t["analog"]) for t in timings)
                profiles_drawn += sum(1 for t in timings if sum(t["profile"]) > 0)
                # The profile campaign's moves are each named by its checks (profile_of).
                if name == "smd23e_profile" and c["kind"] == "shaft_move" and not c.get("expected_rate"):
                    problems.append(f"{name}: {c['check']}: no expected profile in results.json")
                problems += figure_problems(name, c["check"], others)
                drawn_traces += len(c.get("traces", []))
                if word != c["outcome"]:
                    problems.append(f"{name}: {c['check']} reads {word}, results.json {c['outcome']}")
                if word != "not judged":
                    judged_total += 1
                    # Only a check with nothing to draw (no limit, no window) may show a note instead.
                    drawable = any(m.get(k) is not None for m in c["measurements"] for k in ("lower", "upper", "window"))
                    if figures == 0 and (drawable or notes == 0):
                        problems.append(f"{name}: {c['check']} ({word}) has no figure drawn by uPlot")
            problems += [f"{name}: JavaScript error: {e}" for e in found["errors"]]
            problems += label_problems(name, found["labels"])
            labels_checked += sum(f["count"] for f in found["labels"])
            if found["undrawn"]:
                problems.append(f"{name}: {found['undrawn']} figures not drawn")
            bad = sum(1 for c in checks if c["outcome"] in ("fail", "error"))
            if len(found["links"]) < bad or found["dangling"]:
                problems.append(f"{name}: {bad} failed checks, summary links {found['links']}, "
                                f"dangling {found['dangling']}")
            if report.parent.name == "failing" and bad == 0:
                problems.append("the failing campaign has no failed check")
            png = report.parent / "report.png"
            if png.read_bytes()[:8] != b"\x89PNG\r\n\x1a\n":
                problems.append(f"{name}: no screenshot")
        problems += trend_problems(hilrig, browser, scratch, reports)
    finally:
        browser.close()
    if drawn_traces == 0:
        problems.append("no timing diagram with the run's trace in any report")
    if analog_drawn == 0:
        problems.append("no resolver stator drawn as an analog lane in any report")
    if labels_checked == 0:
        problems.append("no mark's words recorded (data-labels) in any report")
    if profiles_drawn == 0:
        problems.append("no shaft_move diagram with its move's expected profile in any report")
    for p in problems:
        print("FAIL:", p)
    if not problems:
        print(f"{len(reports)} reports ({shipped} shipped, 1 failing, 1 crowded), {judged_total} judged checks, "
              f"each with a figure; {drawn_traces} timing diagrams with stimulus, count and output, "
              f"{analog_drawn} analog stator lanes, {profiles_drawn} step rates with their expected profile, "
              f"{labels_checked} marks' words apart from each other and off the traces")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
