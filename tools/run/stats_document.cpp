#include "tools/run/stats_document.h"

#include "base/input_error.h"
#include "tools/run/report.h"

namespace scallop {

using nlohmann::json;

Levelling parseLevelling(const std::string& level, const char* field) {
  if (level == "plane") return Levelling::kPlane;
  if (level == "none") return Levelling::kNone;
  throw InputError(field,
                   "expected \"plane\" (least-squares plane) or \"none\" (heights from "
                   "the mean), got \"" +
                       level + "\"");
}

CellRegion statsRegion(const GridSpec& grid, const std::vector<double>& rectangle,
                       const char* field) {
  if (rectangle.empty()) return wholeMap(grid);
  if (rectangle.size() != 4)
    throw InputError(
        field, "expected 4 numbers x0 y0 x1 y1 (mm), got " + std::to_string(rectangle.size()));
  return regionOfRectangle(grid, rectangle[0], rectangle[1], rectangle[2], rectangle[3], field);
}

json surfaceStatsDocument(const ZMap& map, const CellRegion& region, Levelling levelling,
                          SurfaceStats* stats) {
  const GridSpec& g = map.grid();
  const SurfaceStats s = surfaceStats(map, region, levelling);
  if (stats) *stats = s;
  return {{"grid",
           {{"origin", {g.originX, g.originY}},
            {"spacing", g.spacing},
            {"nx", g.nx},
            {"ny", g.ny},
            {"units", "mm"}}},
          {"region_cells", {{"i", {region.i0, region.i1}}, {"j", {region.j0, region.j1}}}},
          {"region_mm",
           {g.originX + double(region.i0) * g.spacing, g.originY + double(region.j0) * g.spacing,
            g.originX + double(region.i1) * g.spacing, g.originY + double(region.j1) * g.spacing}},
          {"surface_stats", surfaceStatsJson(s)}};
}

}  // namespace scallop
