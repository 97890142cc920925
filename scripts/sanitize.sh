#!/bin/sh
# Builds scallop with AddressSanitizer + UndefinedBehaviorSanitizer (-DSCALLOP_SANITIZE=ON)
# in build-asan, with its test suite (the tests' own files uninstrumented,
# tests/CMakeLists.txt), and runs the whole suite there. Any memory error, leak or
# undefined behaviour in scallop's code aborts the test that hit it, so ctest fails.
# Embree, TBB and OpenImageIO are Debian's uninstrumented shared libraries: errors
# inside them are not seen, but our code's use of their buffers is.
# Tests labelled asan_slow are left out, each for a reason given where it is labelled
# (none at present), and so is the slurm test (label slurm): it tests
# scripts/slurm-bands.sh on a one-node Slurm, not scallop's memory. The bad-input
# matrices (BadInputMatrix.*, ~200 runs of the binary checking exit codes and messages)
# are left out too: the plain suite runs them, and the readers they feed are fuzzed
# under ASan + UBSan (scripts/fuzz.sh) with far more inputs. They are 18 % of the
# plain suite's test time (when measured), more under ASan.
# Usage: scripts/sanitize.sh [extra ctest arguments]
set -eu
cd "$(dirname "$0")/.."
build=build-asan
# -O1 -g1, as the sanitizers' own documentation suggests: line tables are all a report's
# stack trace needs, and GCC compiles the instrumented code 2.3 times faster than at
# -O2 -g (55.8 s -> 23.8 s for tools/cli/collect_command.cpp; the cold build was 21 of
# CI's 42 minutes).
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DSCALLOP_SANITIZE=ON >/dev/null
cmake --build "$build" -j "$(nproc)" --target scallop scallop_tests
# detect_leaks: LeakSanitizer works here (it needs ptrace-free /proc access, which CI
# containers allow). abort_on_error gives a core-dump-style stop that ctest reports.
# The CLI tests run the sanitized scallop binary too, and inherit these settings.
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1:detect_stack_use_after_return=1:strict_string_checks=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
cd "$build"
ctest --output-on-failure -j "$(nproc)" --timeout 1800 -LE 'asan_slow|slurm|hunt' -E '^BadInputMatrix\.' "$@"
