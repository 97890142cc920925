// preview.png: the picture of a height map for people, written by `simulate` beside
// its height images (tools/io/height_images.h). 8-bit RGB: viridis colour map times
// hill-shading (light from the north-west), a colour bar with height ticks and a scale
// bar. North up, like the height images. Not meant to be read back.
#pragma once

#include <cmath>
#include <string>

#include "raycast/zmap.h"

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
  // Colour-bar range, mm; NaN: robust percentiles of the cut region of the (reduced)
  // map, see preview_png.cpp. The range comes from the picture's own cells, so a map
  // reduced before (a tiled run's min-pooled copy) gets the in-memory picture's range.
  double zMin = NAN, zMax = NAN;
};

void writePreviewPng(const ZMap& map, const std::string& path,
                     const PreviewOptions& options = PreviewOptions());

}  // namespace scallop
