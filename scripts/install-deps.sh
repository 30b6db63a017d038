#!/usr/bin/env bash
# The one place hilrig's Debian 12 packages are named. Installs only what is missing,
# so `make demo` and `make test` can call it every time at no cost.
set -euo pipefail

# package            why
packages=(
  build-essential     # g++ 12 (C++20), make; libstdc++.a and libgcc.a, linked into hilrig (HILRIG_STATIC_RUNTIME)
  cmake               # build system (>= 3.25)
  ninja-build         # fast parallel builds for every preset
  pkg-config          # finds libgpiod and libmodbus
  libgtest-dev        # GoogleTest: unit, property and virtual-lane tests
  libgmock-dev        # GoogleMock, shipped with GoogleTest
  libbenchmark-dev    # Google Benchmark: bench/
  libboost-dev        # Boost.Asio: serial ports, host-link I/O, signals on the non-RT side
  libeigen3-dev       # plant models (shafts, press brake, stepper load)
  libtomlplusplus-dev # campaign files (TOML) with line/column in errors; its headers compiled into hilrig (deps/)
  libcli11-dev        # the hilrig command line
  libfmt-dev          # formatting of reports and messages; its headers compiled into hilrig (deps/)
  nlohmann-json3-dev  # results.json, shard merging, baselines
  nettle-dev          # SHA-256 of the campaign file in results.json (merge refuses mixed revisions); not libssl: its load costs every run ~1.5 ms; libnettle.a linked in
  libmodbus-dev       # Modbus RTU/TCP host link and the virtual SMD23E server
  libgpiod-dev        # GPIO backend (libgpiod 1.6 on Debian 12); libgpiod.a linked in
  mbpoll              # an independent Modbus client for integration tests
  can-utils           # candump/log2asc/canplayer: read the rig's CAN logs
  rt-tests            # cyclictest: the peer for the RT loop's latency
  python3             # test helpers: an independent VCD/JUnit reader
  libxml2-utils       # xmllint: junit.xml validated against Jenkins' JUnit schema (tests/results)
  chromium            # headless browser: report.html of every shipped campaign loaded and screenshotted, a figure per judged check (tests/results)
  parallel            # GNU parallel: docs/ci.md's sharding recipe, run as a test
  gtkwave             # vcd2fst/fst2vcd: trace.vcd read as GTKWave reads it (tests/tools)
  clang-format        # the committed .clang-format
  clang               # the fuzzers' compiler (build-fuzz/, make fuzz-smoke and make fuzz)
  libclang-rt-14-dev  # libFuzzer and the ASan/UBSan runtimes clang links the fuzzers with
)

# The RT VM lane (rt-config/vm/, `make test-vm`) needs more: `install-deps.sh --vm`.
if [ "${1:-}" = "--vm" ]; then
  # The PREEMPT_RT kernel behind Debian's metapackage; its image is downloaded and extracted
  # by rt-config/vm/prepare.sh (never installed on the host), its headers are installed here.
  kabi=$(apt-cache depends linux-image-rt-amd64 2>/dev/null | awk '/Depends: linux-image-[0-9]/ {print $2; exit}')
  if [ -z "$kabi" ] && [ "$(id -u)" -eq 0 ]; then
    apt-get update -qq
    kabi=$(apt-cache depends linux-image-rt-amd64 2>/dev/null | awk '/Depends: linux-image-[0-9]/ {print $2; exit}')
  fi
  packages+=(
    qemu-system-x86          # boots the PREEMPT_RT kernel under TCG
    busybox-static           # the guest's initramfs
    cpio                     # packs the initramfs
    kmod                     # modinfo: module dependency order for the guest
    iproute2                 # ip link: vcan, CAN bitrates inside the guest
    linux-source-6.1         # gpio-sim.c and irq_sim.c, built as a module
    bc                       # kernel module build (Kbuild)
    "linux-headers-${kabi#linux-image-}" # module build against the guest kernel
    gpiod                    # gpiodetect/gpioinfo in the guest: shows the gpio-sim chip
  )
  # libgpiod 2.x (bookworm-backports) for the lane's second GPIO backend build, build-gpiod2/:
  # downloaded and unpacked into a private prefix there, never installed (it conflicts with 1.6).
  bash "$(dirname "$0")/fetch-libgpiod2.sh" "$(dirname "$0")/../build-gpiod2/libgpiod2-root"
fi

want=()
# npm: installs report-web/'s locked uPlot (npm ci below), embedded into hilrig's report.html.
# Debian's package when no npm is on the PATH (a node distribution's own npm serves as well).
command -v npm >/dev/null || want+=(npm)
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    want+=("$p")
  fi
done

if [ ${#want[@]} -gt 0 ]; then
  if [ "$(id -u)" -ne 0 ]; then
    echo "install-deps: missing packages: ${want[*]}" >&2
    echo "install-deps: run as root (or: sudo $0)" >&2
    exit 1
  fi
  echo "install-deps: installing ${want[*]}"
  export DEBIAN_FRONTEND=noninteractive
  # An old package list can miss packages: refresh once, then install.
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${want[@]}"
fi

# The report's front end (report-web/): uPlot at the version and integrity hash its
# package-lock.json pins, installed again whenever the lock is newer than what npm installed
# (npm writes node_modules/.package-lock.json last). The build embeds it (rig/results/).
web="$(cd "$(dirname "$0")/../report-web" && pwd)"
if [ ! -f "$web/node_modules/.package-lock.json" ] || [ "$web/package-lock.json" -nt "$web/node_modules/.package-lock.json" ]; then
  echo "install-deps: npm ci in report-web/"
  (cd "$web" && npm ci --no-audit --no-fund --loglevel=error)
fi
