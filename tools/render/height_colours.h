// The height colours of preview.png (tools/render/preview_png.h) and of the hill-shade
// picture's colour mode (tools/render/hillshade_png.h): viridis over a robust range of
// the cut region, darkened or brightened by the relief shading.
#pragma once

#include <cmath>
#include <utility>

#include "tools/render/png_canvas.h"
#include "tools/render/relief_shading.h"

namespace scallop {

// Viridis (perceptually uniform, readable in grey and by colour-blind viewers) at
// t in [0, 1]; t outside (or NaN) takes the end colours.
png::Rgb viridis(double t);

// The colour range, mm: robust percentiles of the cut region, the cells below
// `uncutHeight` (the stock top a simulated map starts at; NaN: the map's highest
// height), leaving out the flanks that fall from the map's edge or from uncut cells,
// the strip a cutter only grazed beside its outermost pass. See height_colours.cpp.
std::pair<double, double> robustRange(const HeightRaster& raster, double uncutHeight = NAN);

// `c` lit by a shading factor (1: as lit as a flat floor): darkened below 1; above 1
// (facets turned to the light) blended towards white instead, up to 60% at
// `maxFactor`, so that highlights also show on the dark end of the colour map.
png::Rgb shaded(png::Rgb c, double factor, double maxFactor);

}  // namespace scallop
