// `scallop render`: a height file of any kind scallop reads, drawn as a ray-traced 3-D
// picture (tools/render/render_png.h).
#pragma once

#include <string>
#include <vector>

#include "raycast/zmap.h"
#include "tools/render/render_png.h"

namespace scallop {

// A height map by what `path` is: a folder of `simulate --bands` files (band-K.json and
// band-K.raw, read and checked as `scallop merge` does, not merged on disk), or a file by
// its extension: .gsf, .exr (simulate's, or merge's), .x3p, or the 16-bit .png/.tif/.tiff
// of `scallop export`. Throws InputError naming the file.
ZMap readAnyHeightMap(const std::string& path);

struct RenderRequest {
  std::string heights, output;
  std::vector<double> region;  // empty, or x0 y0 x1 y1 mm
  RenderOptions options;
};

// Reads, checks the options and the region (InputError naming --size, --view, --light,
// --exaggeration, --region), renders and writes the PNG atomically.
RenderSummary runRender(const RenderRequest& request);

}  // namespace scallop
