#!/usr/bin/env python3
"""Virtual-time speed of campaigns, skipping against the scan-every-period oracle, one run after
the other: for each campaign, `HILRIG run CAMPAIGN --out DIR` and the same with --exact-scan,
alternated REPS times; prints simulated s, the median CPU s (user + system of the finished
child, getrusage: every thread, so a debounce check's probe threads too) and simulated s per
CPU s of each engine, as a Markdown table.

Simulated s counts the virtual time every run played (make_table.simulated_seconds):
campaign.end times (runs + probe runs), a debounce check's probes being whole runs of the
scenario. Where that differs from campaign.end times the runs in results.json (the older
figure), both are printed: "runs only" is that older figure.

--suite: each argument (a directory of campaigns, or several files) is run as one suite, one
process, `HILRIG run ARG --out DIR` (a directory: every *.toml under it, as hilrig run takes
it); its simulated s is the sum over every campaign's results.json in DIR. This is the figure
a nightly job pays: per-process start-up once, not once per campaign.

usage: campaign_speed.py HILRIG REPS CAMPAIGN.toml...
       campaign_speed.py --suite HILRIG REPS DIR_OR_CAMPAIGN...
"""
import json
import os
import pathlib
import resource
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from make_table import campaign_end_seconds, simulated_seconds, virtual_runs  # noqa: E402


def cpu_of(cmd):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    status = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime), status


def timed(hilrig, target, out, reps):
    """Median CPU s of each engine, alternated; the exit status of the last run."""
    times = {False: [], True: []}
    status = 0
    for _ in range(reps):
        for exact in (False, True):
            cmd = [hilrig, "run", target, "--out", out] + (["--exact-scan"] if exact else [])
            cpu, status = cpu_of(cmd)
            times[exact].append(cpu)
    return statistics.median(times[False]), statistics.median(times[True]), status


def simulated_text(sim, sim_runs_only):
    return f"{sim:g}" if abs(sim - sim_runs_only) < 1e-9 else f"{sim:g} (runs only {sim_runs_only:g})"


def per_campaign(hilrig, reps, campaigns):
    print("| campaign | simulated s | exit | skipping CPU s | x real time | --exact-scan CPU s | x real time | speed-up |")
    print("|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        for campaign in campaigns:
            out = os.path.join(work, "out")
            skip, every, status = timed(hilrig, campaign, out, reps)
            text = pathlib.Path(campaign).read_text()
            results = os.path.join(out, "results.json")
            sim, _ = simulated_seconds(text, results)
            sim_runs_only, _ = simulated_seconds(text, results, with_probes=False)
            print(f"| {pathlib.Path(campaign).stem} | {simulated_text(sim, sim_runs_only)} | {status} | {skip:.3f} "
                  f"| {sim / skip:.1f} | {every:.3f} | {sim / every:.1f} | {every / skip:.2f} |", flush=True)


def suite_totals(out):
    """(campaigns, runs, probe runs, simulated s, simulated s of the runs only) of a suite's
    outputs: every results.json under out, each campaign's end read from its campaign_file."""
    campaigns = runs = probes = 0
    sim = sim_runs_only = 0.0
    for path in sorted(pathlib.Path(out).rglob("results.json")):
        results = json.loads(path.read_text())
        end = campaign_end_seconds(pathlib.Path(results["campaign_file"]).read_text())
        r, p = virtual_runs(results)
        campaigns, runs, probes = campaigns + 1, runs + r, probes + p
        sim += end * (r + p)
        sim_runs_only += end * r
    return campaigns, runs, probes, sim, sim_runs_only


def per_suite(hilrig, reps, suites):
    print("| suite | campaigns | runs + probe runs | simulated s | exit | skipping CPU s | x real time "
          "| --exact-scan CPU s | x real time | speed-up |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        for n, suite in enumerate(suites):
            out = os.path.join(work, f"suite{n}")  # its own: a suite's outputs are read back whole
            skip, every, status = timed(hilrig, suite, out, reps)
            campaigns, runs, probes, sim, sim_runs_only = suite_totals(out)
            print(f"| {suite} | {campaigns} | {runs} + {probes} | {simulated_text(sim, sim_runs_only)} | {status} "
                  f"| {skip:.3f} | {sim / skip:.1f} | {every:.3f} | {sim / every:.1f} | {every / skip:.2f} |",
                  flush=True)


def main():
    args = sys.argv[1:]
    suite = bool(args) and args[0] == "--suite"
    if suite:
        args = args[1:]
    if len(args) < 3:
        raise SystemExit(__doc__)
    hilrig, reps, targets = args[0], int(args[1]), args[2:]
    (per_suite if suite else per_campaign)(hilrig, reps, targets)


if __name__ == "__main__":
    main()
