#!/bin/bash
# Sourced by the lane payloads, so each prints its steps and checks the same way: a step line
# with the seconds since the payload began, and each check as a PASS/FAIL line (NOTE for a
# measurement), also appended to the lane's result. Set `lane_name` (the prefix of the checks'
# names) and `result` (the lane's result file) before sourcing.
failed=0
step() { printf '[%s %3ss] %s\n' "$lane_name" "$SECONDS" "$*"; }
pass() { printf 'PASS %s.%s\n' "$lane_name" "$1" | tee -a "$result"; }
fail() {
  printf 'FAIL %s.%s: %s\n' "$lane_name" "$1" "$2" | tee -a "$result"
  failed=1
}
note() { printf 'NOTE %s\n' "$*" | tee -a "$result"; }
