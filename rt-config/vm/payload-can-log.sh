#!/bin/bash
# Lane payload: can.log as can-utils' canplayer reads it (issue 18; log2asc is read on the host
# by test_can_log, canplayer needs a CAN interface). hilrig runs a shipped campaign whose board
# reads a resolver on CAN (campaigns/pls2700/pls2700_faults.toml: 9 runs, laid end to end in
# one log) with a fixed --epoch; canplayer replays its can.log by the log's own timestamps onto
# vcan0 (`vcan0=can0`: the frames logged on can0 are sent on vcan0) while candump -L records
# vcan0. Checks: canplayer exits 0; the frames recorded are the log's (identifier and data, in
# order, none missing or added); the last frame arrives no sooner than the log's span after
# canplayer started (it waited on the timestamps: it read them as times).
# Arguments from guest.sh: OUT CHIP SIM_DIR; HILRIG_BUILD names the build (default: the
# checkout's build/). Each check is a PASS/FAIL line, also in the lane's result.
set -u
out=$1
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
hilrig="${HILRIG_BUILD:-$root/build}/hilrig"
result=${HILRIG_LANE_RESULT:-/dev/null}
dir="$out/can-log"
rm -rf "$dir" && mkdir -p "$dir"
lane_name=can_log
# shellcheck source=lane-report.sh
. "$here/lane-report.sh"

campaign=campaigns/pls2700/pls2700_faults.toml
step "hilrig run $campaign --epoch 1767225600 --trace none"
"$hilrig" run "$root/$campaign" --epoch 1767225600 --trace none --out "$dir/run" >"$dir/run.log" 2>&1
status=$?
sed 's/^/[run] /' "$dir/run.log"
log="$dir/run/can.log"
if [ "$status" = 0 ] && [ -s "$log" ]; then pass written; else
  fail written "hilrig run exited $status, can.log $( [ -s "$log" ] && echo present || echo missing)"
  exit 1
fi

# Bracket the replay with a sentinel frame the log does not carry: candump is bound once it
# has recorded the first; the second (sent after canplayer returned) follows every replayed frame.
sentinel=7FF
if grep -q " $sentinel#" "$log"; then
  fail sentinel "the log itself carries identifier $sentinel"
  exit 1
fi
# Under TCG candump keeps up with a 1 kHz stream only with a deep socket buffer (-r, 32 MiB)
# and its lines going to the guest's tmpfs (/run), not through 9p line by line.
dump=/run/can-log-vcan0.log
step "candump -L -r 33554432 vcan0 (line-buffered, to $dump), bound once it records $sentinel#01"
stdbuf -oL candump -L -r 33554432 vcan0 >"$dump" 2>"$dir/candump.err" &
dumper=$!
trap 'kill "$dumper" 2>/dev/null' EXIT
bracket() { # bracket DATA: send the sentinel until candump has it (at most 10 s)
  local i
  for i in $(seq 50); do
    cansend vcan0 "$sentinel#$1"
    sleep 0.2
    grep -q " $sentinel#$1\$" "$dump" && return 0
  done
  return 1
}
bracket 01 || {
  fail candump "candump recorded nothing on vcan0: $(cat "$dir/candump.err")"
  exit 1
}

frames=$(wc -l <"$log")
step "canplayer -I can.log vcan0=can0 ($frames frames, by the log's timestamps)"
start=$(date +%s.%N)
timeout 120 canplayer -I "$log" vcan0=can0 >"$dir/canplayer.out" 2>&1
status=$?
took=$(echo "$(date +%s.%N) - $start" | bc)
if [ "$status" = 0 ]; then pass canplayer_exit; else fail canplayer_exit "canplayer exited $status: $(head -c 300 "$dir/canplayer.out")"; fi
bracket 02 || fail candump_end "candump never recorded the closing $sentinel#02"
kill "$dumper" 2>/dev/null
wait "$dumper" 2>/dev/null
trap - EXIT
cp "$dump" "$dir/vcan0.log"
dump="$dir/vcan0.log"

# The replayed frames: between the two sentinels (the opening one may have been recorded more
# than once), on vcan0.
sed -n "/ $sentinel#01\$/,/ $sentinel#02\$/p" "$dump" | grep -v " $sentinel#0[12]\$" >"$dir/replayed.log"
awk '{print $3}' "$log" >"$dir/expected.frames"
awk '{print $3}' "$dir/replayed.log" >"$dir/replayed.frames"
got=$(wc -l <"$dir/replayed.frames")
if cmp -s "$dir/expected.frames" "$dir/replayed.frames"; then
  pass frames_in_order
else
  fail frames_in_order "$got of $frames frames; first difference: $(diff "$dir/expected.frames" "$dir/replayed.frames" | head -n 3 | tr '\n' ' ')"
fi
if awk '$2 != "vcan0" {bad = 1} END {exit bad}' "$dir/replayed.log"; then pass on_vcan0; else fail on_vcan0 "a replayed frame not on vcan0"; fi

# canplayer sends each frame no earlier than its offset from the log's first after it started:
# the last frame arrives at least the log's span after canplayer was started (candump -L's
# times are the kernel's receive times, on the same clock as date).
log_span=$(awk 'NR == 1 {gsub(/[()]/, "", $1); a = $1} {gsub(/[()]/, "", $1); b = $1} END {printf "%.6f", b - a}' "$log")
last=$(tail -n 1 "$dir/replayed.log" | awk '{gsub(/[()]/, "", $1); print $1}')
after=$(echo "${last:-0} - $start" | bc)
note "can_log $frames frames replayed, $got recorded; log span $log_span s, last frame ${after} s after canplayer started (it ran $took s)"
if [ -n "$last" ] && [ "$(echo "$after >= $log_span" | bc)" = 1 ]; then
  pass timestamps_honoured
else
  fail timestamps_honoured "the last frame came ${after} s after canplayer started; the log spans $log_span s"
fi
exit "$failed"
