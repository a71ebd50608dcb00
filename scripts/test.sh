#!/usr/bin/env bash
# The README's second command, and what CI runs: installs what Gyre needs, builds it with warnings as
# errors under AddressSanitizer and UndefinedBehaviorSanitizer, runs every test, then builds, installs
# and starts the Debian package. The clean Debian 12 the package is installed on is made while Gyre
# builds and its tests run: debootstrap waits on the network, not on the two cores the build needs.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${GYRE_TEST_BUILD_DIR:-$here/build-test}"
sudo_cmd=()
[[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)

"$here/scripts/install-deps.sh"

clean_root="$(mktemp -d /tmp/gyre-clean-debian.XXXXXX)"
clean_log="$clean_root.log"
"$here/scripts/clean-debian.sh" "$clean_root" >"$clean_log" 2>&1 &
clean_pid=$!
# Whatever ends this script, the clean system goes: stopped first if it is still being made.
# --one-file-system: never follow a mount out of it.
trap 'kill "$clean_pid" 2>/dev/null || true; wait "$clean_pid" 2>/dev/null || true
      "${sudo_cmd[@]}" rm -rf --one-file-system "$clean_root" "$clean_log"' EXIT

# Line tables only (-g1): the sanitizers' reports keep every file and line, and the build takes a
# seventh less time to compile than with full debug information.
cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-g1 -DGYRE_SANITIZE=ON \
      -DGYRE_WERROR=ON
cmake --build "$build" --parallel
ctest --test-dir "$build" --output-on-failure --parallel "$(nproc)"
"$here/scripts/slowest-test-functions.sh" "$build"

wait "$clean_pid" || { cat "$clean_log" >&2; echo "test.sh: the clean Debian 12 for the package test could not be made" >&2; exit 1; }
GYRE_CLEAN_DEBIAN="$clean_root" "$here/scripts/package-test.sh"
