// Reading back the 16-bit grey height images scallop writes (`export --to F.png|F.tif`,
// tools/io/height_export.h): the grey level v of each pixel is z_mm = z_offset_mm +
// z_scale_mm * v, and the grid is "NX x NY cells of S mm, first cell centre at (X, Y) mm;
// row 0 is the largest y", all in ImageDescription; "value 0: no material" makes 0 NaN.
#pragma once

#include <string>

#include "raycast/zmap.h"

namespace scallop {

// Throws InputError(path, ...) for an unreadable image, one not 16-bit single-channel,
// or one without scallop's description (another program's picture has no heights).
ZMap readHeights16(const std::string& path);

}  // namespace scallop
