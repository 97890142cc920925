#!/bin/sh
# Regenerates docs/images/cutters/*.svg, the README's table of cutters: one example of
# each type drawn by `scallop cutter --svg` (its profile mirrored about the axis, the
# chain's joins marked). Usage: scripts/cutter-images.sh [path/to/scallop]
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
scallop=${1:-"$here/build/scallop"}
out="$here/docs/images/cutters"
mkdir -p "$out"
draw() {  # name, title, cutter object
  "$scallop" cutter "$3" --svg "$out/$1.svg" --title "$2" >/dev/null
}
draw ball "ball R3" '{"type": "ball", "radius": 3, "flute_length": 12}'
draw flat "flat R3" '{"type": "flat", "radius": 3, "flute_length": 12}'
draw bull "bull R3 r1" '{"type": "bull", "radius": 3, "corner_radius": 1, "flute_length": 12}'
draw taper_ball "taper_ball r1 5°" \
  '{"type": "taper_ball", "tip_radius": 1, "taper_deg": 5, "flute_length": 12}'
draw taper_bull "taper_bull d4 r1 8°" \
  '{"type": "taper_bull", "tip_diameter": 4, "corner_radius": 1, "taper_deg": 8, "flute_length": 12}'
draw cone_vbit "cone 60° V-bit" '{"type": "cone", "angle_deg": 60, "diameter": 6, "flute_length": 12}'
draw cone_chamfer "cone 90° d1 chamfer" \
  '{"type": "cone", "angle_deg": 90, "tip_diameter": 1, "diameter": 6, "flute_length": 8}'
draw barrel "barrel d12 R40 r1" \
  '{"type": "barrel", "diameter": 12, "form_radius": 40, "tip_radius": 1, "flute_length": 12}'
draw taper_barrel "taper_barrel r2 R250 10°" \
  '{"type": "taper_barrel", "tip_radius": 2, "form_radius": 250, "taper_deg": 10, "reference_diameter": 8, "flute_length": 20}'
draw oval "oval d8 R12 r1.5" \
  '{"type": "oval", "diameter": 8, "form_radius": 12, "tip_radius": 1.5, "flute_length": 10}'
draw lens "lens d10 R12 r1" \
  '{"type": "lens", "diameter": 10, "form_radius": 12, "corner_radius": 1, "flute_length": 8}'
draw profile "profile" \
  '{"type": "profile", "segments": [{"to": [1, 0]}, {"to": [1.7071067811865475, 0.2928932188134524], "arc_radius": 1}, {"to": [2.5, 1.2]}, {"to": [3, 10]}]}'
draw apt "APT CUTTER/6,1,2,2.309,30,0,10" \
  '{"type": "apt", "d": 6, "r": 1, "e": 2, "f": 2.3094010767585, "a": 30, "b": 0, "h": 10}'
