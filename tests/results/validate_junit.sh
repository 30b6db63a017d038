#!/usr/bin/env bash
# junit.xml as a CI server reads it: every shipped campaign run as one suite (the aggregated
# junit.xml and each campaign's own), and a failing campaign, validated against Jenkins' JUnit
# schema (jenkins-junit-10.xsd, by xmllint) and agreeing with hilrig's exit status.
# Usage: validate_junit.sh HILRIG SOURCE_DIR SCRATCH_DIR
set -euo pipefail
hilrig=$1 src=$2 scratch=$3
xsd="$src/tests/results/jenkins-junit-10.xsd"
rm -rf "$scratch"
mkdir -p "$scratch"

# failures + errors over the <testsuites> root, as Jenkins adds them up.
bad_cases() {
  python3 - "$1" <<'PY'
import sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
print(int(root.get("failures")) + int(root.get("errors")))
PY
}

# agrees FILE STATUS: a clean junit.xml exactly when hilrig exited 0.
agrees() {
  local n
  n=$(bad_cases "$1")
  if [ "$2" = 0 ] && [ "$n" != 0 ]; then echo "FAIL: $1 has $n failures/errors but hilrig exited 0"; exit 1; fi
  if [ "$2" != 0 ] && [ "$n" = 0 ]; then echo "FAIL: $1 is clean but hilrig exited $2"; exit 1; fi
  echo "ok: $1: $n failures/errors, exit $2"
}

# 1. Every shipped campaign (the lane's too, on the virtual bus), as one suite.
status=0
"$hilrig" run "$src/campaigns" --out "$scratch/suite" --backend virtual --jobs 2 >"$scratch/suite.log" 2>&1 || status=$?
cat "$scratch/suite.log"
mapfile -t files < <(find "$scratch/suite" -name junit.xml | sort)
shipped=$(find "$src/campaigns" -name '*.toml' | wc -l)
if [ "${#files[@]}" != $((shipped + 1)) ]; then
  echo "FAIL: ${#files[@]} junit.xml files for $shipped campaigns and the suite"; exit 1
fi
xmllint --noout --schema "$xsd" "${files[@]}"
agrees "$scratch/suite/junit.xml" "$status"
for f in "${files[@]}"; do
  [ "$f" = "$scratch/suite/junit.xml" ] && continue
  # Each campaign's own verdict against its junit.xml: pass exactly when it is clean.
  verdict=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["verdict"])' "$(dirname "$f")/results.json")
  agrees "$f" "$([ "$verdict" = pass ] && echo 0 || echo 1)"
done

# 2. A campaign that fails (the reference PLS's late variant: every latency over its limit).
sed 's/^model = "reference_pls"$/model = "reference_pls"\nvariant = "late"/' \
  "$src/campaigns/reference/reference_pls_pass.toml" >"$scratch/late.toml"
status=0
"$hilrig" run "$scratch/late.toml" --out "$scratch/late" >/dev/null 2>&1 || status=$?
if [ "$status" != 1 ]; then echo "FAIL: the late variant exited $status, not 1"; exit 1; fi
xmllint --noout --schema "$xsd" "$scratch/late/junit.xml"
agrees "$scratch/late/junit.xml" "$status"
echo "junit.xml: valid against $(basename "$xsd") and agreeing with the exit status"
