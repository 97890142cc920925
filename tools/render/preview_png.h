// preview.png: the picture of a height map for people, written by `simulate` beside
// its height images (tools/io/height_images.h). 8-bit RGB: viridis colour map times
// hill shading (tools/render/relief_shading.h; light from the north-west, heights
// exaggerated so that scallops show, and the fine texture more so that feed marks
// show beside them, the factors in the legend), a colour bar with height ticks and a
// scale bar; cells that no move reached in grey lit by the relief, "not cut" in the
// legend, and cells without material (NaN) white, "no material" (tools/render/
// map_cells.h). North up, like the height images. Not meant to be read back.
// `scallop export --hillshade --colour` draws a map read from a file with it, so the
// two pictures of the same heights agree (the same shading, colours and exaggeration).
#pragma once

#include <cmath>
#include <string>

#include "raycast/zmap.h"
#include "tools/render/relief_shading.h"

namespace scallop {

struct PreviewOptions {
  // Longest side of the map part of the picture, px. Larger maps are reduced by an
  // integer factor taking the *minimum* height of each block: on a machined surface
  // the deepest point of a cell is what a cutter left, and it keeps cusps visible.
  int maxPixels = 1600;
  // Small maps are enlarged by an integer factor until the longest side reaches
  // this, px, so that the legend text is not larger than the map.
  int minPixels = 400;
  // Drawn above the map.
  std::string title;
  // The height the map started at, mm (a simulation's stock top): cells still at it
  // were reached by no move and are drawn grey, "not cut" in the legend, outside the
  // colour range. NaN: none is told apart (a map read from a file).
  double uncutHeight = NAN;
  // The heights the map started at, cell by cell, on the map's own grid (a stock of any
  // shape: tools/io/job.h fillStockHeights); cells not below them are not cut, as
  // above. Null: uncutHeight alone.
  const ZMap* stockHeights = nullptr;
  // Colour-bar range, mm; NaN: robust percentiles of the cut region of the (reduced)
  // map without the flanks that fall from its edge, see robustRange in
  // tools/render/height_colours.h. The range comes from the picture's own cells, so a map
  // reduced before (a tiled run's min-pooled copy) gets the in-memory picture's range.
  double zMin = NAN, zMax = NAN;
  Light light;
  // Vertical exaggeration of the shading; NaN: automaticExaggeration of the (reduced)
  // map's slopes.
  double exaggeration = NAN;
  // Extra exaggeration of the texture finer than 25 raster cells (feed marks beside
  // scallops); NaN: automaticTextureBoost; 1: none, one exaggeration for everything.
  double textureBoost = NAN;
};

// Writes atomically; returns the vertical exaggeration of the shading.
double writePreviewPng(const ZMap& map, const std::string& path,
                       const PreviewOptions& options = PreviewOptions());

}  // namespace scallop
