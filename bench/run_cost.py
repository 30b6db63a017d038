#!/usr/bin/env python3
"""The whole cost of one `hilrig run` process (start-up, campaign, outputs, exit) for several
hilrig binaries, run in turn N times each so that the machine's load falls on all alike:
prints each binary's minimum and median CPU ms (user + system of the finished child,
getrusage). For comparing builds on the fixed cost of a short campaign (docs/PERFORMANCE.md,
"Fixed cost of a run").

usage: run_cost.py N CAMPAIGN.toml HILRIG...
"""
import resource
import statistics
import subprocess
import sys
import tempfile


def main():
    if len(sys.argv) < 4:
        raise SystemExit(__doc__)
    n, campaign, binaries = int(sys.argv[1]), sys.argv[2], sys.argv[3:]
    cpu = {i: [] for i in range(len(binaries))}
    with tempfile.TemporaryDirectory() as work:
        for _ in range(n):
            for i, hilrig in enumerate(binaries):
                before = resource.getrusage(resource.RUSAGE_CHILDREN)
                subprocess.run([hilrig, "run", campaign, "--out", f"{work}/out{i}"], stdout=subprocess.DEVNULL,
                               check=True)
                after = resource.getrusage(resource.RUSAGE_CHILDREN)
                cpu[i].append((after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime))
    print("| binary | CPU ms, min | CPU ms, median |")
    print("|---|---|---|")
    for i, hilrig in enumerate(binaries):
        print(f"| {hilrig} | {1e3 * min(cpu[i]):.1f} | {1e3 * statistics.median(cpu[i]):.1f} |")


if __name__ == "__main__":
    main()
