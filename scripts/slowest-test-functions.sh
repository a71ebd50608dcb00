#!/usr/bin/env bash
# Lists the slowest QtTest functions of the last ctest run in the build folder BUILD, from the JUnit
# files each test program writes beside itself (gyre_add_test and gyre_add_gui_test in
# tests/CMakeLists.txt). Every function must stay under a minute in the sanitizer build on a 2-core
# machine; QtTest's watchdog (QTEST_FUNCTION_TIMEOUT, set for every test) fails one that does not.
#
#   slowest-test-functions.sh BUILD [COUNT]   (COUNT: how many, default 10)
set -euo pipefail
[[ $# -ge 1 && -d "$1" ]] || { echo "usage: slowest-test-functions.sh BUILD [COUNT]" >&2; exit 2; }
count="${2:-10}"
mapfile -t files < <(find "$1" -name '*.junit.xml')
[[ ${#files[@]} -gt 0 ]] || { echo "slowest-test-functions: no JUnit files under $1: run ctest first" >&2; exit 1; }
echo "The $count slowest test functions (seconds, test program, function):"
# <testcase name="f" classname="TestX" time="1.234"/>: one a function, with its rows' time summed.
for file in "${files[@]}"; do
    program="$(basename "$file" .junit.xml)"
    grep -o '<testcase [^>]*>' "$file" |
        sed -n 's/<testcase name="\([^"]*\)"[^>]*time="\([0-9.]*\)".*/\2 '"$program"' \1/p'
# sed, not head, keeps the first lines: head leaves when it has them, and sort, still writing, would
# die of SIGPIPE (141), which pipefail makes this script's exit status.
done | sort -rn | sed -n "1,${count}p"
