#!/bin/sh
# Draws the README's gallery: every examples/*.json simulated by ./build/scallop and
# rendered in 3-D (`scallop render`, 800 x 500) into docs/images/examples/NAME.png. The
# G-code and post-processor twins of ball_raster give its heights bit for bit and are
# left out.
set -eu
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
mkdir -p docs/images/examples
for job in examples/*.json; do
  name=$(basename "$job" .json)
  case $name in ball_raster_gcode | ball_raster_post) continue ;; esac
  ./build/scallop simulate "$job" -o "$out/$name" --json >/dev/null
  ./build/scallop render "$out/$name/heights.gsf" -o "docs/images/examples/$name.png" \
    --size 800 500 --title "$name" >/dev/null
  echo "docs/images/examples/$name.png"
done
