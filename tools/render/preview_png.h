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
  // Drawn above the map with the built-in font (letters are shown upper-case).
  std::string title;
  // Colour-bar range, mm; NaN: the map's own. A min-pooled reduction of a map too
  // large to hold passes the full map's range so its picture matches the in-memory one.
  double zMin = NAN, zMax = NAN;
};

void writePreviewPng(const ZMap& map, const std::string& path,
                     const PreviewOptions& options = PreviewOptions());

}  // namespace scallop
