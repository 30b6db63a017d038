#!/usr/bin/env bash
# docs/ci.md's recipes, run: the GNU parallel, Slurm array and Kubernetes Indexed Job sharding
# blocks exactly as the document has them (merged shards equal the unsharded run; Slurm and
# Kubernetes stood in for by setting the index variables they set), and the nightly script twice over a small campaign
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
# One wall-clock start for every run of part 1 (the recipes' shards and the unsharded run), as
# a reproducible build pins it: their results.json are then compared whole, started_at and
# host included (hilrig merge keeps the first shard's).
export SOURCE_DATE_EPOCH=1767225600 # 2026-01-01T00:00:00Z

# 1. GNU parallel: the block between the ci-recipe markers, word for word.
# recipe NAME: the fenced block after <!-- ci-recipe: NAME, up to its <!-- /ci-recipe -->.
recipe() {
  python3 - "$src/docs/ci.md" "$1" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
m = re.search(r"<!-- ci-recipe: " + re.escape(sys.argv[2]) + r"\b.*?-->\n```[a-z]*\n(.*?)```\n<!-- /ci-recipe -->",
              text, re.S)
sys.stdout.write(m.group(1) if m else "")
PY
}
recipe gnu-parallel >parallel.sh
[ "$(wc -l <parallel.sh)" -ge 2 ] || fail "no GNU parallel recipe found in docs/ci.md"
cat parallel.sh
bash -e parallel.sh
hilrig run campaigns/ans1/ans1_faults.toml --backend virtual --trace failed --out whole >/dev/null
# The merged shards are the unsharded run: the same JSON but for the shard field.
same_as_whole() {
  python3 - "$1" whole/results.json <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:])
if a["wall_clock"]["started_at"] != "2026-01-01T00:00:00Z":
    sys.exit("started_at is not SOURCE_DATE_EPOCH's: " + a["wall_clock"]["started_at"])
for d in (a, b):
    d.pop("shard", None)
    # Each shard keeps its own first run's trace (in its own --out); the unsharded run one.
    for r in d["runs"]:
        r.pop("trace", None)
sys.exit(0 if a == b else 1)
PY
}
same_as_whole out/merged.json || fail "GNU parallel: merged shards differ from the unsharded run"
# hilrig merge writes junit.xml and report.html beside the merged results (merged.junit.xml,
# merged.report.html): the unsharded run's junit.xml but for the wall time each run took (not
# in results.json: the merged file writes no time attribute at all, rather than a false 0).
python3 - out/merged.junit.xml whole/junit.xml <<'PY' || fail "GNU parallel: merged junit.xml"
import re, sys
merged, whole = sys.argv[1:]
durations = lambda path: re.sub(r' time="[^"]*"', '', open(path).read())
text = open(merged).read()
if ' time="' in text:
    sys.exit("merged.junit.xml writes a time that results.json does not hold")
sys.exit(0 if durations(merged) == durations(whole) else "merged.junit.xml is not the unsharded run's junit.xml")
PY
# With every trace kept (--trace all), the merged report, written elsewhere than the shards,
# links each run's trace where its shard wrote it.
for k in 0 1; do hilrig run campaigns/reference/reference_pls_pass.toml --shard $k/2 --out all/shard-$k >/dev/null; done
hilrig merge merged-all.json all/shard-0/results.json all/shard-1/results.json >/dev/null
python3 - merged-all.json merged-all.report.html <<'PY' || fail "merge: the merged report's trace links"
import json, os, re, sys
results, report = sys.argv[1:]
kept = sorted(r["trace"] for r in json.load(open(results))["runs"] if r.get("trace"))
links = sorted(set(re.findall(r'href="([^"#]+\.vcd)"', open(report).read())))
if not kept or links != kept:
    sys.exit(f"report links {links}, results.json names {kept}")
missing = [l for l in links if not os.path.isfile(l)]
sys.exit(f"links to no file: {missing}" if missing else 0)
PY
echo "ok: GNU parallel recipe: 4 shards merged equal the unsharded run"

# 1b. Slurm array: the batch script once per index of its --array range, as sbatch would run
# it (SLURM_ARRAY_TASK_ID, SLURM_ARRAY_TASK_COUNT), then the merge block.
recipe slurm-array >slurm.sh
recipe slurm-merge >slurm-merge.sh
grep -q SLURM_ARRAY_TASK_ID slurm.sh || fail "no Slurm array recipe found in docs/ci.md"
[ -s slurm-merge.sh ] || fail "no Slurm merge recipe found in docs/ci.md"
range=$(sed -n 's/^#SBATCH --array=\([0-9]*\)-\([0-9]*\)$/\1 \2/p' slurm.sh)
[ -n "$range" ] || fail "the Slurm recipe has no #SBATCH --array=FIRST-LAST"
read -r first last <<<"$range"
rm -rf out
for ((i = first; i <= last; i++)); do
  SLURM_ARRAY_TASK_ID=$i SLURM_ARRAY_TASK_COUNT=$((last - first + 1)) bash -e slurm.sh >/dev/null ||
    fail "Slurm task $i"
done
[ -f "out/shard-$last/results.json" ] || fail "Slurm: no results.json from task $last"
bash -e slurm-merge.sh
same_as_whole out/merged.json || fail "Slurm: merged shards differ from the unsharded run"
echo "ok: Slurm array recipe: $((last - first + 1)) tasks merged equal the unsharded run"

# 1c. Kubernetes Indexed Job: the container's command and args once per completion index
# (JOB_COMPLETION_INDEX), the results volume's mountPath mapped onto a scratch directory (as
# the PersistentVolumeClaim would be), then the merge block with the same mapping.
recipe k8s-indexed-job >job.yaml
recipe k8s-merge >k8s-merge.sh
mkdir -p volume
python3 - job.yaml "$scratch/volume" >k8s-tasks.sh <<'PY' || fail "the Kubernetes recipe is not an Indexed Job"
import shlex, sys, yaml
job = yaml.safe_load(open(sys.argv[1]))
spec = job["spec"]
assert job["kind"] == "Job" and spec["completionMode"] == "Indexed"
container = spec["template"]["spec"]["containers"][0]
mount = container["volumeMounts"][0]["mountPath"]
argv = [a.replace(mount + "/", sys.argv[2] + "/") for a in container["command"] + container["args"]]
print(f"mount={shlex.quote(mount)}")
for i in range(spec["completions"]):
    print(f"JOB_COMPLETION_INDEX={i} {shlex.join(argv)} >/dev/null || exit 1")
PY
cat k8s-tasks.sh
bash -e k8s-tasks.sh || fail "a Kubernetes completion index failed"
mount=$(sed -n 's/^mount=//p' k8s-tasks.sh)
sed -E "s#(^|[[:space:]\"'])$mount/#\1$scratch/volume/#g" k8s-merge.sh >k8s-merge-mapped.sh
grep -q "hilrig merge" k8s-merge-mapped.sh || fail "no Kubernetes merge recipe found in docs/ci.md"
bash -e k8s-merge-mapped.sh
same_as_whole volume/merged.json || fail "Kubernetes: merged shards differ from the unsharded run"
echo "ok: Kubernetes Indexed Job recipe: $(ls -d volume/shard-* | wc -l) indices merged equal the unsharded run"

# 2. The nightly (scripts/ci-nightly.sh) over two campaigns: no baseline, then a baseline.
unset SOURCE_DATE_EPOCH # a nightly's evidence carries the real start
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
