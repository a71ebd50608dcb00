#!/bin/sh
# Measures Gyre's project files at scale (docs/file-format.md, "Cost"): a BVH of JOINTS joints and
# FRAMES frames, written by scripts/mocap-bvh.py, imported into a project, the project summarised
# (`info`, which opens it) and exported as glb, next to `info` of the BVH itself and Assimp's own read
# of it. Each BIN is a folder holding a gyre-cli and its gyre-scene-worker (a build's src/cli and
# src/worker copied together, or a build tree); with several, the runs alternate between them, ROUNDS
# times, so that builds are compared in interleaved runs on a shared machine.
#
#   scripts/project-scale.sh JOINTS FRAMES ROUNDS BENCH BIN...
#
# BENCH is the gyre-bench of a Release build, for BM_AssimpReadBvh on the same file (its wall-clock
# and CPU time). Each line gives the build, the step, the wall-clock seconds, the CPU seconds (user and
# system, of gyre-cli and the gyre-scene-worker it ended), the largest resident set of those processes
# in MB (/usr/bin/time -v: whichever was larger), and the size of the file it wrote. On a machine
# others share, the CPU seconds vary less than the wall-clock ones.
set -eu
[ $# -ge 5 ] || { sed -n '2,15p' "$0"; exit 2; }
joints=$1 frames=$2 rounds=$3 bench=$4
shift 4
work=${GYRE_SCALE_DIR:-/tmp/gyre-project-scale}
mkdir -p "$work"
bvh=$work/mocap-$joints-$frames.bvh
[ -f "$bvh" ] || "$(dirname "$0")/mocap-bvh.py" "$joints" "$frames" "$bvh"
echo "$bvh: $(stat -c %s "$bvh") bytes"

# step NAME OUTPUT COMMAND...: runs the command under /usr/bin/time -v and prints its line.
step() {
    name=$1 output=$2
    shift 2
    if ! /usr/bin/time -v -o "$work/time" "$@" > /dev/null 2> "$work/stderr"; then
        echo "$label $name: failed: $(tail -n 1 "$work/stderr")"
        return
    fi
    seconds=$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$work/time" |
        awk -F: '{ s = 0; for (i = 1; i <= NF; i++) s = s * 60 + $i; print s }')
    cpu=$(awk -F': ' '/User time|System time/ { s += $2 } END { print s }' "$work/time")
    megabytes=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$work/time" | awk '{ printf "%.0f", $1 / 1024 }')
    size=""
    [ -n "$output" ] && [ -f "$output" ] && size=" $(stat -c %s "$output") bytes"
    echo "$label $name: $seconds s, CPU $cpu s, $megabytes MB$size"
}

round=1
while [ "$round" -le "$rounds" ]; do
    assimp=$(GYRE_BENCH_BVH=$bvh "$bench" --benchmark_filter='BM_AssimpReadBvh$' --benchmark_min_time=0.001 2>/dev/null |
        awk '/^BM_AssimpReadBvh/ { print $2 / 1000 " s, CPU " $4 / 1000 " s" }')
    echo "round $round: Assimp's read (BM_AssimpReadBvh): $assimp"
    for bin in "$@"; do
        label="round $round, $bin:"
        project=$work/project.gyre
        rm -f "$project" "$work/export.glb" "$work/export.bin"
        step "import" "$project" "$bin/gyre-cli" import "$bvh" -o "$project"
        step "info of the project" "" "$bin/gyre-cli" info "$project"
        step "info of the BVH" "" "$bin/gyre-cli" info "$bvh"
        step "export as glb" "$work/export.glb" "$bin/gyre-cli" export "$project" -o "$work/export.glb"
    done
    round=$((round + 1))
done
