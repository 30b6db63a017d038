#!/bin/bash
# Lane payload: the kernel-backend tests (gpiod; SocketCAN and the rig's hardware ports), run
# inside the guest against real gpio-sim, vcan and SJA1000 CAN through ctest (-C lane -L
# kernel: one named test per case, see ctest-kernel.sh). Arguments from guest.sh: OUT CHIP
# SIM_DIR. The tests are taken from HILRIG_BUILD (default: the checkout's build/).
set -u
out=$1 chip=$2 sim=$3
here=$(cd "$(dirname "$0")" && pwd)
dir="${HILRIG_BUILD:-$here/../../build}/tests/kernel"
for t in test_kernel_gpiod test_kernel_backends; do
  [ -x "$dir/$t" ] || { echo "payload: $dir/$t not built"; exit 1; }
done
ip link set vcan0 down && ip link set vcan0 mtu 72 && ip link set vcan0 up # CAN FD on vcan0
HILRIG_GPIO_CHIP=$chip HILRIG_GPIO_SIM=$sim bash "$here/ctest-kernel.sh" "$dir" "$out" kernel-tests
