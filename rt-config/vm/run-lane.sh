#!/usr/bin/env bash
# The RT VM lane: boots Debian's PREEMPT_RT kernel under QEMU (TCG) with the host's root
# shared read-only, real gpio-sim, two emulated SJA1000 CAN boards on one QEMU CAN bus plus
# vcan, and two UARTs wired to each other; runs guest.sh (and the payloads, in order) inside.
# Usage: run-lane.sh [WORK_DIR] [PAYLOAD_SCRIPT...]. Exit 0 only when every guest check and
# every payload passed. HILRIG_BUILD names the build the payloads use (default: build/ of
# this checkout).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=${1:-build-vm}
shift || true
payloads=()
for p in "$@"; do
  [ -f "$p" ] || { echo "vm-lane: no payload $p" >&2; exit 2; }
  case "$p" in *,* | *' '*) echo "vm-lane: a payload path may not hold ',' or ' ': $p" >&2; exit 2 ;; esac
  payloads+=("$(cd "$(dirname "$p")" && pwd)/$(basename "$p")")
done
build=${HILRIG_BUILD:-$here/../../build}
if [ ${#payloads[@]} -gt 0 ]; then
  [ -d "$build" ] || { echo "vm-lane: no build directory $build (HILRIG_BUILD)" >&2; exit 2; }
  build=$(cd "$build" && pwd)
fi
step() { printf '[vm-lane] %s\n' "$*"; }
start=$(date +%s)

bash "$here/prepare.sh" "$work"
work=$(cd "$work" && pwd)
kver=$(cat "$work/kernel-version")
out="$work/out"
rm -rf "$out" && mkdir -p "$out"
console="$work/console.log"

step "booting $kver under QEMU (TCG); console in $console"
append="console=ttyS0 panic=-1 quiet hilrig.guest=$here/guest.sh hilrig.out=$out hilrig.work=$work hilrig.build=$build"
if [ ${#payloads[@]} -gt 0 ]; then
  append="$append hilrig.payload=$(IFS=,; echo "${payloads[*]}")"
  step "payloads: ${payloads[*]##*/} (build: $build)"
fi
# ttyS0 is the console; ttyS1 <-> ttyS2: two guest UARTs joined by UDP on loopback, for the serial host link.
p1=$((20000 + RANDOM % 20000)); p2=$((p1 + 1))
set +e
# The guard: about 4 min on an idle 2-core host; a loaded one (seen: load 9, 347 s with the
# kernel tests as 24 ctest processes, before the can.log payload's minute) needs more.
timeout --foreground 600 qemu-system-x86_64 -accel tcg -m 1024 -smp 2 -nographic -no-reboot \
  -kernel "$work/kernel-$kver/boot/vmlinuz-$kver" -initrd "$work/initrd-$kver.cpio.gz" -append "$append" \
  -virtfs local,path=/,mount_tag=hostroot,security_model=none,readonly=on,multidevs=remap \
  -virtfs local,path="$out",mount_tag=laneout,security_model=none \
  -object can-bus,id=cb0 -device kvaser_pci,canbus=cb0 -device kvaser_pci,canbus=cb0 \
  -serial mon:stdio \
  -chardev udp,id=u1,host=127.0.0.1,port=$p2,localaddr=127.0.0.1,localport=$p1 -serial chardev:u1 \
  -chardev udp,id=u2,host=127.0.0.1,port=$p1,localaddr=127.0.0.1,localport=$p2 -serial chardev:u2 \
  </dev/null >"$console" 2>&1
qemu_status=$?
set -e
step "guest finished (qemu exit $qemu_status) after $(( $(date +%s) - start )) s"

if [ -f "$out/lane-result" ]; then sed 's/^/[vm-lane]   /' "$out/lane-result"; fi
if [ -f "$out/lane-result" ] && grep -q '^RESULT PASS' "$out/lane-result"; then
  step "PASS"
  exit 0
fi
step "FAIL — guest console tail:"
tail -n 60 "$console" | sed 's/^/[console] /'
exit 1
