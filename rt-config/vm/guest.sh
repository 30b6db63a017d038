#!/bin/bash
# Runs inside the PREEMPT_RT guest, chrooted into the host's root (read-only): loads the
# CAN and gpio-sim modules, builds the rig's gpio-sim chip, brings up vcan0, can0 and can1,
# checks each, then runs the lane's payloads one after another (kernel command line
# hilrig.payload=P1,P2,...; each gets OUT CHIP SIM_DIR, HILRIG_BUILD and HILRIG_LANE_RESULT,
# and is its own PASS/FAIL line). Every step prints what it does; results go to
# OUT/lane-result, one "PASS name" / "FAIL name: why" a line, and a final RESULT line.
set -u
out=$1
work=$(cat /proc/cmdline | tr ' ' '\n' | sed -n 's/^hilrig.work=//p')
payloads=$(cat /proc/cmdline | tr ' ' '\n' | sed -n 's/^hilrig.payload=//p' | tr ',' ' ')
build=$(cat /proc/cmdline | tr ' ' '\n' | sed -n 's/^hilrig.build=//p')
export TMPDIR="$out/tmp" PATH=/usr/sbin:/usr/bin:/sbin:/bin
mkdir -p "$TMPDIR"
result="$out/lane-result"
: > "$result"
# Payloads find the hilrig build there (default: the checkout's build/) and may add their own
# PASS/FAIL lines to the lane's result.
[ -n "$build" ] && export HILRIG_BUILD="$build"
export HILRIG_LANE_RESULT="$result"
failed=0
step() { printf '[guest] %s\n' "$*"; }
pass() { printf 'PASS %s\n' "$1" | tee -a "$result"; }
fail() { printf 'FAIL %s: %s\n' "$1" "$2" | tee -a "$result"; failed=1; }

step "kernel: $(uname -r) $(uname -v)"
if uname -v | grep -q PREEMPT_RT && [ "$(cat /sys/kernel/realtime 2>/dev/null)" = 1 ]; then
  pass preempt_rt
else
  fail preempt_rt "uname -v: $(uname -v); /sys/kernel/realtime: $(cat /sys/kernel/realtime 2>/dev/null || echo missing)"
fi

step "loading modules"
while read -r m; do
  insmod "$m" 2>/dev/null || fail "insmod $(basename "$m")" "$(insmod "$m" 2>&1)"
done < "$work/guest-modules"

step "gpio-sim: one bank of 16 lines"
mount -t configfs none /sys/kernel/config
cfg=/sys/kernel/config/gpio-sim/rig
mkdir -p "$cfg/bank0" && echo 16 > "$cfg/bank0/num_lines" && echo 1 > "$cfg/live"
chip=$(cat "$cfg/bank0/chip_name" 2>/dev/null)
dev=$(cat "$cfg/dev_name" 2>/dev/null)
sim="/sys/devices/platform/$dev/$chip"
if [ -n "$chip" ] && gpiodetect | grep -q "$chip"; then
  pass gpio_sim_chip
  step "$(gpiodetect | grep "$chip")"
  # The rig drives line 0; the far side sees it in sim_gpio0/value.
  # (gpioset must hold the request: a released line falls back to its pull.)
  gpioset --mode=signal "$chip" 0=1 &
  holder=$!
  for _ in $(seq 50); do # until gpioset holds the line (at most 5 s on a loaded host)
    v=$(cat "$sim/sim_gpio0/value")
    [ "$v" = 1 ] && break
    sleep 0.1
  done
  kill "$holder"; wait "$holder" 2>/dev/null
  [ "$v" = 1 ] && pass gpio_sim_rig_drives || fail gpio_sim_rig_drives "sim_gpio0/value was $v"
  # The far side pulls line 1 up; the rig reads it.
  echo pull-up > "$sim/sim_gpio1/pull"
  [ "$(gpioget "$chip" 1)" = 1 ] && pass gpio_sim_rig_reads || fail gpio_sim_rig_reads "gpioget read $(gpioget "$chip" 1)"
  echo pull-down > "$sim/sim_gpio1/pull"
  echo "$chip" > "$out/gpio-chip"
  echo "$sim" > "$out/gpio-sim-dir"
else
  fail gpio_sim_chip "no chip (chip_name '$chip')"
fi

step "CAN: vcan0, and can0/can1 (two SJA1000 boards on one QEMU CAN bus) at 500 kbit/s"
ip link add vcan0 type vcan && ip link set vcan0 up && pass vcan0_up || fail vcan0_up "ip link failed"
for i in can0 can1; do
  ip link set "$i" type can bitrate 500000 restart-ms 100 && ip link set "$i" up
  if ip -details link show "$i" | grep -q 'bitrate 500000'; then
    pass "${i}_up_500k"
  else
    fail "${i}_up_500k" "$(ip -details link show "$i" 2>&1 | tr '\n' ' ')"
  fi
done
ip -details link show can0 | sed 's/^/[guest]   /'
candump -n 1 -T 5000 -L can1 > "$TMPDIR/can1.log" &
dumper=$!
for _ in $(seq 20); do # resend until candump (bound some time after it started) has one
  cansend can0 123#DEADBEEF
  sleep 0.25
  kill -0 "$dumper" 2>/dev/null || break
done
wait
if grep -q '123#DEADBEEF' "$TMPDIR/can1.log"; then pass can0_to_can1; else fail can0_to_can1 "can1 saw: $(cat "$TMPDIR/can1.log")"; fi

step "serial: ttyS1 <-> ttyS2 (two UARTs joined by QEMU), 19200 8E1"
for t in ttyS1 ttyS2; do stty -F "/dev/$t" 19200 raw -echo cs8 parenb -parodd -cstopb; done
exec 3</dev/ttyS2 # the receiver is open before the first byte is sent
printf 'hilrig' > /dev/ttyS1
timeout 5 head -c 6 <&3 > "$TMPDIR/uart.txt"
exec 3<&-
if [ "$(cat "$TMPDIR/uart.txt")" = hilrig ]; then pass uart_s1_to_s2; else fail uart_s1_to_s2 "ttyS2 read '$(cat "$TMPDIR/uart.txt")'"; fi

for payload in $payloads; do
  name=$(basename "$payload" .sh)
  step "payload: $payload (started $(date +%T))"
  bash "$payload" "$out" "$chip" "$sim"
  status=$?
  if [ "$status" = 0 ]; then pass "$name"; else fail "$name" "exit $status"; fi
done

if [ "$failed" = 0 ]; then echo "RESULT PASS" | tee -a "$result"; else echo "RESULT FAIL" | tee -a "$result"; fi
sync
