#!/usr/bin/env python3
"""report.html as a person opens it (issue 18, "Done when"): every shipped campaign is run
as one suite and each campaign's report is loaded in one headless Chromium (driven over its
DevTools pipe, so one browser start serves every page). In the DOM Chromium built, with every
run expanded, each check section that was judged (data-judgement is not "not judged") must
hold a figure whose SVG the browser laid out with a size; the sections must be as many as
results.json's checks; a failing campaign's summary must link each failed check. A
screenshot of each report is written beside it (report.png).

Usage: check_report_browser.py HILRIG SOURCE_DIR SCRATCH_DIR CHROMIUM
"""
import base64
import json
import os
import pathlib
import shutil
import subprocess
import sys

# Per check section: its word, and how many figures hold an SVG laid out with a size. Then
# the summary's links to failed checks, each pointing at a section that exists.
INSPECT = """JSON.stringify((() => {
  document.querySelectorAll('details').forEach(d => { d.open = true; });
  const laidOut = e => e.getBoundingClientRect().width > 0 && e.getBoundingClientRect().height > 0;
  // A timing diagram: its lanes by role, and whether its expected window and limit are drawn
  // inside the figure's box.
  const timing = svg => {
    const box = svg.getBoundingClientRect();
    const inside = e => { const r = e.getBoundingClientRect();
      return r.left >= box.left - 1 && r.right <= box.right + 1 && r.top >= box.top - 1 && r.bottom <= box.bottom + 1; };
    const lanes = role => [...svg.querySelectorAll('g.lane.' + role)].filter(laidOut).map(g => g.dataset.lane);
    return {stimulus: lanes('stimulus'), count: lanes('count'), output: lanes('output'), rate: lanes('rate'),
            expected: [...svg.querySelectorAll('rect.expected')].filter(inside).length,
            limits: [...svg.querySelectorAll('line.limit')].filter(inside).length};
  };
  const sections = [...document.querySelectorAll('section.check')].map(s => [
    s.dataset.judgement,
    [...s.querySelectorAll('figure.evidence > svg')].filter(laidOut).length,
    [...s.querySelectorAll('figure.evidence > svg')].filter(g => g.querySelector('g.lane')).map(timing)]);
  const links = [...document.querySelectorAll('ul.failures a')].map(a => a.getAttribute('href'));
  const dangling = links.filter(h => !document.getElementById(h.slice(1)));
  return {sections, links, dangling};
})())"""


# Checks judged against the shaft: their diagrams show the encoder (stimulus) and the count.
ON_SHAFT = ("throughput", "edge_at_position", "advance_counts")


def timing_problems(name, check, timings, encoder):
    """Each window results.json cut a trace for is one diagram with the run's lanes in it: the
    stimulus (enc.A/enc.B, when the campaign wires the encoder: a resolver board's stators are
    not drawn) and shaft.count for a check on the shaft, the check's output line,
    and its expected window and limit drawn inside the figure (a limitless time: none); a
    shaft_move also its step rate against time."""
    traces = check.get("traces", [])
    out = []
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
        if check["kind"] in ON_SHAFT and encoder and t["stimulus"] != ["enc.A", "enc.B"]:
            out.append(f"{name}: {check['check']}: stimulus lanes {t['stimulus']}, not the encoder's A/B")
        if check["kind"] == "shaft_move" and len(t["rate"]) != 1:
            out.append(f"{name}: {check['check']}: no step rate against time in its timing diagram")
        if not t["output"]:
            out.append(f"{name}: {check['check']}: no output lane in its timing diagram")
        if t["expected"] > 1 or (t["expected"] == 1) != (t["limits"] > 0):
            out.append(f"{name}: {check['check']}: expected window {t['expected']}, limit lines {t['limits']}")
    return out


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
    # A failing campaign (none is shipped): ans1_brake with the rig's stop-time limit below
    # the 100 ms stop the board makes, so the check fails and its figure must be there.
    failing = scratch / "failing.toml"
    failing.write_text(pathlib.Path(src, "campaigns/ans1/ans1_brake.toml").read_text().replace(
        "limit_ms = 150", "limit_ms = 50", 1))
    subprocess.run([hilrig, "run", str(failing), "--out", str(scratch / "failing")], capture_output=True)
    if not (scratch / "failing" / "report.html").exists():
        problems.append("the failing campaign wrote no report")
    else:
        reports.append(scratch / "failing" / "report.html")

    sources = {p.stem: p for p in pathlib.Path(src, "campaigns").rglob("*.toml")}
    browser = Browser(chromium, scratch / "chromium-profile")
    judged_total = 0
    drawn_traces = 0
    try:
        for report in reports:
            name = report.parent.name
            found = browser.inspect(report, report.parent / "report.png")
            results = json.loads((report.parent / "results.json").read_text())
            checks = [c for run in results["runs"] for c in run["checks"]]
            toml = sources.get(name, failing if name == "failing" else None)
            encoder = toml is not None and 'rig = "enc.A"' in toml.read_text()
            if len(found["sections"]) != len(checks):
                problems.append(f"{name}: {len(found['sections'])} check sections, {len(checks)} in results.json")
            for (word, figures, timings), c in zip(found["sections"], checks):
                problems += timing_problems(name, c, timings, encoder)
                drawn_traces += len(c.get("traces", []))
                if word != c["outcome"]:
                    problems.append(f"{name}: {c['check']} reads {word}, results.json {c['outcome']}")
                if word != "not judged":
                    judged_total += 1
                    if figures == 0:
                        problems.append(f"{name}: {c['check']} ({word}) has no figure laid out")
            bad = sum(1 for c in checks if c["outcome"] in ("fail", "error"))
            if len(found["links"]) < bad or found["dangling"]:
                problems.append(f"{name}: {bad} failed checks, summary links {found['links']}, "
                                f"dangling {found['dangling']}")
            if report.parent.name == "failing" and bad == 0:
                problems.append("the failing campaign has no failed check")
            png = report.parent / "report.png"
            if png.read_bytes()[:8] != b"\x89PNG\r\n\x1a\n":
                problems.append(f"{name}: no screenshot")
    finally:
        browser.close()
    if drawn_traces == 0:
        problems.append("no timing diagram with the run's trace in any report")
    for p in problems:
        print("FAIL:", p)
    if not problems:
        print(f"{len(reports)} reports ({shipped} shipped, 1 failing), {judged_total} judged checks, "
              f"each with a figure; {drawn_traces} timing diagrams with stimulus, count and output")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
