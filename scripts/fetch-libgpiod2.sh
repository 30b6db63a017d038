#!/usr/bin/env bash
# libgpiod 2.x for the second GPIO backend (drivers/gpiod/gpiod_v2.cpp), without touching the
# system's libgpiod 1.6: Debian 12's own bookworm-backports ships libgpiod 2.1 (libgpiod3,
# libgpiod-dev), whose -dev package conflicts with the installed 1.6 one. So the two packages
# are downloaded, never installed, and unpacked into a private prefix the build points at:
#   cmake ... -DHILRIG_GPIOD_API=2 -DHILRIG_GPIOD_ROOT=PREFIX
# Usage: fetch-libgpiod2.sh [PREFIX] (default build-gpiod2/libgpiod2-root). Cached: a second
# call with the headers already there does nothing. Needs root the first time (apt source).
set -euo pipefail
prefix=${1:-build-gpiod2/libgpiod2-root}
say() { printf 'fetch-libgpiod2: %s\n' "$*"; }

if [ -f "$prefix/usr/include/gpiod.h" ] && grep -q gpiod_line_settings_new "$prefix/usr/include/gpiod.h"; then
  exit 0
fi

# bookworm-backports as an apt source, on the same mirror and key as the machine's bookworm
# entry. Backports are pinned at priority 100 by their Release file, so nothing installed
# changes: packages come from there only when asked for by name (pkg/bookworm-backports).
list=/etc/apt/sources.list.d/hilrig-bookworm-backports.sources
if ! apt-cache policy 2>/dev/null | grep -q 'bookworm-backports/main'; then
  [ "$(id -u)" -eq 0 ] || { say "run as root once to add bookworm-backports as an apt source" >&2; exit 1; }
  uri=""
  keyring=/usr/share/keyrings/debian-archive-keyring.gpg
  # deb822 files first (Debian 12's default), then one-line lists.
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] || continue
    uri=$(awk 'BEGIN{RS=""} /Suites:[^\n]*bookworm([ \n]|$)/ && /Components:[^\n]*main/ {
                 if (match($0, /URIs: *[^ \n]+/)) { u = substr($0, RSTART, RLENGTH); sub(/URIs: */, "", u); print u; exit } }' "$f")
    [ -n "$uri" ] && break
  done
  if [ -z "$uri" ]; then
    uri=$(cat /etc/apt/sources.list /etc/apt/sources.list.d/*.list 2>/dev/null |
      awk '$1 == "deb" && $0 ~ / bookworm main/ { for (i = 2; i <= NF; i++) if ($i ~ /:\/\//) { print $i; exit } }')
  fi
  [ -n "$uri" ] || { say "no bookworm apt source found to derive the backports mirror from" >&2; exit 1; }
  say "adding bookworm-backports ($uri) as an apt source: $list"
  printf 'Types: deb\nURIs: %s\nSuites: bookworm-backports\nComponents: main\nSigned-By: %s\n' "$uri" "$keyring" >"$list"
  apt-get update -qq
fi

mkdir -p "$prefix"
prefix=$(cd "$prefix" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
chown _apt "$tmp" 2>/dev/null || true # apt downloads as user _apt
say "downloading libgpiod3 and libgpiod-dev from bookworm-backports"
(cd "$tmp" && apt-get download -qq libgpiod3/bookworm-backports libgpiod-dev/bookworm-backports)
for deb in "$tmp"/*.deb; do
  say "unpacking $(basename "$deb") into $prefix"
  dpkg -x "$deb" "$prefix"
done
grep -q gpiod_line_settings_new "$prefix/usr/include/gpiod.h" ||
  { say "$prefix/usr/include/gpiod.h is not the 2.x API" >&2; exit 1; }
say "ready: $prefix (libgpiod $(sed -n 's/^Version: *//p' "$prefix"/usr/lib/*/pkgconfig/libgpiod.pc))"
