#!/usr/bin/env bash
# The nightly of docs/ci.md: every shipped campaign as a suite, each campaign's results.json
# compared with the last good night's, and this night's kept as the baseline when it is clean.
# Usage: ci-nightly.sh OUT BASELINE [hilrig run options, e.g. --jobs 4]
# Exit: the suite's status (0/1/2/3), or 1 when it passed but `hilrig compare` found a regression.
set -uo pipefail
out=$1 baseline=$2
shift 2
hilrig=${HILRIG:-hilrig}
campaigns=${CAMPAIGNS:-campaigns}

status=0
"$hilrig" run "$campaigns" --backend virtual --out "$out" "$@" || status=$?
if [ "$status" -ge 2 ]; then exit "$status"; fi # bad input or a rig fault: nothing to compare

while IFS= read -r rel; do
  if [ -f "$baseline/$rel" ]; then
    "$hilrig" compare "$baseline/$rel" "$out/$rel" || { c=$?; [ "$c" -gt "$status" ] && status=$c; }
  else
    echo "ci-nightly: $rel: no baseline yet"
  fi
done < <(cd "$out" && find . -name results.json | sed 's|^\./||' | sort)

if [ "$status" = 0 ]; then
  rm -rf "$baseline.new"
  fresh=$(mkdir -p "$baseline.new" && cd "$baseline.new" && pwd)
  (cd "$out" && find . -name results.json -exec cp --parents {} "$fresh/" \;)
  rm -rf "$baseline" && mv "$baseline.new" "$baseline"
  echo "ci-nightly: clean; $baseline is this night's results"
fi
exit "$status"
