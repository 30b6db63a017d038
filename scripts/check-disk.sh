#!/usr/bin/env bash
# make test's first step: stops before building when the disk cannot hold the whole run, which
# would otherwise fail half an hour in, at a link ("No space left on device"), with nothing learnt.
#
# The need is measured, not guessed: the build trees of one clean `make test` (build, build-asan,
# build-fuzz, build-gpiod2, build-vm with its cached kernel and images, and the tests' scratch
# files inside them): 5,285 MiB on 2026-11-26 (10 GB before -gz/-g1), 5.5 GiB with a margin.
# Trees already here count toward it, so a second run needs little.
# Usage: check-disk.sh [TREE_DIR]   (default: the repository root, where make test builds)
#   HILRIG_TEST_DISK_MB   the whole run's need in MiB (default below); 0 skips the check
set -euo pipefail
cd "${1:-$(dirname "$0")/..}"

need_mb=${HILRIG_TEST_DISK_MB:-5632}
[[ $need_mb =~ ^[0-9]+$ ]] || { echo "check-disk: HILRIG_TEST_DISK_MB=$need_mb is not a whole number of MiB" >&2; exit 2; }
((need_mb > 0)) || exit 0

held_mb=0
for tree in build build-asan build-fuzz build-gpiod2 build-vm; do
  [[ -d $tree ]] && held_mb=$((held_mb + $(du -sm "$tree" | cut -f1)))
done
free_mb=$(df -Pm . | awk 'NR == 2 { print $4 }')
missing_mb=$((need_mb - held_mb))
if ((missing_mb > free_mb)); then
  echo "make test: the disk holding $PWD has $free_mb MiB free; the run needs about $missing_mb MiB more" >&2
  echo "make test: (a clean run's build trees take $need_mb MiB; the ones here hold $held_mb MiB)." >&2
  echo "make test: free some space, or set HILRIG_TEST_DISK_MB=0 to run anyway." >&2
  exit 1
fi
echo "make test: disk: $free_mb MiB free, about $((missing_mb > 0 ? missing_mb : 0)) MiB more needed"
