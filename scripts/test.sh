#!/bin/sh
# Builds scallop and runs the whole test suite (GoogleTest through CTest).
set -eu
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
./scripts/build.sh
cd build
ctest --output-on-failure -j "$(nproc)" --timeout 1200
