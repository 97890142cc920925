// The 3-D picture of a height map for people (`scallop render`, `simulate --view`):
// the surface ray-traced with Embree in oblique light with shadows (tools/render/
// surface_render.h), coloured by height, on walls down to a base; a box on the base
// with ticks in mm, a colour bar in µm (or mm), and a note of the vertical exaggeration,
// the light, the view and how the surface was sampled.
//
// The surface is the bilinear surface through the cell centres (tools/render/
// height_surface.h), traced from the level of block means whose nodes are about a pixel
// apart where the picture is finest (k x k cells a node, k = floor(pixel footprint /
// spacing), at least 1, smoothed by [1 2 1] / 4), at a fixed 2 x 2 grid of samples a
// pixel: marks finer than a
// pixel are averaged, not aliased into moiré, and a map of 4e8 cells is traced from a
// few million nodes.
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <string>

#include "analysis/surface_metrology.h"
#include "raycast/zmap.h"
#include "tools/render/colour_map.h"
#include "tools/render/png_canvas.h"
#include "tools/render/render_camera.h"

namespace scallop {

struct RenderOptions {
  int widthPx = 1600, heightPx = 1000;  // the whole picture, in [1, 16384]
  Direction view{210, 40};              // where the camera stands
  Direction light{315, 45};             // where the light comes from
  // Vertical exaggeration, in (0, 1e6]; NaN: the relief (the colour range) is made a
  // fifth of the region's longer side, to two significant digits.
  double exaggeration = NAN;
  Projection projection = Projection::kOrthographic;
  ColourMap colourMap = ColourMap::kViridis;
  std::string title;         // drawn above the picture
  double uncutHeight = NAN;  // heights at or above it are grey, "uncut" (a simulation's stock top)
  int samplesPerSide = 2;    // n x n samples a pixel
  // Called as rows of the picture are traced (rows done, rows in all), one call at a
  // time; it may throw to cancel (nothing is written then).
  std::function<void(int64_t, int64_t)> progress;
};

// The option names bad values are reported under.
struct RenderOptionNames {
  std::string size = "--size", view = "--view", light = "--light", exaggeration = "--exaggeration";
};

// Throws InputError naming the option: a size outside [1, 16384] px, an angle not
// finite, an elevation outside (0, 90] degrees, an exaggeration outside (0, 1e6].
void checkRenderOptions(const RenderOptions& options, const RenderOptionNames& names = {});

struct RenderSummary {
  double exaggeration = 1;
  bool automaticExaggeration = false;
  int blockCells = 1;  // k: the level's nodes are means of k x k cells
  int64_t nodesX = 0, nodesY = 0;
  size_t tiles = 0;            // Embree primitives
  double zLow = 0, zHigh = 0;  // colour range, mm
};

struct RenderedPicture {
  png::Canvas canvas{1, 1};
  RenderSummary summary;
};

// The picture of `region` of `map`. Throws InputError(regionName, ...) when the region
// is narrower than two nodes or holds no height.
RenderedPicture renderPicture(const ZMap& map, const CellRegion& region,
                              const RenderOptions& options, const char* regionName = "--region");

// Renders and writes the PNG atomically (no partial file on any error).
RenderSummary writeRenderPng(const ZMap& map, const CellRegion& region, const std::string& path,
                             const RenderOptions& options, const char* regionName = "--region");

}  // namespace scallop
