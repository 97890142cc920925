#!/bin/sh
# Builds the two pictures of docs/images/README.md: a 1 x 1 mm window of a small raster
# (three passes along x, 0.5 mm apart) of a ball cutter R = 3 mm, lead 15 degrees,
# 2 flutes, fz = 0.1 mm, on 2 um cells, simulated with the cutting-edge model
# ("cutting": {"model": "teeth"}) and with the envelope model (the swept solid of
# revolution), both hill-shaded with the same light and the same vertical
# exaggeration:
#     docs/images/teeth-window.png      the feed marks (0.42 um deep, 0.1 mm apart)
#     docs/images/envelope-window.png   the same window without them
#     docs/images/face-mill-inserts.png examples/face_mill_inserts.json: a face mill's
#                                       round inserts, one 9 um lower (docs/teeth.md)
# The two job files are written below (teeth-window.json, envelope-window.json) and
# kept with the outputs when OUT=DIR is given; otherwise in a temporary folder.
# Usage: scripts/teeth-pictures.sh  (SCALLOP=path/to/scallop to use another binary;
# the default is ./build/scallop). About 12 s on 2 cores; each picture is ~20 KB.
set -eu
cd "$(dirname "$0")/.."
scallop=${SCALLOP:-./build/scallop}
if [ -n "${OUT:-}" ]; then
  out=$OUT
  mkdir -p "$out"
else
  out=$(mktemp -d)
  trap 'rm -rf "$out"' EXIT
fi

# The light and the exaggeration both pictures share: the map makers' north-west
# light, 45 degrees up, and heights x 10, a round number beside what
# `export --hillshade` picks by itself for either window (x 11: a typical slope of the
# scallops shows at 35 degrees); more puts the far side of each scallop in shadow.
shade() { # heights, picture, title
  "$scallop" export "$1" --to "$2" --hillshade --azimuth 315 --elevation 45 \
    --exaggeration 10 --title "$3"
}

job() { # name, extra top-level keys
  cat >"$out/$1.json" <<EOF
{
  "tool":  {"type": "ball", "radius": 3.0, "flutes": 2},$2
  "stock": {"min": [0, -0.5, -1], "max": [1, 0.5, 0]},
  "grid":  {"spacing": 0.002},
  "path":  {"raster": {"direction": "x", "step_over": 0.5, "depth": 0.1, "lead_deg": 15}}
}
EOF
}
job teeth-window '
  "cutting": {"model": "teeth", "feed_per_tooth": 0.1, "phase_deg": 0},'
job envelope-window '
  "cutting": {"model": "envelope"},'

mkdir -p docs/images
for name in teeth-window envelope-window; do
  "$scallop" simulate "$out/$name.json" -o "$out/$name" >/dev/null
done
shade "$out/teeth-window/heights.gsf" docs/images/teeth-window.png \
  "teeth: ball R3, lead 15°, 2 flutes, fz 0.1 mm, 2 µm cells"
shade "$out/envelope-window/heights.gsf" docs/images/envelope-window.png \
  "envelope: the same passes, swept solid of revolution"
# The face mill with two round inserts, one 9 um lower (examples/face_mill_inserts.json).
"$scallop" simulate examples/face_mill_inserts.json -o "$out/face-mill-inserts" >/dev/null
shade "$out/face-mill-inserts/heights.gsf" docs/images/face-mill-inserts.png \
  "face mill R10, 2 round inserts ri 5 (one 9 µm lower), fz 0.4 mm, 4 µm cells"
ls -l docs/images/teeth-window.png docs/images/envelope-window.png \
  docs/images/face-mill-inserts.png
