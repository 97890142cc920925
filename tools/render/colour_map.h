// The colour maps a 3-D picture may colour heights with (`scallop render --colormap`):
// viridis, preview.png's (tools/render/height_colours.h), or grey.
#pragma once

#include <string>

#include "tools/render/png_canvas.h"

namespace scallop {

enum class ColourMap { kViridis, kGrey };

// "viridis" or "grey" ("gray"); throws InputError(where, ...) for another name.
ColourMap parseColourMap(const std::string& name, const std::string& where);
const char* colourMapName(ColourMap map);

// The colour at t in [0, 1] (t outside, or NaN, takes the end colours): grey runs from
// 40 (t = 0) to 235 (t = 1), so that shading still shows at both ends.
png::Rgb colourAt(ColourMap map, double t);

}  // namespace scallop
