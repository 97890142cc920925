#include "tools/render/map_cells.h"

#include <algorithm>
#include <cmath>

namespace scallop {

std::vector<CellKind> cellKinds(const HeightRaster& raster, double uncutHeight,
                                const HeightRaster* stock) {
  std::vector<CellKind> kinds(raster.z.size(), CellKind::Cut);
  const bool withStock = stock && stock->z.size() == raster.z.size();
  for (size_t c = 0; c < raster.z.size(); ++c) {
    const double z = raster.z[c];
    if (std::isnan(z))
      kinds[c] = CellKind::NoMaterial;
    else if (z >= uncutHeight || (withStock && z >= stock->z[c]))  // false for NaN
      kinds[c] = CellKind::NotCut;
  }
  return kinds;
}

std::vector<CellLegendLine> cellLegend(const std::vector<CellKind>& kinds) {
  std::vector<CellLegendLine> lines;
  if (std::find(kinds.begin(), kinds.end(), CellKind::NotCut) != kinds.end())
    lines.push_back({kNotCutColour, "not cut: the stock as it started, no move reached it"});
  if (std::find(kinds.begin(), kinds.end(), CellKind::NoMaterial) != kinds.end())
    lines.push_back({kNoMaterialColour, "no material: the cell's line misses the stock"});
  return lines;
}

}  // namespace scallop
