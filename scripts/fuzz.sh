#!/bin/sh
# Builds the libFuzzer targets (one a seed folder tests/fuzz/corpus/NAME) with clang, ASan and UBSan in
# build-fuzz and runs each for SECONDS (default 60). A crash, sanitizer report, hang
# (> 10 s on one input) or blow-up (> 2 GB) stops that target, saves the input as
# build-fuzz/findings/NAME-crash-..., and makes this script exit 1 after all have run.
# New interesting inputs go to build-fuzz/corpus/NAME (the seeds in
# tests/fuzz/corpus/NAME are only read). Usage: scripts/fuzz.sh [SECONDS] [NAME...]
# (SECONDS = 0 only builds.)
set -eu
cd "$(dirname "$0")/.."
seconds=${1:-60}
[ $# -gt 0 ] && shift
build=build-fuzz
# -O1 -g1 as in scripts/sanitize.sh: the instrumented build compiles about twice as fast.
CC=clang CXX=clang++ cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DSCALLOP_FUZZ=ON \
  -DSCALLOP_BUILD_TESTS=OFF >/dev/null
names=${*:-$(cd tests/fuzz/corpus && ls -d -- */ | sed 's:/$::')}
targets=""
for n in $names; do targets="$targets ${n}_fuzz"; done
# shellcheck disable=SC2086
cmake --build "$build" -j2 --target $targets
if [ "$seconds" -le 0 ]; then exit 0; fi  # 0: build only
mkdir -p "$build/findings"
# Leaks are findings too; allocator_may_return_null turns a huge allocation into
# std::bad_alloc (a finding: readers must refuse before allocating) instead of an abort.
export ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=1:abort_on_error=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
failed=""
for n in $names; do
  mkdir -p "$build/corpus/$n"
  dict=""
  [ -f "tests/fuzz/$n.dict" ] && dict="-dict=tests/fuzz/$n.dict"
  echo "== fuzzing $n for ${seconds} s"
  # shellcheck disable=SC2086
  if ! "$build/tests/fuzz/${n}_fuzz" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -max_len=4096 -print_final_stats=1 -artifact_prefix="$build/findings/$n-" $dict \
    "$build/corpus/$n" "tests/fuzz/corpus/$n" 2>"$build/findings/$n.log"; then
    failed="$failed $n"
    tail -n 60 "$build/findings/$n.log"
  else
    grep -E "^(#[0-9]+.*DONE|stat::number_of_executed_units|stat::peak_rss)" "$build/findings/$n.log" || true
  fi
done
if [ -n "$failed" ]; then
  echo "fuzz.sh: findings in:$failed (inputs in $build/findings; add each to tests/fuzz/regressions)"
  exit 1
fi
echo "fuzz.sh: no findings"
