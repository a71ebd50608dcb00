#!/usr/bin/env bash
# The README's second command, and what CI runs: installs what Gyre needs, builds it with warnings as
# errors under AddressSanitizer and UndefinedBehaviorSanitizer, runs every test, then builds, installs
# and starts the Debian package.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${GYRE_TEST_BUILD_DIR:-$here/build-test}"

"$here/scripts/install-deps.sh"
cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DGYRE_SANITIZE=ON -DGYRE_WERROR=ON
cmake --build "$build" --parallel
ctest --test-dir "$build" --output-on-failure --parallel "$(nproc)"
"$here/scripts/package-test.sh"
