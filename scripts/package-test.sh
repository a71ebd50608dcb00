#!/usr/bin/env bash
# Builds Gyre's Debian package (Release, `cpack -G DEB`), checks what it holds, and installs it with apt
# on a clean Debian 12: a minimal system made by debootstrap from Debian's archive, with nothing of the
# build machine in it (scripts/clean-debian.sh; GYRE_CLEAN_DEBIAN names one already made). There the
# installed gyre-cli must run a verb, and the installed gyre must open its bundled sample on a virtual
# X server and draw its window (kept as build-package/installed-gyre.png to look at). test.sh runs this
# after the tests. Needs root, or sudo, for debootstrap and chroot.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${GYRE_PACKAGE_BUILD_DIR:-$here/build-package}"
app_id=org.gyre.Gyre

fail() { echo "package-test: $*" >&2; exit 1; }

"$here/scripts/install-deps.sh"
cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DGYRE_BUILD_TESTS=OFF -DGYRE_BUILD_BENCH=OFF
cmake --build "$build" --parallel
rm -f "$build"/gyre_*.deb
(cd "$build" && cpack -G DEB)
package="$(ls "$build"/gyre_*.deb)"
echo "package-test: built $package"

contents="$(dpkg-deb --contents "$package")"
expected=(./usr/bin/gyre ./usr/bin/gyre-cli ./usr/bin/gyre-scene-worker "./usr/share/applications/$app_id.desktop"
    "./usr/share/metainfo/$app_id.metainfo.xml" "./usr/share/mime/packages/$app_id.xml"
    "./usr/share/icons/hicolor/scalable/apps/$app_id.svg" ./usr/share/doc/gyre/user-guide.md
    ./usr/share/doc/gyre/images/guide-window.png)
for size in 16 22 24 32 48 64 128 256 512; do
    expected+=("./usr/share/icons/hicolor/${size}x${size}/apps/$app_id.png")
done
for file in "${expected[@]}"; do
    grep -q " $file\$" <<<"$contents" || fail "$package lacks $file"
done

sudo_cmd=()
[[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)
# The clean system scripts/test.sh made while the tests ran, or a new one.
root="${GYRE_CLEAN_DEBIAN:-}"
if [[ -z "$root" ]]; then
    root="$(mktemp -d /tmp/gyre-clean-debian.XXXXXX)"
    # --one-file-system: never follow a mount out of the clean system.
    trap '"${sudo_cmd[@]}" rm -rf --one-file-system "$root"' EXIT
    echo "package-test: making a clean Debian 12 in $root"
    "$here/scripts/clean-debian.sh" "$root"
fi
[[ -x "$root/usr/bin/Xvfb" ]] || fail "$root is not a clean Debian 12 made by scripts/clean-debian.sh"
"${sudo_cmd[@]}" cp "$package" "$root/tmp/"
in_root() {
    "${sudo_cmd[@]}" chroot "$root" env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 \
        DEBIAN_FRONTEND=noninteractive XDG_RUNTIME_DIR=/tmp/runtime "$@"
}

# As a user installs it: apt fetches what the package depends on.
in_root apt-get install -y -q -o Dpkg::Use-Pty=0 "/tmp/$(basename "$package")"

version="$(dpkg-deb --field "$package" Version)"
[[ "$(in_root gyre-cli --version)" == "gyre-cli $version" ]] || fail "the installed gyre-cli is not the package's version, $version"
in_root sh -c 'printf "time,qw,qx,qy,qz\n0,1,0,0,0\n1,0,0,0,1\n" >/tmp/keys.csv'
in_root gyre-cli interpolate /tmp/keys.csv -o /tmp/frames.csv --method slerp --fps 10
[[ "$(in_root sh -c 'grep -c "^[0-9]" /tmp/frames.csv')" -eq 11 ]] || fail "the installed gyre-cli wrote no 11 frames"
# Scene files are read by gyre-scene-worker, which the installed gyre-cli must find beside itself.
in_root sh -c 'printf "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n" >/tmp/triangle.obj'
in_root gyre-cli info /tmp/triangle.obj | grep -q "^1 object" || fail "the installed gyre-cli cannot read a scene file"

in_root install -d -m 700 /tmp/runtime
in_root xvfb-run -a -s "-screen 0 1600x1000x24" env QT_QPA_PLATFORM=xcb gyre --screenshot /tmp/window.png --delay 4000 \
    || fail "the installed gyre did not start"
"${sudo_cmd[@]}" cp "$root/tmp/window.png" "$build/installed-gyre.png"
[[ -s "$build/installed-gyre.png" ]] || fail "the installed gyre drew no window"
echo "package-test: $package installs on a clean Debian 12, and gyre and gyre-cli start there (gyre-cli reads a scene through gyre-scene-worker);"
echo "package-test: the installed gyre's window is in $build/installed-gyre.png."
