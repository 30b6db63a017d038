#!/usr/bin/env python3
"""Checks that can-utils' log2asc reads hilrig's candump logs back frame for frame.

  candump_log2asc.py LOG2ASC FIXTURE
runs FIXTURE DIR (tests/tools/candump_fixture: DIR/bus.log and DIR/expected.txt), converts
bus.log with `log2asc -I bus.log -O bus.asc can0` and compares each ASC line (ID, extended,
remote, FD, BRS, ESI, length, data, time relative to the first frame in microseconds)
with expected.txt, which the fixture took from the trace recorder, not from the log.
"""
import os
import subprocess
import sys
import tempfile


def parse_asc(text):
    frames = []
    for line in text.splitlines():
        f = line.split()
        if not f or not f[0][0].isdigit():
            continue  # header lines: date, base, ...
        t = round(float(f[0]) * 1e6)
        if f[1] == "CANFD":
            # time CANFD channel Rx id brs esi dlc len data...
            ident, brs, esi, length = f[4], f[5] == "1", f[6] == "1", int(f[8])
            data = "".join(f[9:9 + length]) or "-"
            frames.append((t, ident.rstrip("x").lower().lstrip("0") or "0", ident.endswith("x"), False, True,
                           brs, esi, length, data))
        else:
            # time channel id Rx d|r dlc data...
            ident, kind, length = f[2], f[4], int(f[5])
            rtr = kind == "r"
            data = "-" if rtr or length == 0 else "".join(f[6:6 + length])
            frames.append((t, ident.rstrip("x").lower().lstrip("0") or "0", ident.endswith("x"), rtr, False,
                           False, False, length, data))
    return frames


def parse_expected(text):
    frames, first = [], None
    for line in text.splitlines():
        f = line.split()
        if not f:
            continue
        t_us = int(f[0]) // 1000  # candump keeps microseconds, truncated
        first = t_us if first is None else first
        frames.append((t_us - first, f[1].lower().lstrip("0") or "0", f[2] == "1", f[3] == "1", f[4] == "1",
                       f[5] == "1", f[6] == "1", int(f[7]), f[8]))
    return frames


def main(argv):
    if len(argv) != 3:
        print(__doc__)
        return 2
    log2asc, fixture = argv[1], argv[2]
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([fixture, tmp], check=True)
        asc = os.path.join(tmp, "bus.asc")
        subprocess.run([log2asc, "-I", os.path.join(tmp, "bus.log"), "-O", asc, "can0"], check=True)
        got = parse_asc(open(asc).read())
        want = parse_expected(open(os.path.join(tmp, "expected.txt")).read())
    bad = sum(1 for g, w in zip(got, want) if g != w) + abs(len(got) - len(want))
    for g, w in zip(got, want):
        if g != w:
            print(f"log2asc read {g}, expected {w}")
            break
    print(f"{len(want)} frames expected, {len(got)} read by log2asc")
    print(f"{len(want) - bad if bad <= len(want) else 0} passed, {bad} failed")
    return 1 if bad or not want else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
