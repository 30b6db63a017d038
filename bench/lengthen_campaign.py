#!/usr/bin/env python3
"""Prints a campaign file made FACTOR times longer in virtual time (for the RSS-growth figure):
campaign.end is scaled, and so is the motion that fills it: a press_stroke's `strokes`, or
else every `duration` of [[motion.move]]. Text edits only, so the file keeps its comments.
With --standstill only campaign.end is scaled: the motion is as shipped and the shaft then
stands still (the standstill figure, 4e: a longer standstill should cost ~nothing).

usage: lengthen_campaign.py [--standstill] CAMPAIGN.toml FACTOR"""
import re
import sys

UNITS = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}


def scale_duration(text, factor):
    m = re.fullmatch(r"([0-9.]+)(ns|us|ms|s)", text)
    if not m:
        raise SystemExit(f"lengthen_campaign: not a duration: {text}")
    return f"{float(m.group(1)) * UNITS[m.group(2)] * factor * 1e3:g}ms"


def main():
    args = sys.argv[1:]
    standstill = args[:1] == ["--standstill"]
    if standstill:
        args = args[1:]
    path, factor = args[0], int(args[1])
    lines = open(path, encoding="utf-8").read().splitlines()
    has_strokes = any(re.match(r"\s*strokes\s*=", l) for l in lines)
    table = ""
    out = []
    for line in lines:
        head = re.match(r"\s*\[+([^\]]+)\]+", line)
        if head:
            table = head.group(1).strip()
        m = re.match(r'(\s*)(end|duration)(\s*=\s*)"([^"]+)"(.*)', line)
        if m and ((table == "campaign" and m.group(2) == "end") or
                  (table == "motion.move" and m.group(2) == "duration" and not has_strokes and not standstill)):
            line = f'{m.group(1)}{m.group(2)}{m.group(3)}"{scale_duration(m.group(4), factor)}"{m.group(5)}'
        m = re.match(r"(\s*strokes\s*=\s*)([0-9]+)(.*)", line)
        if m and table == "motion.move" and not standstill:
            line = f"{m.group(1)}{int(m.group(2)) * factor}{m.group(3)}"
        out.append(line)
    print("\n".join(out))


if __name__ == "__main__":
    main()
