#!/usr/bin/env bash
# The README's first command: installs what Gyre needs, builds it (Release), and opens the desktop
# application on its bundled sample, the L-shaped cycle of the ScrewBender paper. On a machine without
# a display it runs the application on a virtual X server instead and saves a picture of its window.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${GYRE_BUILD_DIR:-$here/build}"

"$here/scripts/install-deps.sh"
cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" --parallel

app="$build/src/app/gyre"
if [[ -n "${DISPLAY:-}" || -n "${WAYLAND_DISPLAY:-}" ]]; then
    exec "$app" "$@"
fi
screenshot="$build/gyre-window.png"
echo "No display: running gyre on a virtual X server for a few seconds."
xvfb-run -a -s "-screen 0 1600x1000x24" env QT_QPA_PLATFORM=xcb "$app" --screenshot "$screenshot" --delay 4000 "$@"
echo "gyre opened the bundled sample; its window is in $screenshot."
echo "On a machine with a display, $app opens it for you to use; $build/src/cli/gyre-cli --help lists the batch verbs."
