#!/bin/sh
# Configures (Release, Ninja, ccache) and builds scallop into ./build: the targets
# named on the command line (`./scripts/build.sh scallop`: the CLI alone, what the
# quick start runs), or every target (the test suite, the micro-benchmarks, the Python
# module) when none is named.
set -eu
cd "$(dirname "$0")/.."
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
targets=""
for t in "$@"; do targets="$targets --target $t"; done
# shellcheck disable=SC2086  # one word per target
cmake --build build -j "$(nproc)" $targets
