#!/bin/sh
# Configures build-clang: the one clang tree that scripts/sanitize.sh and
# scripts/fuzz.sh share, so that CI compiles the libraries once for both. Every
# target there has AddressSanitizer + UndefinedBehaviorSanitizer and libFuzzer's
# coverage instrumentation (-DSCALLOP_FUZZ=ON implies -DSCALLOP_SANITIZE=ON); the
# coverage counters cost the sanitized test suite little, and the test suite and the
# fuzz targets link the same libraries. Prints the tree's folder.
set -eu
cd "$(dirname "$0")/.."
build=build-clang
CC=clang CXX=clang++ cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DSCALLOP_SANITIZE=ON -DSCALLOP_FUZZ=ON -DSCALLOP_BUILD_TESTS=ON >/dev/null
echo "$build"
