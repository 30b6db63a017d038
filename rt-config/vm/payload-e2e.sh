#!/bin/bash
# Lane payload: hilrig end to end through the guest kernel's real interfaces. The virtual
# ANS1 is served on the far side (`hilrig serve ans1 --far far-lane.toml`: gpio-sim's
# simulator side, the resolver-emulator node on can1, Modbus RTU on ttyS2); `hilrig run
# --rig rig-lane.toml` plays the campaign on the near side (libgpiod, can0, ttyS1):
#   1. campaigns/lane/ans1_lane.toml (quadrature) and ans1_lane_resolver.toml (the resolver
#      angle stream on can0), setpoints over Modbus RTU, captured outputs: every check must
#      pass (exit 0). The rig's measured latencies are printed from results.json.
#   2. campaigns/lane/ans1_bus_off.toml: once the resolver stream is seen on the bus, can0
#      leaves it; the run must stop with the named CAN rig fault (exit 3) and keep
#      results.json and the trace.
# Arguments from guest.sh: OUT CHIP SIM_DIR; HILRIG_BUILD names the build (default: the
# checkout's build/). Each step prints what it does; each check is a PASS/FAIL line, also in
# the lane's result (HILRIG_LANE_RESULT), with the latencies as NOTE lines.
set -u
out=$1 chip=$2 sim=$3
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
hilrig="${HILRIG_BUILD:-$root/build}/hilrig"
result=${HILRIG_LANE_RESULT:-/dev/null}
e2e="$out/e2e"
mkdir -p "$e2e"
lane_name=e2e
# shellcheck source=lane-report.sh
. "$here/lane-report.sh"

[ -x "$hilrig" ] || {
  fail hilrig "$hilrig not built"
  exit 1
}
[ -n "$chip" ] && [ -d "$sim" ] || {
  fail gpio_sim "no gpio-sim chip from guest.sh"
  exit 1
}

# The rig config names the lane's chip as guest.sh usually builds it; follow the guest if not.
rig="$here/rig-lane.toml"
if ! grep -q "^chip = \"$chip\"" "$rig"; then
  sed "s/^chip = .*/chip = \"$chip\"/" "$rig" >"$e2e/rig-lane.toml"
  rig="$e2e/rig-lane.toml"
  step "rig config: chip is $chip here ($rig)"
fi

# Under QEMU the SJA1000's transmit completes late and the rig's stream catches up in bursts:
# a queue of 10 frames (the default) fills in a burst. Room for 1,000 frames.
step "can0: txqueuelen 1000"
ip link set can0 txqueuelen 1000

serve_pid=
# serve_start NAME: the far side for one campaign (a fresh board: its encoder count starts at 0).
serve_start() {
  local ready="$e2e/$1.serve-ready" i
  rm -f "$ready"
  # --byte-timeout: QEMU's emulated UART delivers a request in bursts with gaps longer than the
  # 3.5-character silence, which would otherwise end the frame early (lost requests, host-link timeouts).
  step "$1: hilrig serve ans1 --modbus-rtu /dev/ttyS2 --far far-lane.toml --gpio-sim $sim --can can1 --tick 2ms --scan 500us --byte-timeout 100ms"
  "$hilrig" serve ans1 --modbus-rtu /dev/ttyS2 --far "$here/far-lane.toml" --gpio-sim "$sim" --can can1 \
    --tick 2ms --scan 500us --byte-timeout 100ms --port-file "$ready" >"$e2e/$1.serve.log" 2>&1 &
  serve_pid=$!
  for i in $(seq 1 150); do # up to 30 s: the port file appears once it serves
    [ -s "$ready" ] && break
    kill -0 "$serve_pid" 2>/dev/null || break
    sleep 0.2
  done
  sed 's/^/[serve] /' "$e2e/$1.serve.log"
  if [ -s "$ready" ]; then pass "$1.serve"; else fail "$1.serve" "hilrig serve did not come up"; fi
  [ -s "$ready" ]
}
serve_stop() {
  [ -n "$serve_pid" ] || return 0
  kill -INT "$serve_pid" 2>/dev/null
  wait "$serve_pid" 2>/dev/null
  serve_pid=
  tail -n 1 "$e2e/$1.serve.log" | sed 's/^/[serve] /'
}
trap '[ -n "$serve_pid" ] && kill -INT "$serve_pid" 2>/dev/null' EXIT

# The rig's measured latencies (rig.* timing, crossing-to-edge latencies, host handshakes),
# as figures: this lane reports them; QEMU makes them no reference.
latencies() {
  python3 - "$1" <<'EOF' | while read -r line; do note "$2 $line"; done
import json, sys
r = json.load(open(sys.argv[1]))
for run in r.get("runs", []):
    for c in run.get("checks", []):
        for m in c.get("measurements", []):
            n = m.get("name", "")
            if m.get("unit") == "us" and m.get("value") is not None:
                print(f"{n} = {m['value']:.1f} us")
EOF
}

# checks_of RESULTS: one line per check, its outcome.
checks_of() {
  python3 - "$1" <<'EOF'
import json, sys
r = json.load(open(sys.argv[1]))
for run in r.get("runs", []):
    if run.get("error"):
        print(f"run {run.get('index')}: error: {run['error']}")
    for c in run.get("checks", []):
        print(f"{c['check']}: {c['outcome']}")
EOF
}

# functional NAME CAMPAIGN: a fresh far side, then the campaign; every check must pass.
functional() {
  local name=$1 campaign=$2 status
  serve_start "$name" || return
  step "$name: hilrig run campaigns/lane/$campaign --rig $(basename "$rig")"
  timeout 150 "$hilrig" run "$root/campaigns/lane/$campaign" --rig "$rig" --out "$e2e/$name" --progress \
    >"$e2e/$name.run.log" 2>&1
  status=$?
  sed 's/^/[run] /' "$e2e/$name.run.log"
  serve_stop "$name"
  if [ -f "$e2e/$name/results.json" ]; then
    checks_of "$e2e/$name/results.json" | sed 's/^/[e2e]   /'
    latencies "$e2e/$name/results.json" "$name"
  fi
  if [ "$status" = 0 ]; then pass "$name.checks"; else fail "$name.checks" "hilrig run exited $status (0: every check passed)"; fi
}

# ---- 1. the functional campaigns: encoder, then resolver ----
if serve_start probe; then
  step "probe: mbpoll reads status word 0 over ttyS1: the served board reports Resolver Fault before any stream"
  w0=$(mbpoll -m rtu -a 1 -b 19200 -P even -t 3 -r 1 -c 1 -1 -q /dev/ttyS1 2>&1 | sed -n 's/^\[1\]:[[:space:]]*//p')
  if [ -n "$w0" ] && [ $((w0 & 0x1000)) != 0 ]; then pass probe.mbpoll_status; else fail probe.mbpoll_status "word 0 read '$w0'"; fi
  serve_stop probe
fi
functional lane ans1_lane.toml
functional lane_resolver ans1_lane_resolver.toml

# ---- 2. can0 leaves the bus mid-stream ----
if serve_start bus_off; then
  step "bus_off: hilrig run campaigns/lane/ans1_bus_off.toml --rig $(basename "$rig") (in the background)"
  timeout 150 "$hilrig" run "$root/campaigns/lane/ans1_bus_off.toml" --rig "$rig" --out "$e2e/bus_off" --progress \
    >"$e2e/bus_off.run.log" 2>&1 &
  run_pid=$!
  # The run has started when hilrig prints its progress line; the stream runs when can1 sees it.
  for i in $(seq 1 150); do
    grep -q '^\[1/1\] run' "$e2e/bus_off.run.log" 2>/dev/null && break
    kill -0 "$run_pid" 2>/dev/null || break
    sleep 0.2
  done
  step "bus_off: waiting for 100 ResolverAngle frames (0x120) on can1"
  frames=$(timeout 30 candump -n 100 can1,120:7FF 2>/dev/null | wc -l)
  step "bus_off: saw $frames frames; ip link set can0 down"
  ip link set can0 down
  wait "$run_pid"
  status=$?
  sed 's/^/[run] /' "$e2e/bus_off.run.log"
  serve_stop bus_off
  step "bus_off: can0 back up"
  ip link set can0 up
  if [ "$status" = 3 ]; then pass bus_off.exit_3; else fail bus_off.exit_3 "hilrig run exited $status"; fi
  if grep -q 'CAN can0' "$e2e/bus_off.run.log"; then
    pass bus_off.named_fault
    note "bus_off $(grep -o 'CAN can0[^"]*' "$e2e/bus_off.run.log" | head -n 1)"
  else
    fail bus_off.named_fault "no 'CAN can0' fault in hilrig's output"
  fi
  if [ -f "$e2e/bus_off/results.json" ] && grep -q 'CAN can0' "$e2e/bus_off/results.json"; then
    pass bus_off.results_kept
  else
    fail bus_off.results_kept "results.json missing or without the fault"
  fi
  # The trace keeps the encoder edges the rig played before the fault.
  if [ -f "$e2e/bus_off/trace.vcd" ] && [ "$(grep -c '^#' "$e2e/bus_off/trace.vcd")" -gt 2 ]; then
    pass bus_off.trace_kept
  else
    fail bus_off.trace_kept "trace.vcd missing or empty"
  fi
fi

exit "$failed"
