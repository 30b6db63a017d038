#!/usr/bin/env bash
# Runs the fuzzers built in build-fuzz/ (make build-fuzz).
#   fuzz/run.sh smoke NAME...  a short deterministic run each (fixed -seed, -runs): make test
#   fuzz/run.sh long NAME...   FUZZ_SECONDS (600) each, corpus kept in build-fuzz/corpus/NAME
# Each starts from the shipped files: campaigns/ for the campaign reader, rt-config/ for the
# rig-config reader, fuzz/seeds/NAME/ (one request of each function code) for Modbus. A crash,
# a leak (LeakSanitizer), an uncaught exception or an input slower than -timeout fails the run;
# libFuzzer leaves the input as build-fuzz/crash-*, leak-* or timeout-*.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:?usage: fuzz/run.sh smoke|long NAME...}
shift

seeds_of() {
  case "$1" in
  fuzz_campaign) echo campaigns ;;
  fuzz_rig_config) echo rt-config ;;
  *) echo "fuzz/seeds/${1#fuzz_}" ;;
  esac
}
# Runs in the smoke run: each takes a few seconds on one core of the CI machine.
runs_of() {
  case "$1" in
  fuzz_campaign) echo 10000 ;;
  fuzz_rig_config) echo 10000 ;;
  fuzz_modbus_rtu) echo 100000 ;;
  *) echo 200000 ;;
  esac
}

for name in "$@"; do
  exe=build-fuzz/fuzz/$name
  corpus=build-fuzz/corpus/$name
  if [ "$mode" = smoke ]; then
    # A fresh corpus each time, so the same seed replays the same inputs.
    rm -rf "$corpus"
    mkdir -p "$corpus"
    limits=(-seed=1 "-runs=$(runs_of "$name")")
  else
    mkdir -p "$corpus"
    limits=("-max_total_time=${FUZZ_SECONDS:-600}")
  fi
  start=$(date +%s)
  "$exe" "${limits[@]}" -max_len=8192 -timeout=10 -rss_limit_mb=2048 -artifact_prefix=build-fuzz/ \
    -print_final_stats=1 "$corpus" "$(seeds_of "$name")" >"build-fuzz/$name.log" 2>&1 || {
    tail -40 "build-fuzz/$name.log"
    echo "fuzz: $name failed (build-fuzz/$name.log)" >&2
    exit 1
  }
  echo "fuzz: $name $mode: $(grep -m1 -o 'stat::number_of_executed_units: *[0-9]*' "build-fuzz/$name.log" |
    grep -o '[0-9]*$') inputs in $(($(date +%s) - start)) s, no crash, leak or timeout"
done
