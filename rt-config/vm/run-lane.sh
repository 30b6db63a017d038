#!/usr/bin/env bash
# The RT VM lane: boots Debian's PREEMPT_RT kernel under QEMU (TCG) with the host's root
# shared read-only, real gpio-sim, two emulated SJA1000 CAN boards on one QEMU CAN bus plus
# vcan, and two UARTs wired to each other; runs guest.sh (and an optional payload) inside.
# Usage: run-lane.sh [WORK_DIR] [PAYLOAD_SCRIPT]. Exit 0 only when every guest check passed.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=${1:-build-vm}
payload=${2:-}
step() { printf '[vm-lane] %s\n' "$*"; }
start=$(date +%s)

bash "$here/prepare.sh" "$work"
work=$(cd "$work" && pwd)
kver=$(cat "$work/kernel-version")
out="$work/out"
rm -rf "$out" && mkdir -p "$out"
console="$work/console.log"

step "booting $kver under QEMU (TCG); console in $console"
append="console=ttyS0 panic=-1 quiet hilrig.guest=$here/guest.sh hilrig.out=$out hilrig.work=$work"
[ -n "$payload" ] && append="$append hilrig.payload=$(cd "$(dirname "$payload")" && pwd)/$(basename "$payload")"
# ttyS0 is the console; ttyS1 <-> ttyS2: two guest UARTs joined by UDP on loopback, for the serial host link.
p1=$((20000 + RANDOM % 20000)); p2=$((p1 + 1))
set +e
timeout --foreground 280 qemu-system-x86_64 -accel tcg -m 1024 -smp 2 -nographic -no-reboot \
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
