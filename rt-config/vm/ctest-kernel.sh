#!/bin/bash
# Runs the kernel-backend tests of one build tree through ctest inside the guest: every
# GoogleTest case is its own ctest test (label "kernel", registered only for -C lane; see
# tests/kernel/CMakeLists.txt). The build tree is read-only in the guest, so ctest runs from a
# scratch directory under OUT whose CTestTestfile points at the tree's tests/kernel.
# Usage: ctest-kernel.sh KERNEL_TESTS_DIR OUT NAME. Prints ctest's per-test lines prefixed
# [NAME], adds "PASS NAME.<test>" / "FAIL NAME.<test>: <status>" lines to HILRIG_LANE_RESULT,
# writes OUT/NAME.junit.xml, and exits non-zero if a test failed or none ran.
set -u
dir=$1 out=$2 name=$3
result=${HILRIG_LANE_RESULT:-/dev/null}
scratch="$out/ctest-$name"
rm -rf "$scratch" && mkdir -p "$scratch"
printf 'subdirs("%s")\n' "$dir" >"$scratch/CTestTestfile.cmake"
ctest --test-dir "$scratch" -C lane -L kernel --no-tests=error --output-on-failure --timeout 120 \
  --output-junit "$out/$name.junit.xml" >"$scratch/ctest.txt" 2>&1
status=$?
sed "s/^/[$name] /" "$scratch/ctest.txt"
# "  3/22 Test  #3: Suite.Case ....   Passed    0.01 sec" -> one lane result line per test.
sed -nE 's/^ *[0-9]+\/[0-9]+ Test +#[0-9]+: ([^ ]+) \.*[* ]*(Passed|.*)  +[0-9.]+ sec$/\1 \2/p' "$scratch/ctest.txt" |
  while read -r test verdict; do
    if [ "$verdict" = Passed ]; then
      printf 'PASS %s.%s\n' "$name" "$test"
    else
      printf 'FAIL %s.%s: %s\n' "$name" "$test" "$verdict"
    fi
  done >>"$result"
exit $status
