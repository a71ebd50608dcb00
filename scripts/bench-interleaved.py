#!/usr/bin/env python3
# Compares gyre-bench binaries of several builds in interleaved runs, as the figures in docs/ are
# measured on a machine others share: ROUNDS times, each binary in turn runs the benchmarks FILTER
# matches (three repetitions each); then each benchmark's CPU time per item, as the minimum and
# median of every run of each binary, in µs. For BM_Fit/N the item is a key (time / N); otherwise an iteration.
#
#   scripts/bench-interleaved.py ROUNDS FILTER GYRE_BENCH...
#
# e.g. scripts/bench-interleaved.py 3 'BM_Fit/(100|400|2000|3000)$' /tmp/before/gyre-bench build/tests/bench/gyre-bench
import collections
import json
import subprocess
import sys

if len(sys.argv) < 4:
    sys.exit("usage: bench-interleaved.py ROUNDS FILTER GYRE_BENCH...")
rounds = int(sys.argv[1])
pattern = sys.argv[2]
binaries = sys.argv[3:]
times = collections.defaultdict(list)
for _ in range(rounds):
    for binary in binaries:
        run = subprocess.run([binary, "--benchmark_filter=" + pattern, "--benchmark_format=json",
                              "--benchmark_repetitions=3"], capture_output=True, text=True, check=True)
        for benchmark in json.loads(run.stdout)["benchmarks"]:
            if benchmark.get("run_type") == "iteration":
                microseconds = {"ns": 1e-3, "us": 1.0, "ms": 1e3, "s": 1e6}[benchmark["time_unit"]]
                times[(binary, benchmark["run_name"])].append(benchmark["cpu_time"] * microseconds)


def items(name):
    return int(name.split("/")[1]) if name.startswith("BM_Fit/") else 1


names = sorted({name for _, name in times}, key=lambda name: (name.split("/")[0], items(name)))
for name in names:
    row = [name]
    for binary in binaries:
        values = sorted(value / items(name) for value in times[(binary, name)])
        row.append("%s: min %.4g µs, median %.4g µs %s" % (binary, values[0], values[len(values) // 2],
                                                          "CPU a key" if items(name) > 1 else "CPU"))
    print(" | ".join(row))
