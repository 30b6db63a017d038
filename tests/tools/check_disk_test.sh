#!/usr/bin/env bash
# scripts/check-disk.sh, make test's first step: it stops (exit 1, naming the free and the needed
# MiB) when the disk cannot hold what is still to be built, counts build trees already present
# toward the need, and refuses a need that is not a number (exit 2).
# Usage: check_disk_test.sh SOURCE_DIR SCRATCH_DIR
set -euo pipefail
src=$1 scratch=$2
rm -rf "$scratch"
mkdir -p "$scratch"
cd "$scratch"
fail() { echo "FAIL: $*"; exit 1; }
check() { HILRIG_TEST_DISK_MB=$1 bash "$src/scripts/check-disk.sh" "$scratch"; }

free_mb=$(df -Pm "$scratch" | awk 'NR == 2 { print $4 }')

# The disk is shared, so what is free moves while this runs: each case keeps a wide margin.
# Needs 8 GiB more than the disk has free: stops, and says how much it has and needs.
status=0
check $((free_mb + 8192)) >out 2>err || status=$?
[ "$status" = 1 ] || fail "a need 8 GiB over the $free_mb MiB free exited $status, not 1"
grep -q "MiB free; the run needs about" err || fail "the refusal does not say what is free and needed: $(cat err)"

# Fits: passes. (Half of what is free leaves room for whatever else writes meanwhile.)
check $((free_mb / 2)) >out 2>&1 || fail "a need of half the free space was refused: $(cat out)"

# A build tree already here counts toward the need: 512 MiB held, a need of free + 256 MiB fits.
mkdir -p "$scratch/build"
fallocate -l 512M "$scratch/build/held"
free_mb=$(df -Pm "$scratch" | awk 'NR == 2 { print $4 }')
check $((free_mb + 256)) >out 2>&1 || fail "the 512 MiB already built was not counted: $(cat out)"
rm -f "$scratch/build/held"

# 0 skips; a need that is not a number is bad input.
check 0 >out 2>&1 || fail "HILRIG_TEST_DISK_MB=0 did not skip the check"
status=0
check 4GB >out 2>err || status=$?
[ "$status" = 2 ] || fail "HILRIG_TEST_DISK_MB=4GB exited $status, not 2"
grep -q "not a whole number" err || fail "the bad value is not named: $(cat err)"
echo "check_disk: all cases pass"
