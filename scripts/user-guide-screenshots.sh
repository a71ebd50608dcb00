#!/usr/bin/env bash
# Regenerates the pictures of the user guide, docs/images/guide-*.png, and the README's sphere,
# docs/images/sphere-view.png, from the running window: builds tst_user_guide and tst_sphere_view
# (Release) and runs them with GYRE_GUIDE_IMAGES set to docs/images, the guide's on a virtual X server
# of its screen size, so that each state pictured is saved there as the test reaches and checks it.
# Look at the pictures before committing them.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${GYRE_BUILD_DIR:-$here/build}"

"$here/scripts/install-deps.sh"
cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DGYRE_BUILD_TESTS=ON
cmake --build "$build" --parallel --target tst_user_guide tst_sphere_view

GYRE_GUIDE_IMAGES="$here/docs/images" QT_QPA_PLATFORM=xcb \
    xvfb-run -a -s "-screen 0 1600x1000x24" "$build/tests/gui/tst_user_guide"
# The README's sphere, the spinning top after its fit.
GYRE_GUIDE_IMAGES="$here/docs/images" QT_QPA_PLATFORM=offscreen \
    "$build/tests/gui/tst_sphere_view" theSpinningTopSampleAfterItsFit
echo "The guide's pictures are in $here/docs/images."
