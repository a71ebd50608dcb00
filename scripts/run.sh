#!/usr/bin/env bash
# The README's first command: installs what Gyre needs, builds it (Release), and runs it on the
# bundled sample. Until the desktop app exists, "running it" means gyre-cli smoothing the L-shaped
# cycle of the ScrewBender paper and converting the result to Euler angles.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${GYRE_BUILD_DIR:-$here/build}"

"$here/scripts/install-deps.sh"
cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" --parallel

cli="$build/src/cli/gyre-cli"
sample="$here/resources/samples/l-cycle.csv"
out="$build/samples"
mkdir -p "$out"
"$cli" subdivide "$sample" -o "$out/l-cycle-jarek.csv" --scheme jarek --levels 4
"$cli" convert "$out/l-cycle-jarek.csv" -o "$out/l-cycle-jarek-euler.csv" --to euler --order zyx --intrinsic
echo
echo "Subdivided the 6 control poses of $sample into $(($(grep -vc '^#' "$out/l-cycle-jarek.csv") - 1)) poses (Jarek, 4 levels):"
head -n 6 "$out/l-cycle-jarek-euler.csv"
echo "..."
echo "Full results: $out/l-cycle-jarek.csv (quaternions) and $out/l-cycle-jarek-euler.csv (intrinsic zyx angles)."
echo "Try: $cli --help"
