// Synthetic height fields for the metrology, rendering and file-format tests: z sampled
// over an nx x ny grid with the given origin and spacing (mm), either at the cell
// centres, z(x, y), or by the cells' indices, z(i, j).
#pragma once

#include <cstdint>
#include <functional>

#include "raycast/zmap.h"

namespace scallop {

inline GridSpec fieldGrid(double originX, double originY, int64_t nx, int64_t ny, double spacing) {
  GridSpec g;
  g.originX = originX;
  g.originY = originY;
  g.spacing = spacing;
  g.nx = nx;
  g.ny = ny;
  return g;
}

inline ZMap indexedField(double originX, double originY, int64_t nx, int64_t ny, double spacing,
                         const std::function<double(int64_t, int64_t)>& z) {
  ZMap map(fieldGrid(originX, originY, nx, ny, spacing), 0.0);
  for (int64_t j = 0; j < ny; ++j)
    for (int64_t i = 0; i < nx; ++i) map.at(i, j) = z(i, j);
  return map;
}

inline ZMap sampledField(double originX, double originY, int64_t nx, int64_t ny, double spacing,
                         const std::function<double(double, double)>& z) {
  const GridSpec g = fieldGrid(originX, originY, nx, ny, spacing);
  return indexedField(originX, originY, nx, ny, spacing,
                      [&](int64_t i, int64_t j) { return z(g.cellCentreX(i), g.cellCentreY(j)); });
}

}  // namespace scallop
