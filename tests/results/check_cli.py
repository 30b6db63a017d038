#!/usr/bin/env python3
"""`hilrig compare` and `hilrig merge` exit codes on the sample results (written by
write_sample_results): merge of the one shard equals the input and exits by its verdict, compare against itself
passes (0), a drift beyond 5 % is a regression (1), unreadable input and a baseline of another
campaign or device are bad input (2)."""
import json
import os
import subprocess
import sys

hilrig, sample = sys.argv[1], sys.argv[2]
base = os.path.join(sample, "results.json")
merged = os.path.join(sample, "merged.json")
drifted = os.path.join(sample, "drifted.json")
problems = []


def run(*args):
    return subprocess.run([hilrig, *args], capture_output=True, text=True)


def expect(code, *args):
    r = run(*args)
    if r.returncode != code:
        problems.append(f"hilrig {' '.join(args)}: exit {r.returncode}, expected {code}\n{r.stdout}{r.stderr}")
    return r


# The sample's verdict is error, and its run 8 was stopped by a rig fault (a CAN bus-off): merge
# writes the merge and judges it as `hilrig run` would, exit 3, the rig's failure
# (tests/tools/ci_recipes_test.sh merges a passing campaign: exit 0).
r = expect(3, "merge", merged, base)
if "verdict error" not in r.stdout:
    problems.append(f"merge did not say its verdict: {r.stdout}")
with open(base) as f:
    doc = json.load(f)
with open(merged) as f:
    if json.load(f) != doc:
        problems.append("merging the only shard changed the content")
expect(0, "compare", base, merged)

# 10 us -> 10.6 us is a 6 % drift: beyond the default 5 %, within an absolute 1 us threshold.
doc["runs"][0]["checks"][0]["measurements"][1]["value"] = 10.6
with open(drifted, "w") as f:
    json.dump(doc, f)
r = expect(1, "compare", base, drifted)
if "DRIFT" not in r.stdout:
    problems.append("the drift is not in the table:\n" + r.stdout)
expect(0, "compare", base, drifted, "--threshold", "max=1")
expect(2, "compare", base, os.path.join(sample, "absent.json"))
expect(2, "compare", base, drifted, "--threshold", "max")

# A baseline of another campaign, or of the same campaign on another device, is refused (2).
for key, value in (("campaign", "another-campaign"), ("device", "smd23e")):
    with open(base) as f:
        other = json.load(f)
    other[key] = value
    stranger = os.path.join(sample, f"other-{key}.json")
    with open(stranger, "w") as f:
        json.dump(other, f)
    r = expect(2, "compare", stranger, base)
    if "a baseline must be the same campaign on the same device" not in r.stderr or value not in r.stderr:
        problems.append(f"another {key}: no clear refusal:\n{r.stderr}")

# merge, compare and trend given a file that is not what a writer wrote (cut short, a value
# hand-edited to another type, another schema, a measurement edited to pass with no value):
# exit 2, the message names the file, and nothing is written.
with open(base) as f:
    text = f.read()
broken = {
    "cut": text[: len(text) // 2],
    "typed": text.replace('"planned_runs": ', '"planned_runs": "x", "was": ', 1),
    "schema": json.dumps({"testsuites": []}),
    "passed-null": json.dumps(
        {**doc, "runs": [{**doc["runs"][0], "checks": [{**doc["runs"][0]["checks"][0], "measurements": [
            {**m, "value": None, "outcome": "pass"} for m in doc["runs"][0]["checks"][0]["measurements"]]}]}]}),
}
for name, body in broken.items():
    bad = os.path.join(sample, f"broken-{name}.json")
    with open(bad, "w") as f:
        f.write(body)
    out = os.path.join(sample, f"merged-broken-{name}")
    for args in (("merge", out + ".json", base, bad), ("compare", base, bad), ("trend", base, bad, "--out", out + ".html")):
        r = expect(2, *args)
        if bad not in r.stderr:
            problems.append(f"hilrig {args[0]} of a {name} file: the message does not name it:\n{r.stderr}")
    written = [p for p in os.listdir(sample) if p.startswith(f"merged-broken-{name}")]
    if written:
        problems.append(f"merge/trend of a {name} file wrote {written}")

# The merged junit.xml carries no time it does not know (results.json holds no run's wall time).
with open(os.path.join(sample, "merged.junit.xml")) as f:
    if ' time="' in f.read():
        problems.append("merged junit.xml writes a time results.json does not hold")

# A negative --seed is refused before anything runs; serve --fault names the choices.
campaign = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "campaigns", "reference",
                        "reference_pls_pass.toml")
# run and power parse --seed alike (rig/cli/seed_option.cpp): 0..2^64-1, nothing past it, no sign.
seed_range = "a seed is a decimal integer 0..18446744073709551615"
for command in ("run", "power"):
    for bad in ("-1", "18446744073709551616"):
        out = os.path.join(sample, f"bad-seed-{command}")
        r = expect(2, command, campaign, "--out", out, "--seed", bad)
        if seed_range not in r.stderr or os.path.exists(out):
            problems.append(f"{command} --seed {bad} not refused clearly:\n" + r.stderr)
# The top of the range is a seed for both (power: refused later, for its unknown --check).
r = expect(2, "power", campaign, "--seed", "18446744073709551615", "--check", "no-such-check")
if "no-such-check" not in r.stderr or "seed" in r.stderr:
    problems.append("power --seed 2^64-1 not taken:\n" + r.stderr)
r = expect(2, "serve", "smd23e", "--pty", "--fault", "lost-step")
if "(one of: none, wrong-acceleration, lost-steps, ignored-limit, late-stop)" not in r.stderr:
    problems.append("serve --fault does not list the choices:\n" + r.stderr)

for p in problems:
    print(p)
sys.exit(1 if problems else 0)
