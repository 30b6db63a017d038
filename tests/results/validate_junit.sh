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

# agrees STATUS FILE [FILE...]: each junit.xml is clean (failures + errors over the <testsuites>
# root, as Jenkins adds them up, are 0) exactly when its verdict passed. STATUS is hilrig's exit
# status for the first file; every further file is a campaign of the suite, judged by its own
# results.json beside it. One Python for every file: a Python start costs ~0.5 s of CPU here.
agrees() {
  python3 - "$@" <<'PY'
import json, pathlib, sys, xml.etree.ElementTree as ET
status, files = sys.argv[1], sys.argv[2:]
for i, f in enumerate(files):
    root = ET.parse(f).getroot()
    bad = int(root.get("failures")) + int(root.get("errors"))
    if i == 0:
        exit_status = status
    else:
        verdict = json.loads((pathlib.Path(f).parent / "results.json").read_text())["verdict"]
        exit_status = "0" if verdict == "pass" else "1"
    if exit_status == "0" and bad != 0:
        sys.exit(f"FAIL: {f} has {bad} failures/errors but hilrig exited 0")
    if exit_status != "0" and bad == 0:
        sys.exit(f"FAIL: {f} is clean but hilrig exited {exit_status}")
    print(f"ok: {f}: {bad} failures/errors, exit {exit_status}")
PY
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
# The suite's junit.xml against the exit status, then each campaign's own against its verdict.
campaigns=()
for f in "${files[@]}"; do [ "$f" != "$scratch/suite/junit.xml" ] && campaigns+=("$f"); done
agrees "$status" "$scratch/suite/junit.xml" "${campaigns[@]}"

# 2. A campaign that fails (the reference PLS's late variant: every latency over its limit).
sed 's/^model = "reference_pls"$/model = "reference_pls"\nvariant = "late"/' \
  "$src/campaigns/reference/reference_pls_pass.toml" >"$scratch/late.toml"
status=0
"$hilrig" run "$scratch/late.toml" --out "$scratch/late" >/dev/null 2>&1 || status=$?
if [ "$status" != 1 ]; then echo "FAIL: the late variant exited $status, not 1"; exit 1; fi
xmllint --noout --schema "$xsd" "$scratch/late/junit.xml"
agrees "$status" "$scratch/late/junit.xml"
echo "junit.xml: valid against $(basename "$xsd") and agreeing with the exit status"
