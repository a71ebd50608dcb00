#!/usr/bin/env bash
# Runs the libFuzzer harnesses of tests/fuzz: builds them with clang (AddressSanitizer,
# UndefinedBehaviorSanitizer, libFuzzer) in build-fuzz, writes the mutation test's seed files as the
# starting corpus, and runs each harness for a bounded time. Inputs that fail are left as
# build-fuzz/fuzz/crash-* (libFuzzer's names); the grown corpus stays in build-fuzz/fuzz/corpus.
#
#   scripts/fuzz.sh [SECONDS_PER_HARNESS]   default 60; more libFuzzer flags in GYRE_FUZZ_FLAGS
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${GYRE_FUZZ_BUILD_DIR:-$here/build-fuzz}"
seconds="${1:-60}"

launcher=()
if command -v ccache >/dev/null; then
    launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
      -DGYRE_FUZZ=ON -DGYRE_SANITIZE=ON -DGYRE_BUILD_BENCH=OFF "${launcher[@]}"
cmake --build "$build" --parallel "$(nproc)" --target fuzz_pose_csv fuzz_project gyre_fuzz_corpus

work="$build/fuzz"
mkdir -p "$work/corpus"
"$build/tests/fuzz/gyre_fuzz_corpus" "$work/seeds"
for harness in pose_csv project; do
    mkdir -p "$work/corpus/$harness"
    echo "== fuzz_$harness for $seconds s"
    (cd "$work" && "$build/tests/fuzz/fuzz_$harness" -max_total_time="$seconds" -timeout=5 -rss_limit_mb=2048 \
        -print_final_stats=1 ${GYRE_FUZZ_FLAGS:-} "corpus/$harness" "seeds/$harness")
done
