#!/bin/bash
# Lane payload for figures 6a/6b (bench/run-all.sh, docs/PERFORMANCE.md), inside the guest:
#   6a  bench_can_frames (drivers/socketcan, kernel receive timestamps) on vcan0, then the
#       peer: cangen -g 0 into candump -L on the same vcan0; both read (N-1)/(last-first) from
#       the kernel's receive timestamps, with the same receive buffer.
#   6b  bench_gpio_edges: drivers/gpiod OutputRequest vs a bare libgpiod set-value loop on one
#       gpio-sim line, in one binary.
# Rounds alternate rig and peer. Raw outputs go to OUT/bench/; OUT/bench/summary has the
# key=value lines bench/make_table.py reads.
# Arguments from guest.sh: OUT CHIP SIM_DIR. HILRIG_BUILD names the release build tree (default
# build-release beside rt-config/). BENCH_CAN_FRAMES, BENCH_GPIO_EDGES, BENCH_ROUNDS size it.
set -u
out=$1 chip=$2 sim=$3
here=$(cd "$(dirname "$0")" && pwd)
build=${HILRIG_BUILD:-$here/../../build-release}
can_bin="$build/bench/can_frames/bench_can_frames"
gpio_bin="$build/bench/gpio_edges/bench_gpio_edges"
# Many short rounds rather than a few long ones: the host shares its cores, and alternating
# often lets rig and peer see the same load. Each round's rig/peer ratio is kept as well.
frames=${BENCH_CAN_FRAMES:-10000}
edges=${BENCH_GPIO_EDGES:-20001}
rounds=${BENCH_ROUNDS:-9}
rcvbuf=$((32 << 20)) # holds every frame of a run: loss would be the receiver's, not the link's
raw="$out/bench"
mkdir -p "$raw"
summary="$raw/summary"
: >"$summary"
status=0
for b in "$can_bin" "$gpio_bin"; do [ -x "$b" ] || { echo "payload-bench: $b not built"; exit 1; }; done
command -v cangen >/dev/null && command -v candump >/dev/null || { echo "payload-bench: can-utils missing"; exit 1; }
median() { sort -g | awk '{v[NR] = $1} END {if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

# candump -L lines are "(sec.usec) iface id#data": rate from the first and last timestamps.
# The log goes to the guest's tmpfs (/run): writing it over 9p would make candump the bottleneck.
scratch=$(mktemp -d /run/hilrig-bench.XXXXXX)
peer_round() { # peer_round ROUND
  local log="$scratch/candump-$1.log"
  candump -L -n "$frames" -r "$rcvbuf" -T 10000 vcan0,123:7FF >"$log" 2>"$raw/candump-$1.err" &
  local dump=$!
  sleep 0.5 # candump's socket must be bound before the first frame
  cangen vcan0 -g 0 -n "$frames" -I 123 -L 8 -D i >"$raw/cangen-$1.txt" 2>&1
  echo "cangen_exit=$?" >>"$raw/cangen-$1.txt"
  wait "$dump"
  awk -v n="$frames" '{gsub(/[()]/, "", $1); if (NR == 1) first = $1; last = $1}
    END {span = last - first; printf "received=%d\nlost=%d\nkernel_span_s=%.6f\nfps=%.1f\n", NR, n - NR, span, (span > 0 ? (NR - 1) / span : 0)}' \
    "$log" >"$raw/peer-$1.txt"
  head -n 3 "$log" >"$raw/candump-$1.head"
  rm -f "$log"
}

echo "[bench] 6a: $frames frames a round, $rounds rounds, vcan0"
for r in $(seq 1 "$rounds"); do
  # Who goes first alternates, so neither always runs on the warmer (or busier) machine.
  if [ $((r % 2)) = 0 ]; then peer_round "$r"; fi
  "$can_bin" vcan0 "$frames" "$rcvbuf" >"$raw/hilrig-can-$r.txt" 2>&1 || status=1
  if [ $((r % 2)) = 1 ]; then peer_round "$r"; fi
  h=$(sed -n 's/^fps=//p' "$raw/hilrig-can-$r.txt")
  p=$(sed -n 's/^fps=//p' "$raw/peer-$r.txt")
  awk -v h="${h:-0}" -v p="${p:-0}" 'BEGIN {if (p > 0) print h / p}' >>"$raw/can-paired"
  echo "[bench]   round $r: hilrig $(grep -E '^(fps|lost)=' "$raw/hilrig-can-$r.txt" | tr '\n' ' ')| peer $(grep -E '^(fps|lost)=' "$raw/peer-$r.txt" | tr '\n' ' ')"
done
{
  echo "can_frames=$frames"
  echo "can_rounds=$rounds"
  echo "can_hilrig_fps=$(cat "$raw"/hilrig-can-*.txt | sed -n 's/^fps=//p' | median)"
  echo "can_peer_fps=$(cat "$raw"/peer-*.txt | sed -n 's/^fps=//p' | median)"
  echo "can_paired_ratio=$(median <"$raw/can-paired")"
  echo "can_hilrig_lost=$(cat "$raw"/hilrig-can-*.txt | sed -n 's/^lost=//p' | awk '{s += $1} END {print s + 0}')"
  echo "can_hilrig_out_of_order=$(cat "$raw"/hilrig-can-*.txt | sed -n 's/^out_of_order=//p' | awk '{s += $1} END {print s + 0}')"
  echo "can_peer_lost=$(cat "$raw"/peer-*.txt | sed -n 's/^lost=//p' | awk '{s += $1} END {print s + 0}')"
} >>"$summary"

# A line none of the lane's other checks use.
line=15
echo "[bench] 6b: $edges edges a round, $((rounds * 2 + 1)) rounds, $chip line $line"
"$gpio_bin" "$chip" "$line" "$edges" "$((rounds * 2 + 1))" "$sim" >"$raw/gpio.txt" 2>&1 || status=1
sed 's/^/[bench]   /' "$raw/gpio.txt"
{
  echo "gpio_edges=$edges"
  echo "gpio_rounds=$((rounds * 2 + 1))"
  sed -n 's/^\(libgpiod_version\|paired_ratio\|hilrig_eps\|bare_eps\|hilrig_errors\|bare_errors\|far_side_wrong\)=/gpio_&/p' "$raw/gpio.txt"
} >>"$summary"
echo "kernel=$(uname -r)" >>"$summary"
sed 's/^/[bench] summary: /' "$summary"
exit "$status"
