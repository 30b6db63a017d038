#!/bin/bash
# Lane payload: the kernel-backend tests' GPIO half built against libgpiod 2.x
# (drivers/gpiod/gpiod_v2.cpp), run inside the guest against real gpio-sim through ctest. The build tree is
# configured with -DHILRIG_GPIOD_API=2 -DHILRIG_GPIOD_ROOT=<tree>/libgpiod2-root (the prefix
# scripts/fetch-libgpiod2.sh fills), and only test_kernel_gpiod needs building:
#   bash scripts/fetch-libgpiod2.sh build-gpiod2/libgpiod2-root
#   cmake --preset default -B build-gpiod2 -DHILRIG_GPIOD_API=2 -DHILRIG_GPIOD_ROOT=$PWD/build-gpiod2/libgpiod2-root
#   cmake --build build-gpiod2 --target test_kernel_gpiod
# Arguments from guest.sh: OUT CHIP SIM_DIR. HILRIG_GPIOD2_BUILD names the tree (default
# build-gpiod2 of this checkout; HILRIG_BUILD, the lane's main 1.6 build, is not this one),
# HILRIG_GPIOD_ROOT the prefix (default HILRIG_GPIOD2_BUILD/libgpiod2-root).
set -u
out=$1 chip=$2 sim=$3
here=$(cd "$(dirname "$0")" && pwd)
build=${HILRIG_GPIOD2_BUILD:-$here/../../build-gpiod2}
root=${HILRIG_GPIOD_ROOT:-$build/libgpiod2-root}
bin="$build/tests/kernel/test_kernel_gpiod"
[ -x "$bin" ] || { echo "payload-gpiod2: $bin not built"; exit 1; }
lib=$(dirname "$(compgen -G "$root/usr/lib/*/libgpiod.so.3" | head -n 1)")
[ -f "$lib/libgpiod.so.3" ] || { echo "payload-gpiod2: no libgpiod.so.3 under $root"; exit 1; }
export LD_LIBRARY_PATH="$lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
# Proof of which library the tests run on: the 2.x soname, from the private prefix.
used=$(ldd "$bin" | awk '/libgpiod\.so/ {print $1, $3}')
echo "[gpiod2] $used"
case "$used" in
  "libgpiod.so.3 $lib/"*) ;;
  *) echo "payload-gpiod2: $bin does not use $lib/libgpiod.so.3"; exit 1 ;;
esac
# Through ctest like the 1.6 build's (test_kernel_backends is not built in this tree: its
# placeholder test has no "kernel" label and is not run).
HILRIG_GPIO_CHIP=$chip HILRIG_GPIO_SIM=$sim bash "$here/ctest-kernel.sh" "$(dirname "$bin")" "$out" gpiod2
