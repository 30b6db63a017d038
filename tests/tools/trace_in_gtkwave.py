#!/usr/bin/env python3
"""trace.vcd as a person opens it: a failing campaign's VCD converts with GTKWave's vcd2fst and
keeps its integer and real signals, carries the shaft, the stators, the host's words and a
marker wire per check window, and each failed check has a .gtkw that opens on its window;
a second run into the same --out removes the first run's trace files.

  trace_in_gtkwave.py HILRIG VCD2FST FST2VCD SOURCE_DIR SCRATCH_DIR

Expected values come from the campaign (campaigns/ans1/ans1_resolver.toml), not from hilrig:
90 lines = 360 counts a turn at 100 rpm for 1000 ms is 600 counts; each stator at an
excitation peak is amplitude * ratio (1.0 * 0.95) times sin or cos of the shaft angle, so
sin^2 + cos^2 = 0.9025 at every peak, one peak every 1/5000 s.
"""
import json
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vcd_reader import read_vcd  # noqa: E402


def fail(msg):
    print("FAIL:", msg)
    sys.exit(1)


def main(hilrig, vcd2fst, fst2vcd, src, scratch):
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    campaign = os.path.join(src, "campaigns", "ans1", "ans1_resolver.toml")
    text = open(campaign).read()
    # The "on" setpoint is programmed at 100 counts: judging it at 110 fails it.
    bad = os.path.join(scratch, "bad.toml")
    open(bad, "w").write(text.replace("position = 100\n", "position = 110\n", 1))
    out = os.path.join(scratch, "out")
    status = subprocess.run([hilrig, "run", bad, "--out", out], capture_output=True).returncode
    if status != 1:
        fail(f"the failing campaign exited {status}, not 1")
    results = json.load(open(os.path.join(out, "results.json")))
    run0 = results["runs"][0]
    vcd = os.path.join(out, "trace-run0.vcd")

    # 1. GTKWave's own converter reads it, and the round trip keeps integer and real signals.
    fst = os.path.join(scratch, "trace.fst")
    subprocess.run([vcd2fst, vcd, fst], check=True, capture_output=True)
    back = subprocess.run([fst2vcd, fst], check=True, capture_output=True, text=True).stdout
    kinds = set(re.findall(r"\$var (\w+) ", back))
    if not {"integer", "real", "wire"} <= kinds:
        fail(f"after vcd2fst/fst2vcd the variable kinds are {sorted(kinds)}")

    declared, changes = read_vcd(open(vcd).read())
    for name, kind in [("shaft.count", "integer"), ("shaft.position", "integer"), ("resolver.sin", "real"),
                       ("resolver.cos", "real"), ("host.transmit", "wire"), ("host.acknowledge", "wire"),
                       ("host.out0", "integer"), ("host.in0", "integer"), ("check.on", "wire")]:
        if name not in declared or declared[name][0] != kind:
            fail(f"{name} is not a {kind} signal: {declared.get(name)}")

    def series(name):
        return [(t, v) for t, n, v in changes if n == name]

    # 2. The shaft: 600 counts at the end, position = count mod 360.
    count = series("shaft.count")
    if count[-1] != (1_000_000_000, 600):
        fail(f"shaft.count ends {count[-1]}, expected 600 at 1000 ms")
    position = dict(series("shaft.position"))
    for t, c in count:
        if position.get(t) != c % 360:
            fail(f"shaft.position at {t} is {position.get(t)}, count {c}")

    # 3. The stators at every excitation peak (after the initial value at 0).
    sin = [(t, v) for t, v in series("resolver.sin") if t > 0]
    cos = dict(series("resolver.cos"))
    if len(sin) != 5000:
        fail(f"{len(sin)} stator samples in 1 s at 5 kHz")
    for t, s in sin:
        if abs(s * s + cos[t] ** 2 - 0.95 ** 2) > 1e-9:
            fail(f"stators at {t}: {s}, {cos[t]}: not 0.95 in magnitude")
    if any((b[0] - a[0]) != 200_000 for a, b in zip(sin, sin[1:])):
        fail("stator samples are not one excitation period (200 us) apart")

    # 4. The host: Transmit rises with the write of the setpoints (10 ms), Acknowledge answers.
    transmit = [(t, v) for t, v in series("host.transmit") if v == 1]
    if not transmit or transmit[0][0] != 10_000_000:
        fail(f"host.transmit: {transmit[:3]}")
    if not any(v == 1 for t, v in series("host.acknowledge")):
        fail("host.acknowledge never set")

    # 5. A marker wire per check: high exactly over the windows results.json gives.
    on = next(c for c in run0["checks"] if c["check"] == "on")
    windows = sorted((m["window"]["begin_ns"], m["window"]["end_ns"]) for m in on["measurements"] if m["window"])
    marks = series("check.on")[1:]  # after its initial 0
    rises = [t for t, v in marks if v == 1]
    falls = [t for t, v in marks if v == 0]
    if not windows or rises[0] != windows[0][0] or falls[-1] != max(max(e, b + 1) for b, e in windows):
        fail(f"check.on marks {marks[:4]}..., windows {windows[:2]}...")

    # 6. One save file per failed check, opening on the first failed window.
    gtkws = sorted(f for f in os.listdir(out) if f.endswith(".gtkw"))
    failed = sorted(f"trace-run0.{c['check']}.gtkw" for c in run0["checks"] if c["outcome"] in ("fail", "error"))
    if gtkws != failed or not failed:
        fail(f"save files {gtkws}, failed checks {failed}")
    save = open(os.path.join(out, "trace-run0.on.gtkw")).read()
    first = next(m for m in on["measurements"] if m["outcome"] != "pass" and m["window"])
    begin, end = first["window"]["begin_ns"], first["window"]["end_ns"]
    if '[dumpfile] "trace-run0.vcd"' not in save:
        fail("the save file does not name its VCD")
    star = re.search(r"^\*(-?[0-9.]+) (-?\d+) (-?\d+) (-?\d+)", save, re.M)
    if not star or (int(star.group(3)), int(star.group(4))) != (begin, end):
        fail(f"markers A/B {star and star.groups()} are not the window {begin}..{end}")
    start = int(re.search(r"^\[timestart\] (\d+)", save, re.M).group(1))
    if not start <= min(begin, int(star.group(2))):
        fail(f"the view starts at {start}, after the window {begin}")
    for name in ("ls1", "shaft.count", "resolver.sin", "check.on"):
        if f"\n{name}\n" not in save:
            fail(f"the save file does not show {name}")

    # 7. The passing campaign into the same --out: the failing run's traces are gone.
    status = subprocess.run([hilrig, "run", campaign, "--out", out], capture_output=True).returncode
    if status != 0:
        fail(f"the shipped campaign exited {status}")
    left = sorted(f for f in os.listdir(out) if f.endswith(".gtkw") or f.startswith("trace-run"))
    if left:
        fail(f"stale trace files left: {left}")
    print("trace.vcd: vcd2fst reads it; shaft, stators, host words, check windows and .gtkw views as expected")


if __name__ == "__main__":
    if len(sys.argv) != 6:
        print(__doc__)
        sys.exit(2)
    main(*sys.argv[1:])
