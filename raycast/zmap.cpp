#include "raycast/zmap.h"

#include <algorithm>
#include <cmath>

namespace scallop {

GridSpec gridCovering(double minX, double minY, double maxX, double maxY, double spacing) {
  GridSpec g;
  g.originX = minX;
  g.originY = minY;
  g.spacing = spacing;
  // The 1e-9 guard keeps an extent that is an exact multiple of the spacing from
  // gaining a row to round-off (20 / 0.002 is 10000.000000000002 in double).
  g.nx = std::max<int64_t>(1, int64_t(std::ceil((maxX - minX) / spacing - 1e-9)));
  g.ny = std::max<int64_t>(1, int64_t(std::ceil((maxY - minY) / spacing - 1e-9)));
  return g;
}

ZMap::ZMap(const GridSpec& grid, double initialHeight)
    : grid_(grid), heights_(size_t(grid.cells()), initialHeight) {}

double ZMap::minHeight() const {
  return heights_.empty() ? 0.0 : *std::min_element(heights_.begin(), heights_.end());
}

double ZMap::maxHeight() const {
  return heights_.empty() ? 0.0 : *std::max_element(heights_.begin(), heights_.end());
}

}  // namespace scallop
