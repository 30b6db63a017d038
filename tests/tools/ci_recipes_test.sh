#!/usr/bin/env bash
# docs/ci.md's recipes, run: the GNU parallel sharding block exactly as the document has it
# (merged shards equal the unsharded run), and the nightly script twice over a small campaign
# tree (a baseline made, then compared against), and against a stranger's baseline (refused).
# Usage: ci_recipes_test.sh HILRIG SOURCE_DIR SCRATCH_DIR
set -euo pipefail
hilrig=$1 src=$2 scratch=$3
rm -rf "$scratch"
mkdir -p "$scratch/bin"
ln -s "$(cd "$(dirname "$hilrig")" && pwd)/$(basename "$hilrig")" "$scratch/bin/hilrig"
export PATH="$scratch/bin:$PATH"
cd "$scratch"
ln -s "$src/campaigns" campaigns
fail() { echo "FAIL: $*"; exit 1; }

# 1. GNU parallel: the block between the ci-recipe markers, word for word.
sed -n '/<!-- ci-recipe: gnu-parallel/,/<!-- \/ci-recipe -->/p' "$src/docs/ci.md" | sed '/^```\|^<!--/d' >parallel.sh
[ "$(wc -l <parallel.sh)" -ge 2 ] || fail "no GNU parallel recipe found in docs/ci.md"
cat parallel.sh
bash -e parallel.sh
hilrig run campaigns/ans1/ans1_faults.toml --backend virtual --out out/whole >/dev/null
# The merged shards are the unsharded run: the same JSON but for the shard field.
python3 - out/merged.json out/whole/results.json <<'PY' || fail "merged shards differ from the unsharded run"
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:])
for d in (a, b):
    d.pop("shard", None)
    d.pop("wall_clock", None)
    # Each shard keeps its own first run's trace (in its own --out); the unsharded run one.
    for r in d["runs"]:
        r.pop("trace", None)
sys.exit(0 if a == b else 1)
PY
echo "ok: GNU parallel recipe: 4 shards merged equal the unsharded run"

# 2. The nightly (scripts/ci-nightly.sh) over two campaigns: no baseline, then a baseline.
mkdir -p tree/reference
cp "$src/campaigns/reference/"*.toml tree/reference/
export HILRIG=hilrig CAMPAIGNS=tree
bash "$src/scripts/ci-nightly.sh" night1 baseline --jobs 2 >night1.log 2>&1 || { cat night1.log; fail "first night"; }
grep -q "no baseline yet" night1.log || fail "first night compared against nothing?"
[ -f baseline/reference/reference_pls_pass/results.json ] || fail "no baseline kept after a clean night"
bash "$src/scripts/ci-nightly.sh" night2 baseline --jobs 2 >night2.log 2>&1 || { cat night2.log; fail "second night"; }
grep -q " 0 regressions" night2.log || { cat night2.log; fail "second night did not compare"; }
echo "ok: nightly: baseline made, then compared"

# 3. A baseline of another campaign is refused, not compared.
status=0
hilrig compare baseline/reference/reference_pls_pass/results.json \
  night2/reference/reference_pls_faults/results.json >stranger.log 2>&1 || status=$?
[ "$status" = 2 ] || fail "a stranger's baseline: exit $status, expected 2"
grep -q "a baseline must be the same campaign on the same device" stranger.log || fail "no clear message"
echo "ok: a baseline of another campaign is refused (exit 2)"
