#include "raycast/stock_map.h"

#include <algorithm>
#include <cmath>

#include "raycast/grid_frame.h"

namespace scallop {

namespace {

// The bilinear height of `stock` at (x, y), NaN if a neighbour is void.
double interpolate(const ZMap& stock, double x, double y) {
  const GridSpec& s = stock.grid();
  const double fx = std::clamp((x - s.originX) / s.spacing - 0.5, 0.0, double(s.nx - 1));
  const double fy = std::clamp((y - s.originY) / s.spacing - 0.5, 0.0, double(s.ny - 1));
  const int64_t i0 = std::min<int64_t>(int64_t(fx), s.nx - 1), i1 = std::min(i0 + 1, s.nx - 1);
  const int64_t j0 = std::min<int64_t>(int64_t(fy), s.ny - 1), j1 = std::min(j0 + 1, s.ny - 1);
  const double tx = fx - double(i0), ty = fy - double(j0);
  const double low = stock.at(i0, j0) * (1 - tx) + stock.at(i1, j0) * tx;
  const double high = stock.at(i0, j1) * (1 - tx) + stock.at(i1, j1) * tx;
  return low * (1 - ty) + high * ty;
}

}  // namespace

void fillFromHeightMap(ZMap& map, const ZMap& stock) {
  const GridSpec& g = map.grid();
  const GridSpec& s = stock.grid();
  const bool coincide = g.spacing == s.spacing && g.originX == s.originX && g.originY == s.originY;
  for (int64_t j = 0; j < g.ny; ++j)
    for (int64_t i = 0; i < g.nx; ++i) {
      const int64_t si = g.offsetI + i, sj = g.offsetJ + j;
      const double h = coincide && si < s.nx && sj < s.ny
                           ? stock.at(si, sj)
                           : interpolate(stock, g.cellCentreX(i), g.cellCentreY(j));
      map.at(i, j) = std::isnan(h) ? kNoMaterial : h;
    }
}

}  // namespace scallop
