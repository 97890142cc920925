#include "tools/run/map_export.h"

#include "analysis/surface_metrology.h"
#include "base/input_error.h"
#include "tools/io/height_export.h"
#include "tools/io/height_formats.h"
#include "tools/run/profile_roughness.h"

namespace scallop {

namespace {

// The cells of `region` as a map of their own (the same cell centres).
ZMap cropped(const ZMap& map, const CellRegion& region) {
  GridSpec g = map.grid();
  g.offsetI += region.i0;
  g.offsetJ += region.j0;
  g.nx = region.i1 - region.i0;
  g.ny = region.j1 - region.j0;
  ZMap out(g, 0.0);
  for (int64_t j = 0; j < g.ny; ++j)
    for (int64_t i = 0; i < g.nx; ++i) out.at(i, j) = map.at(region.i0 + i, region.j0 + j);
  return out;
}

}  // namespace

void exportHeightMap(const ZMap& map, const std::string& path, const std::string& title,
                     const std::string& frame) {
  heightFormatOf(path, false).write(map, path, title, frame);
}

void exportProfileCsv(const ZMap& map, const std::vector<double>& line, double stepMm,
                      double cutoffMm, const std::string& path, const char* lineField,
                      const char* cutoffField) {
  const Profile p = lineProfile(map, line, stepMm, lineField);
  // The roughness column is filled when the profile is long enough for the cutoff.
  const double needMm = 3 * cutoffMm;
  const double lengthMm = double(p.height.size() - 1) * p.stepMm;
  if (lengthMm >= needMm) {
    const RoughnessStats r = roughness(p, cutoffMm, cutoffField);
    writeProfileCsv(p, &r, path);
  } else {
    writeProfileCsv(p, nullptr, path);
  }
}

HillshadeExport exportHillshade(const ZMap& map, const std::vector<double>& rectangle,
                                const HillshadeOptions& options, const std::string& path,
                                const char* regionField) {
  if (!rectangle.empty() && rectangle.size() != 4)
    throw InputError(regionField, "expected 4 numbers: x0 y0 x1 y1 (mm)");
  const CellRegion region = rectangle.empty()
                                ? wholeMap(map.grid())
                                : regionOfRectangle(map.grid(), rectangle[0], rectangle[1],
                                                    rectangle[2], rectangle[3], regionField);
  HillshadeExport out;
  out.exaggeration =
      writeHillshadePng(rectangle.empty() ? map : cropped(map, region), path, options, "--");
  out.cellsX = region.i1 - region.i0;
  out.cellsY = region.j1 - region.j0;
  return out;
}

}  // namespace scallop
