// A synthetic height field for the metrology tests: z(x, y) sampled at the cell
// centres of an nx x ny grid with the given origin and spacing (mm).
#pragma once

#include <cstdint>
#include <functional>

#include "raycast/zmap.h"

namespace scallop {

inline ZMap sampledField(double originX, double originY, int64_t nx, int64_t ny, double spacing,
                         const std::function<double(double, double)>& z) {
  GridSpec g;
  g.originX = originX;
  g.originY = originY;
  g.spacing = spacing;
  g.nx = nx;
  g.ny = ny;
  ZMap map(g, 0.0);
  for (int64_t j = 0; j < ny; ++j)
    for (int64_t i = 0; i < nx; ++i) map.at(i, j) = z(g.cellCentreX(i), g.cellCentreY(j));
  return map;
}

}  // namespace scallop
