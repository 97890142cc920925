// Hill shading of a height map (shared by preview.png, tools/render/preview_png.h, and
// the hill-shade picture, tools/render/hillshade_png.h): the surface's normals lit by
// a distant Lambertian light, with a vertical exaggeration so that micrometre relief
// on a millimetre field (scallops, feed marks) shows.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "raycast/zmap.h"

namespace scallop {

// Heights on a square raster, north up: z[r * w + a], column a = 0 at the smallest x,
// row r = 0 at the largest y.
struct HeightRaster {
  int w = 0, h = 0;
  double cellMm = 0;  // side of one raster cell, mm
  std::vector<double> z;

  double at(int a, int r) const { return z[size_t(r) * size_t(w) + size_t(a)]; }
};

// The map reduced by the smallest integer factor k that makes its longest side at most
// `maxPixels`, taking the *minimum* height of each k x k block: on a machined surface
// the deepest point of a cell is what a cutter left, and it keeps cusps visible.
HeightRaster reduceMap(const ZMap& map, int maxPixels);

// A distant light. Azimuth: where the light comes from, degrees clockwise from north
// (+y) towards east (+x), the map makers' convention (315: the north-west). Elevation:
// degrees above the horizon, in (0, 90].
struct Light {
  double azimuthDeg = 315;
  double elevationDeg = 45;
};

// dz/dx and dz/dy (mm per mm, y towards the north) of every cell: central differences
// over the real cell spacing, one-sided on the edges, 0 across a raster one cell wide.
struct Slopes {
  std::vector<double> dzdx, dzdy;
};
Slopes slopes(const HeightRaster& raster);

// The q-quantile (0 <= q < 1) of the slope magnitudes |(dz/dx, dz/dy)| above `floor`,
// 0 when there is none.
double slopeQuantile(const Slopes& s, double q, double floor);

// The vertical exaggeration that tilts a typical facet (the 75th percentile of the
// slopes steeper than 1 nm per mm) to 35 degrees, to two significant digits so that a
// legend states it exactly; 1 for a surface without such slopes. Scallops and feed
// marks are micrometres high over tenths of a millimetre: slopes of 1e-3 to 1e-1.
double automaticExaggeration(const Slopes& s);

// The slopes of the texture finer than a box of (2 radius + 1) cells: the heights
// minus their mean over that box (edges clamped), a "local relief model".
Slopes textureSlopes(const HeightRaster& raster, int radius);

// How much more than the rest to exaggerate the texture so that it shows: feed marks
// of 0.4 um beside scallops of tens of um tilt by a degree or two at the exaggeration
// that shows the scallops. The boost tilts the texture's typical facet (the 75th
// percentile of its slopes steeper than 1% of the surface's typical slope, so that the
// residue of smooth curvature does not count) to 10 degrees: the texture's factor,
// exaggeration times boost, has two significant digits, and the boost is at most 10;
// 1 (no boost) when that would be less than 2 (the texture already shows) or there is
// no texture.
double automaticTextureBoost(const Slopes& all, const Slopes& texture, double exaggeration);

// all + (boost - 1) texture: the slopes of the heights with their texture scaled by boost.
Slopes boosted(const Slopes& all, const Slopes& texture, double boost);

// What both pictures (preview.png, the grey hill-shade picture) start from: the map
// reduced to at most `maxPixels` a side, the factor `up` that enlarges it towards
// `minPixels`, its slopes and the exaggeration (`exaggeration`, or automatic when NaN).
// Throws InputError naming `path` for an empty map or a spacing that is not positive.
struct ReliefGrid {
  HeightRaster grid;
  int up = 1;
  Slopes slope;
  double exaggeration = 1;
};
ReliefGrid reliefGridOf(const ZMap& map, const std::string& path, int maxPixels, int minPixels,
                        double exaggeration);

// The Lambert term of every cell, max(0, n . l): n the unit normal of the surface with
// its heights multiplied by `exaggeration`, (-e dz/dx, -e dz/dy, 1) / |.|, and l the
// unit vector towards the light, (cos(el) sin(az), cos(el) cos(az), sin(el)).
std::vector<double> lambert(const Slopes& s, double exaggeration, const Light& light);

// The legend that says how a picture is shaded, one or two lines:
// "relief shading: heights × 10, light from 315° at 45°", and with a texture boost
// above 1 "texture finer than 125 µm: heights × 40" (exaggeration times boost;
// `textureMm` is the texture box's side).
std::vector<std::string> reliefLegend(double exaggeration, const Light& light, double boost = 1,
                                      double textureMm = 0);

}  // namespace scallop
