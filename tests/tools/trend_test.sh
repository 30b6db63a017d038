#!/usr/bin/env bash
# `hilrig trend` over three nights of one campaign (two clean, the third with the reference
# PLS's late variant, whose latencies exceed their 300 us limit): one self-contained page with
# a section per measurement (run and name) whose values, night by night, are the results.json
# values, a point per night in its word's colour and the limit drawn; two passing nights of the
# fault campaign show their caught faults blue and no red (docs/ci.md); another campaign's
# results and a missing file are bad input (exit 2).
# Usage: trend_test.sh HILRIG SOURCE_DIR SCRATCH_DIR
set -euo pipefail
hilrig=$1 src=$2 scratch=$3
rm -rf "$scratch"
mkdir -p "$scratch"
cd "$scratch"
fail() { echo "FAIL: $*"; exit 1; }

pass="$src/campaigns/reference/reference_pls_pass.toml"
sed 's/^model = "reference_pls"$/model = "reference_pls"\nvariant = "late"/' "$pass" >late.toml
"$hilrig" run "$pass" --out n1 >/dev/null
"$hilrig" run "$pass" --out n2 --seed 2 >/dev/null
status=0
"$hilrig" run late.toml --out n3 >/dev/null || status=$?
[ "$status" = 1 ] || fail "the late night exited $status, not 1"

cat >check_trend.py <<'PY'
import html, json, re, sys
page = open(sys.argv[1]).read()
nights = [json.load(open(p)) for p in sys.argv[2:]]
# Self-contained: nothing fetched.
assert not re.search(r'(src|href)="', page), "the page links out"
expected = {}  # (run, measurement) -> [(value, outcome) or None per night]
for i, n in enumerate(nights):
    for run in n["runs"]:
        for check in run["checks"]:
            for m in check["measurements"]:
                # The word it reads (report.html's): a fault's evidence is caught, not fail.
                word = m["outcome"]
                if check["outcome"] in ("caught", "not judged") and word != "pass":
                    word = check["outcome"]
                expected.setdefault((run["name"], m["name"]), [None] * len(nights))[i] = (m["value"], word, m["upper"])
sections = page.split("<section>")[1:]
assert len(sections) == len(expected), f"{len(sections)} sections for {len(expected)} measurements"
colour = {"pass": "#1a7f37", "fail": "#cf222e", "caught": "#0969da", "not judged": "#57606a", "error": "#9a6700"}
late_failures = 0
for s in sections:
    name, run = re.search(r"<h3>(.*?) <small>\((.*?)\)</small>", s).groups()
    want = expected[(html.unescape(run), html.unescape(name))]
    values = re.findall(r" (-|[-0-9.e+]+(?: \((?:pass|fail|caught|not judged|error)\))?)", re.search(r"values:(.*?)</p>", s).group(1))
    assert len(values) == len(want), (name, values)
    for v, w in zip(values, want):
        if w is None:
            assert v == "-", (name, v)
            continue
        number, outcome = re.match(r"([-0-9.e+]+) \(([\w ]+)\)", v).groups()
        assert abs(float(number) - w[0]) <= 1e-9 * max(1.0, abs(w[0])) and outcome == w[1], (name, v, w)
    # The figure's data (drawn by uPlot): each night's point sits in its outcome's series, in
    # that outcome's colour, and nowhere else.
    chart = json.loads(re.search(r'<script type="application/json" class="figure-data">(.*?)</script>', s).group(1))["charts"][0]
    by_label = {series["label"]: (series["colour"], chart["data"][k + 1]) for k, series in enumerate(chart["series"])}
    for night, w in enumerate(want):
        for outcome in colour:
            shown = by_label[outcome][1][night]
            if w is not None and w[1] == outcome:
                assert by_label[outcome][0] == colour[outcome] and abs(shown - w[0]) <= 1e-9 * max(1.0, abs(w[0])), (name, night, outcome, shown)
            else:
                assert shown is None, (name, night, outcome, shown)
    upper = want[-1][2]
    if upper is not None:
        assert any(h["at"] == upper and h["label"].startswith(f"upper limit {upper:g}") for h in chart["hlines"]), (name, upper, chart["hlines"])
    if want[-1][1] == "fail":
        late_failures += 1
caught = sum(1 for w in expected.values() for p in w if p is not None and p[1] == "caught")
if all(n["verdict"] == "pass" for n in nights):
    # Passing nights: no red anywhere (the fault runs' evidence reads caught).
    assert late_failures == 0 and "(fail)" not in page, "a passing night shows a failure"
    assert caught > 0, "the fault nights show nothing caught"
else:
    assert late_failures > 0, "the late night shows no failure"
print(f"ok: {len(sections)} measurements over {len(nights)} nights, {late_failures} failing on the last, {caught} caught")
PY
"$hilrig" trend n1/results.json n2/results.json n3/results.json --out trend.html >trend.log
python3 check_trend.py trend.html n1/results.json n2/results.json n3/results.json || fail "the trend page does not show the nights"

# Two passing nights of the fault campaign: every fault caught, so no red point.
faults="$src/campaigns/reference/reference_pls_faults.toml"
"$hilrig" run "$faults" --out f1 >/dev/null
"$hilrig" run "$faults" --out f2 --seed 12 >/dev/null
"$hilrig" trend f1/results.json f2/results.json --out faults.html >/dev/null
python3 check_trend.py faults.html f1/results.json f2/results.json || fail "the fault nights' trend shows red"

# Another campaign's results, and a file that is not there: bad input.
"$hilrig" run "$src/campaigns/reference/reference_pls_faults.toml" --out other >/dev/null
status=0
"$hilrig" trend n1/results.json other/results.json --out stranger.html 2>stranger.log || status=$?
[ "$status" = 2 ] || fail "a stranger's results exited $status, not 2"
grep -q "a trend is one campaign on one device" stranger.log || fail "no reason given: $(cat stranger.log)"
# Both files named: nights run at the same epoch share a label.
grep -q "n1/results.json (.*other/results.json (" stranger.log || fail "the files are not named: $(cat stranger.log)"
[ ! -e stranger.html ] || fail "a page was written for a stranger"
status=0
"$hilrig" trend n1/results.json missing.json --out missing.html 2>/dev/null || status=$?
[ "$status" = 2 ] || fail "a missing file exited $status, not 2"
echo "hilrig trend: as expected"
