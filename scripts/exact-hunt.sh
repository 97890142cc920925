#!/bin/sh
# The exactness hunt (docs/testing.md "The exactness hunt"): adversarial single moves of
# every cutter and path kind run through the whole pipeline, each cell checked against
# certificates that share no code with the kernel. CI runs 1e5 cells (the ExactHunt ctest);
# a release runs 1e8:
#   ./scripts/exact-hunt.sh [--cells N] [--seed S] [--keep DIR]
# Exit 0: every cell within 1e-6 mm of its bracket; 1: the failing cases' job and path
# files are in DIR (default exact-hunt-failures/), each a reproducer for `scallop simulate`.
set -eu
cd "$(dirname "$0")/.."
./scripts/build.sh scallop_exact_hunt >/dev/null
exec ./build/tests/scallop_exact_hunt "$@"
