#!/usr/bin/env bash
# Prepares the RT VM lane in WORK (default build-vm/): Debian's PREEMPT_RT kernel image
# (extracted, not installed), the gpio-sim module built from Debian's own kernel source
# (Debian's 6.1 kernels are built without CONFIG_GPIO_SIM), and a busybox initramfs that
# mounts the host's root read-only over 9p. Everything is cached by kernel version.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=${1:-build-vm}
mkdir -p "$work"
work=$(cd "$work" && pwd)
step() { printf '[vm-lane] %s\n' "$*"; }

# The kernel ABI behind the linux-image-rt-amd64 metapackage, e.g. 6.1.0-56-rt-amd64.
image_pkg=$(apt-cache depends linux-image-rt-amd64 2>/dev/null | awk '/Depends: linux-image-[0-9]/ {print $2; exit}')
[ -n "$image_pkg" ] || { echo "vm-lane: cannot resolve linux-image-rt-amd64 (apt-get update?)" >&2; exit 1; }
kver=${image_pkg#linux-image-}
echo "$kver" > "$work/kernel-version"
step "kernel $kver"

kdir="$work/kernel-$kver"
if [ ! -f "$kdir/boot/vmlinuz-$kver" ]; then
  step "downloading and extracting $image_pkg"
  tmp=$(mktemp -d)
  (cd "$tmp" && apt-get download "$image_pkg" >/dev/null)
  rm -rf "$kdir" && mkdir -p "$kdir"
  dpkg -x "$tmp"/"$image_pkg"_*.deb "$kdir"
  rm -rf "$tmp"
fi

headers="/usr/src/linux-headers-$kver"
[ -d "$headers" ] || { echo "vm-lane: $headers missing: run scripts/install-deps.sh --vm" >&2; exit 1; }

mod="$work/gpio-sim-$kver"
if [ ! -f "$mod/gpio-sim-rig.ko" ]; then
  step "building gpio-sim from Debian's linux-source"
  src_tar=$(compgen -G '/usr/src/linux-source-*.tar.xz' | head -n 1 || true)
  [ -n "$src_tar" ] || { echo "vm-lane: no /usr/src/linux-source-*.tar.xz: run scripts/install-deps.sh --vm" >&2; exit 1; }
  top=$(basename "$src_tar" .tar.xz)
  rm -rf "$mod" && mkdir -p "$mod"
  tar -xJf "$src_tar" -C "$mod" --strip-components=3 "$top/drivers/gpio/gpio-sim.c" "$top/drivers/gpio/gpiolib.h"
  tar -xJf "$src_tar" -C "$mod" --strip-components=3 "$top/kernel/irq/irq_sim.c"
  # irq_to_desc() is not exported to modules; generic_handle_irq() does the same here.
  sed -i 's/handle_simple_irq(irq_to_desc(irqnum));/generic_handle_irq(irqnum);/' "$mod/irq_sim.c"
  grep -q 'generic_handle_irq(irqnum);' "$mod/irq_sim.c" || { echo "vm-lane: irq_sim.c patch did not apply" >&2; exit 1; }
  cp "$here/gpio-sim.Kbuild" "$mod/Kbuild"
  make -s -C "$headers" M="$mod" modules >"$mod/build.log" 2>&1 || { tail -20 "$mod/build.log"; exit 1; }
fi

# Modules the guest loads, in dependency order, from the extracted tree (and gpio-sim).
moddir="$kdir/lib/modules/$kver"
order_file="$work/guest-modules"
: > "$order_file"
declare -A seen=()
add_module() { # add_module NAME: its dependencies first
  local name=$1 path deps d
  [ -n "${seen[$name]:-}" ] && return
  seen[$name]=1
  path=$(find "$moddir/kernel" -name "$name.ko" -print -quit)
  [ -n "$path" ] || { echo "vm-lane: module $name not in $kver" >&2; exit 1; }
  deps=$(modinfo -F depends "$path")
  for d in ${deps//,/ }; do add_module "$d"; done
  echo "$path" >> "$order_file"
}
for m in can can-raw can-dev vcan sja1000 kvaser_pci configfs; do add_module "$m"; done
echo "$mod/gpio-sim-rig.ko" >> "$order_file"

# The initramfs: busybox, the 9p chain, and /init.
initrd="$work/initrd-$kver.cpio.gz"
if [ ! -f "$initrd" ] || [ "$here/init" -nt "$initrd" ]; then
  step "building the initramfs"
  root=$(mktemp -d)
  mkdir -p "$root"/{bin,dev,proc,sys,host,lib/modules}
  cp /bin/busybox "$root/bin/busybox"
  for m in virtio_ring virtio virtio_pci_modern_dev virtio_pci_legacy_dev virtio_pci netfs fscache 9pnet 9pnet_virtio 9p; do
    cp "$(find "$moddir/kernel" -name "$m.ko" -print -quit)" "$root/lib/modules/"
  done
  cp "$here/init" "$root/init"
  chmod +x "$root/init"
  (cd "$root" && find . | cpio -o -H newc --quiet | gzip -1) > "$initrd"
  rm -rf "$root"
fi
step "ready: $kdir/boot/vmlinuz-$kver, $initrd, gpio-sim-rig.ko"
