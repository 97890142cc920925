// Height-map file exchange beyond simulate's own outputs (height_images.h):
//  - readHeightFile: reads a height map by its extension through the table of
//    height_formats.h (.gsf, .exr, .x3p; anything else is refused with exit 1, naming
//    the expected formats);
//  - 16-bit PNG and TIFF: grey levels v = 0..65535 with z_mm = offset + scale * v,
//    offset = the map's minimum and scale = range / 65535 (a quantisation of at most
//    scale / 2). Both are spelled out in ImageDescription (a PNG tEXt chunk, the TIFF
//    tag) and, in PNG, also as text chunks "scallop:z_offset_mm", "scallop:z_scale_mm",
//    with the grid ("scallop:origin_x", "scallop:origin_y", "scallop:spacing_mm"). North up.
//  - CSV profile: one line per sample, "distance_mm,x_mm,y_mm,z_mm,roughness_mm"
//    (roughness empty outside the Gaussian filter's valid part).
#pragma once

#include <string>

#include "analysis/profile_metrology.h"
#include "raycast/zmap.h"

namespace scallop {

// `frame`, when given, receives the frame the heights are in (height_images.h).
ZMap readHeightFile(const std::string& path, std::string* frame = nullptr);

// Format from the extension: ".png" or ".tif"/".tiff". A map in a frame
// (GridFrame::describe()) says so in ImageDescription and, in PNG, the text chunk
// "scallop:frame".
void writeHeights16(const ZMap& map, const std::string& path, const std::string& frame = "");

void writeProfileCsv(const Profile& profile, const RoughnessStats* roughness,
                     const std::string& path);

}  // namespace scallop
