// A cutter's profile as an SVG picture: the meridian chain (sweep/cutter_profile.h)
// mirrored about the axis into the tool's silhouette, lines as lines and arcs as true
// SVG arcs, the segment joins marked, the axis dashed and the largest radius and flute
// length written underneath. What `scallop cutter --svg` writes and the README's table
// of cutters shows (scripts/cutter-images.sh).
#pragma once

#include <string>

#include "sweep/cutter.h"

namespace scallop {

// `title` is printed above the picture (e.g. the type and its parameters).
std::string cutterProfileSvg(const Cutter& cutter, const std::string& title);

}  // namespace scallop
