// The hill-shade picture of a height map, for people (`scallop export --hillshade`):
// the surface lit as a relief (tools/render/relief_shading.h), grey, 8-bit RGB, north
// up, with a scale bar and a legend stating the vertical exaggeration and the light.
// Grey level = round(255 * max(0, n . l)): a flat floor under the default light (45
// degrees up) is 180. With `colour` the picture is preview.png's instead, drawn by the
// same code with the same rule (viridis times the same shading, the texture boost when
// the exaggeration is automatic, a colour bar, cells without material white;
// tools/render/preview_png.h), so that it equals a simulation's preview of the heights
// but for the cells not cut, which a file does not tell.
#pragma once

#include <cmath>
#include <string>

#include "raycast/zmap.h"
#include "tools/render/relief_shading.h"

namespace scallop {

struct HillshadeOptions {
  Light light;
  // Vertical exaggeration; NaN: automaticExaggeration of the (reduced) map's slopes.
  double exaggeration = NAN;
  bool colour = false;
  std::string title;  // drawn above the map
  // As PreviewOptions: the longest side of the map part is reduced (block minimum) to
  // at most maxPixels, and small maps are enlarged until it reaches minPixels.
  int maxPixels = 1600, minPixels = 400;
};

// Validates the light and the exaggeration (InputError naming `field` + "azimuth",
// "elevation" or "exaggeration": finite; elevation in (0, 90] degrees; exaggeration
// in (0, 1e6]), then writes the picture atomically. Returns the exaggeration used.
double writeHillshadePng(const ZMap& map, const std::string& path,
                         const HillshadeOptions& options = HillshadeOptions(),
                         const std::string& field = "hillshade.");

}  // namespace scallop
