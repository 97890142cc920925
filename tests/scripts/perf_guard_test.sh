#!/bin/sh
# The performance guard can fail: B1 with a deliberate 5 % slowdown (the driver casts 5 %
# of the rows twice) must exceed the 2 % threshold against the baseline, and the same build
# without it must pass. Argument: the build folder. Skipped (77) without valgrind.
set -u
build=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
command -v valgrind >/dev/null || { echo "valgrind not installed: skipped"; exit 77; }
if "$root/scripts/perf-guard.sh" --build "$build" --no-build --case B1 --extra-cells 5; then
  echo "FAIL: the guard passed a 5 % slowdown" >&2
  exit 1
fi
"$root/scripts/perf-guard.sh" --build "$build" --no-build --case B1 || {
  echo "FAIL: the guard failed the build as it is (is tests/benchmarks/perf-baseline.txt current?)" >&2
  exit 1
}
echo "the guard fails a 5 % slowdown and passes the build"
