#!/bin/bash
# Lane payload: the kernel-backend GoogleTest binary, run inside the guest against real
# gpio-sim, vcan and SJA1000 CAN. Arguments from guest.sh: OUT CHIP SIM_DIR.
set -u
out=$1 chip=$2 sim=$3
here=$(cd "$(dirname "$0")" && pwd)
bin="$here/../../build/tests/kernel/test_kernel_backends"
[ -x "$bin" ] || { echo "payload: $bin not built"; exit 1; }
ip link set vcan0 down && ip link set vcan0 mtu 72 && ip link set vcan0 up # CAN FD on vcan0
HILRIG_GPIO_CHIP=$chip HILRIG_GPIO_SIM=$sim "$bin" --gtest_output="xml:$out/kernel-tests.xml" 2>&1 | sed 's/^/[kernel-tests] /'
exit "${PIPESTATUS[0]}"
