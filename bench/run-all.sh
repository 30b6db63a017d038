#!/usr/bin/env bash
# Runs every hilrig benchmark next to its named peer and prints ONE table (figure, hilrig,
# peer, ratio, target), also written to $BUILD_DIR/bench-table.md. `make bench` calls it after
# building the release preset; by hand: `bash bench/run-all.sh` from the repo root.
#
# Environment:
#   BUILD_DIR        build tree holding hilrig and bench/ (default build-release)
#   BENCH_RT_SECONDS latency measured by each of hilrig and cyclictest, in seconds (default 10)
#   BENCH_RT_ROUNDS  alternating rounds the latency seconds are cut into (default 5)
#   BENCH_RT_PRIO    SCHED_FIFO priority of both (default 80)
#   BENCH_RT_CPU     CPU both are pinned to (default: the last CPU)
#   BENCH_REPS       Google Benchmark repetitions; the median is reported (default 5)
#   BENCH_VM         0 skips figures 6a/6b, which boot the RT VM lane (default 1)
#   BENCH_VM_WORK    the lane's work dir for 6a/6b (default build-vm, shared with make test-vm)
#   BENCH_CAN_FRAMES, BENCH_GPIO_EDGES, BENCH_ROUNDS  size 6a/6b (rt-config/vm/payload-bench.sh)
set -euo pipefail

cd "$(dirname "$0")/.."
ROOT=$PWD
BUILD_DIR=${BUILD_DIR:-build-release}
RT_S=${BENCH_RT_SECONDS:-10}
RT_PRIO=${BENCH_RT_PRIO:-80}
RT_CPU=${BENCH_RT_CPU:-$(($(nproc) - 1))}
REPS=${BENCH_REPS:-5}
# Raw outputs (benchmark JSON, latency histograms, /usr/bin/time -v, results.json) are kept
# next to the table, so every figure can be traced back to what produced it.
WORK=$BUILD_DIR/bench-raw
rm -rf "$WORK"
mkdir -p "$WORK"

HILRIG=$BUILD_DIR/hilrig
for f in "$HILRIG" "$BUILD_DIR/bench/scheduler/bench_scheduler" \
  "$BUILD_DIR/bench/quadrature_bound/bench_quadrature_bound"; do
  [[ -x $f ]] || { echo "run-all.sh: $f is missing; build the release preset first" >&2; exit 2; }
done

say() { echo "run-all.sh: $*" >&2; }

# --- machine, as the table is read against it -------------------------------------------
{
  echo "nproc=$(nproc)"
  echo "cpu=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')"
  echo "kernel=$(uname -r)$(uname -v | grep -q PREEMPT_RT && echo ' PREEMPT_RT' || echo ' (not PREEMPT_RT)')"
  echo "load_before=$(cut -d' ' -f1-3 /proc/loadavg)"
  echo "date=$(date -u +%Y-%m-%dT%H:%M:%SZ)"
} >"$WORK/machine"

gbench() { # binary filter out.json
  "$1" --benchmark_filter="$2" --benchmark_repetitions="$REPS" \
    --benchmark_report_aggregates_only=true --benchmark_format=json >"$3" 2>"$3.err"
}

# --- 1. scheduler hold model, 1,000 pending ------------------------------------------------
say "scheduler (bench/scheduler)"
gbench "$BUILD_DIR/bench/scheduler/bench_scheduler" 'BM_SchedulerHold/1000$' "$WORK/sched.json"

# --- 2. quadrature edges vs writing the same records ---------------------------------------
say "quadrature edges vs store bandwidth (bench/quadrature_bound)"
gbench "$BUILD_DIR/bench/quadrature_bound/bench_quadrature_bound" '.' "$WORK/quad.json"
# bench/signals' own trapezoid figure, for cross-checking (same solver, same profile).
if [[ -x $BUILD_DIR/bench/signals/bench_signals ]]; then
  gbench "$BUILD_DIR/bench/signals/bench_signals" 'BM_TrapezoidEdges$' "$WORK/signals.json" || true
fi

# --- 3. RT loop vs cyclictest, same duration/priority/CPU, in alternating rounds ------------
# The host's load moves from second to second, so the run is cut into rounds that alternate
# who goes first; each side's histograms are summed over its rounds (make_table.py), and both
# see the same stretch of the machine's load.
RT_ROUNDS=${BENCH_RT_ROUNDS:-5}
slice=$((RT_S / RT_ROUNDS))
((slice >= 1)) || slice=1
say "latency: hilrig and cyclictest, $RT_ROUNDS alternating rounds of ${slice}s each, priority $RT_PRIO, cpu $RT_CPU"
command -v cyclictest >/dev/null || echo "cyclictest not installed (Debian rt-tests)" >"$WORK/cyclictest-missing"
rt_hilrig() {
  "$HILRIG" latency --duration "$slice" --priority "$RT_PRIO" --cpu "$RT_CPU" --interval 1000 \
    >"$WORK/hilrig-latency-$1.txt" 2>&1 || echo "exit=$?" >>"$WORK/hilrig-latency-$1.txt"
}
rt_cyclictest() {
  [[ -f $WORK/cyclictest-missing ]] && return 0
  cyclictest -m -p "$RT_PRIO" -a "$RT_CPU" -i 1000 -D "$slice" -q -h 1000 \
    >"$WORK/cyclictest-$1.txt" 2>&1 || echo "exit=$?" >>"$WORK/cyclictest-$1.txt"
}
for r in $(seq 1 "$RT_ROUNDS"); do
  if ((r % 2)); then rt_hilrig "$r"; rt_cyclictest "$r"; else rt_cyclictest "$r"; rt_hilrig "$r"; fi
done
cat "$WORK"/hilrig-latency-*.txt >"$WORK/hilrig-latency.txt"
if [[ -f $WORK/cyclictest-missing ]]; then cp "$WORK/cyclictest-missing" "$WORK/cyclictest.txt"; else cat "$WORK"/cyclictest-*.txt >"$WORK/cyclictest.txt"; fi

# --- 4./5. ANS1 press campaign: virtual-time speed and peak RSS, 1x and 10x -------------------
# The bench's own campaign, named: a glob over campaigns/ans1/ would pick up whichever press
# campaign sorts first (the plant campaign, since it shipped), and the figures would move.
CAMPAIGN=$ROOT/bench/campaigns/ans1_press.toml
python3 "$ROOT/bench/lengthen_campaign.py" "$CAMPAIGN" 10 >"$WORK/press_x10.toml"
say "campaign $CAMPAIGN, 1x and 10x"
for v in x1 x10; do
  file=$CAMPAIGN
  [[ $v == x10 ]] && file=$WORK/press_x10.toml
  /usr/bin/time -v "$HILRIG" run "$file" --out "$WORK/out-$v" >"$WORK/run-$v.txt" 2>"$WORK/time-$v.txt" ||
    echo "$?" >"$WORK/exit-$v"
done

# --- 4c./4d. plant campaigns: simulated seconds per CPU second (user + system) ---------------
# A plant closes the loop in virtual time: the press plant (one replan per valve input) and the
# stepper load (one replan per step pulse, 25,600 of them).
for v in ans1/ans1_press_plant smd23e/smd23e_load_too_fast; do
  name=$(basename "$v")
  /usr/bin/time -v "$HILRIG" run "$ROOT/campaigns/$v.toml" --out "$WORK/out-$name" >"$WORK/run-$name.txt" \
    2>"$WORK/time-$name.txt" || echo "$?" >"$WORK/exit-$name"
done

# --- 4e. standstill: the shipped suite with every campaign.end 10x, the motion as shipped ----
# (the shaft then stands still), against the suite as shipped: one process each, CPU s.
# campaigns/lane is left out (it runs on the virtual bus too) so that the figure measures the
# same suite as the hand measurement in docs/PERFORMANCE.md.
for v in x1 x10; do
  rm -rf "$WORK/suite-$v" && mkdir -p "$WORK/suite-$v"
  for c in "$ROOT"/campaigns/*/*.toml; do
    [[ $c == */campaigns/lane/* ]] && continue
    d=$WORK/suite-$v/$(basename "$(dirname "$c")") && mkdir -p "$d"
    if [[ $v == x1 ]]; then cp "$c" "$d/"; else python3 "$ROOT/bench/lengthen_campaign.py" --standstill "$c" 10 >"$d/$(basename "$c")"; fi
  done
  say "suite, campaign.end $v (standstill after the motion)"
  /usr/bin/time -v "$HILRIG" run "$WORK/suite-$v" --out "$WORK/out-suite-$v" >"$WORK/run-suite-$v.txt" \
    2>"$WORK/time-suite-$v.txt" || echo "$?" >"$WORK/exit-suite-$v"
done

# --- 6a./6b. CAN frames and GPIO edges: SocketCAN and gpio-sim exist only in the RT VM lane --
# rt-config/vm/payload-bench.sh runs bench_can_frames next to cangen -> candump on vcan0 and
# bench_gpio_edges (gpiod backend vs bare libgpiod) on a gpio-sim line, inside the guest.
# BENCH_VM=0 skips it; BENCH_VM_WORK is the lane's work dir (kernel and module cache).
if [[ ${BENCH_VM:-1} == 0 ]]; then
  echo "BENCH_VM=0" >"$WORK/lane-skipped"
elif [[ ! -x $BUILD_DIR/bench/can_frames/bench_can_frames || ! -x $BUILD_DIR/bench/gpio_edges/bench_gpio_edges ]]; then
  echo "bench_can_frames/bench_gpio_edges not built" >"$WORK/lane-skipped"
elif ! bash "$ROOT/scripts/install-deps.sh" --vm >"$WORK/lane-deps.txt" 2>&1; then
  echo "the lane's packages are missing (scripts/install-deps.sh --vm, as root)" >"$WORK/lane-skipped"
else
  say "CAN frames and GPIO edges inside the RT VM lane (QEMU TCG, about 2 min)"
  vm_work=${BENCH_VM_WORK:-$ROOT/build-vm} # shares make test-vm's cache
  # The payload reads its tree from HILRIG_BUILD: a one-line wrapper sets it, however the lane
  # passes (or does not pass) the host's environment into the guest.
  {
    echo '#!/bin/bash'
    printf 'export HILRIG_BUILD=%q\n' "$(cd "$BUILD_DIR" && pwd)"
    for v in BENCH_CAN_FRAMES BENCH_GPIO_EDGES BENCH_ROUNDS; do
      [[ -n ${!v:-} ]] && printf 'export %s=%q\n' "$v" "${!v}"
    done
    printf 'exec bash %q "$@"\n' "$ROOT/rt-config/vm/payload-bench.sh"
  } >"$WORK/lane-payload.sh"
  HILRIG_BUILD=$(cd "$BUILD_DIR" && pwd) bash "$ROOT/rt-config/vm/run-lane.sh" "$vm_work" "$WORK/lane-payload.sh" \
    >"$WORK/lane.txt" 2>&1 ||
    echo "exit=$?" >>"$WORK/lane.txt"
  if [[ -f $vm_work/out/bench/summary ]]; then
    cp -r "$vm_work/out/bench" "$WORK/lane-bench"
  else
    echo "the lane gave no bench summary: $WORK/lane.txt" >"$WORK/lane-skipped"
  fi
fi

rm -f "$WORK"/out-*/trace*.vcd # tens of MB each; rerun the campaign to look at one
echo "load_after=$(cut -d' ' -f1-3 /proc/loadavg)" >>"$WORK/machine"

python3 "$ROOT/bench/make_table.py" "$WORK" "$CAMPAIGN" "$RT_S" "$RT_PRIO" "$RT_CPU" | tee "$BUILD_DIR/bench-table.md"
