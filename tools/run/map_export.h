// `scallop export`'s work: a height map written in another format, a line profile as CSV,
// or a hill-shaded picture of a region. The command parses the options and checks their
// combination; these do the rest.
#pragma once

#include <string>
#include <vector>

#include "raycast/zmap.h"
#include "tools/render/hillshade_png.h"

namespace scallop {

// Writes `map` to `path` in the format of its extension: .x3p (ISO 25178-72), .png/.tif/
// .tiff (16-bit), .gsf (Gwyddion), .exr; `title` goes into the formats that carry one,
// and `frame` (GridFrame::describe(); empty: seen from above) into every one: GSF
// ScallopFrame, EXR and PNG scallop:frame, PNG/TIFF ImageDescription, X3P's Comment.
// InputError for another extension.
void exportHeightMap(const ZMap& map, const std::string& path, const std::string& title,
                     const std::string& frame = "");

// Writes the profile of `map` along `line` = {x0, y0, x1, y1} (mm), a sample every
// `stepMm` (0: the grid spacing), as CSV; its roughness column (cutoff `cutoffMm`) is
// filled when the profile is at least 3 cutoffs long. Fields as profileRoughness.
void exportProfileCsv(const ZMap& map, const std::vector<double>& line, double stepMm,
                      double cutoffMm, const std::string& path, const char* lineField,
                      const char* cutoffField);

// The hill shade of `map`, or of the cells in `rectangle` = {x0, y0, x1, y1} (mm) when
// it is not empty (InputError naming `regionField` if it holds no cell), as PNG.
struct HillshadeExport {
  int64_t cellsX = 0, cellsY = 0;  // of the region drawn
  double exaggeration = 0;         // the vertical exaggeration used
};
HillshadeExport exportHillshade(const ZMap& map, const std::vector<double>& rectangle,
                                const HillshadeOptions& options, const std::string& path,
                                const char* regionField);

}  // namespace scallop
