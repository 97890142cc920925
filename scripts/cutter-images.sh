#!/bin/sh
# Regenerates docs/images/cutters/*.svg, the pictures of docs/cutters.md: each example of
# the cutter-shape table (tools/io/job_cutter_shapes.cpp, `scallop cutter --pictures`)
# drawn by `scallop cutter --svg` (its profile mirrored about the axis, the chain's joins
# marked). Usage: scripts/cutter-images.sh [path/to/scallop]
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
scallop=${1:-"$here/build/scallop"}
out="$here/docs/images/cutters"
mkdir -p "$out"
tab=$(printf '\t')
"$scallop" cutter --pictures | while IFS="$tab" read -r file title tool; do
  "$scallop" cutter "$tool" --svg "$out/$file.svg" --title "$title" >/dev/null
done
