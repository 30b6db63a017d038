#!/usr/bin/env python3
"""Virtual-time speed of campaigns, skipping against the scan-every-period oracle, one run after
the other: for each campaign, `HILRIG run CAMPAIGN --out DIR` and the same with --exact-scan,
alternated REPS times; prints simulated s (campaign.end times the runs made, as make_table.py
counts it), the median CPU s (user + system of the finished child, getrusage) and simulated s
per CPU s of each engine, as a Markdown table.

usage: campaign_speed.py HILRIG REPS CAMPAIGN.toml...
"""
import os
import pathlib
import resource
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from make_table import simulated_seconds  # noqa: E402


def cpu_of(cmd):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    status = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime), status


def main():
    hilrig, reps, campaigns = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
    print("| campaign | simulated s | exit | skipping CPU s | x real time | --exact-scan CPU s | x real time | speed-up |")
    print("|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        for campaign in campaigns:
            out = os.path.join(work, "out")
            times = {False: [], True: []}
            status = 0
            for _ in range(reps):
                for exact in (False, True):
                    cmd = [hilrig, "run", campaign, "--out", out] + (["--exact-scan"] if exact else [])
                    cpu, status = cpu_of(cmd)
                    times[exact].append(cpu)
            sim, _ = simulated_seconds(pathlib.Path(campaign).read_text(), os.path.join(out, "results.json"))
            skip, every = statistics.median(times[False]), statistics.median(times[True])
            print(f"| {pathlib.Path(campaign).stem} | {sim:g} | {status} | {skip:.3f} | {sim / skip:.1f} "
                  f"| {every:.3f} | {sim / every:.1f} | {every / skip:.2f} |", flush=True)


if __name__ == "__main__":
    main()
