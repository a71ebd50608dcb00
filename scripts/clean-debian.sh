#!/usr/bin/env bash
# Makes a clean Debian 12 in the empty folder ROOT for scripts/package-test.sh to install Gyre's
# package on: a minimal system made by debootstrap from Debian's archive, with nothing of the build
# machine in it, its package lists fetched and the virtual X server that starts gyre there installed.
# It needs the network and little CPU, so scripts/test.sh runs it while Gyre builds and its tests run.
# Needs root, or sudo, for debootstrap and chroot.
#
#   clean-debian.sh ROOT    (GYRE_DEBIAN_MIRROR names another mirror)
set -euo pipefail
[[ $# -eq 1 && -d "$1" ]] || { echo "usage: clean-debian.sh ROOT (an existing empty folder)" >&2; exit 2; }
root="$1"
mirror="${GYRE_DEBIAN_MIRROR:-http://deb.debian.org/debian}"
sudo_cmd=()
[[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)

chmod 755 "$root" # apt downloads as its own user, _apt, who must reach the system's folders
log="$(mktemp /tmp/gyre-debootstrap.XXXXXX.log)"
"${sudo_cmd[@]}" debootstrap --variant=minbase bookworm "$root" "$mirror" >"$log" 2>&1 ||
    { tail -n 20 "$log" >&2; echo "clean-debian: debootstrap could not make a Debian 12 system from $mirror (log: $log)" >&2; exit 1; }
rm -f "$log"
"${sudo_cmd[@]}" cp /etc/resolv.conf "$root/etc/resolv.conf"
"${sudo_cmd[@]}" tee "$root/etc/apt/sources.list" >/dev/null <<SOURCES
deb $mirror bookworm main
deb $mirror bookworm-updates main
deb ${mirror%/debian}/debian-security bookworm-security main
SOURCES
# There is no terminal in the chroot for dpkg to log through: Use-Pty=0.
"${sudo_cmd[@]}" chroot "$root" env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 \
    DEBIAN_FRONTEND=noninteractive sh -c 'apt-get update -q && apt-get install -y -q -o Dpkg::Use-Pty=0 xvfb xauth'
echo "clean-debian: a clean Debian 12 is ready in $root"
