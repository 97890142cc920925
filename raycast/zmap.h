// ZMap: a regular grid of absolute heights (mm) over the stock, one per cell.
//
// Cell (i, j), 0 <= i < nx, 0 <= j < ny, is the square of side `spacing` whose centre
// is (origin.x + (i + 1/2) s, origin.y + (j + 1/2) s) (CONVENTIONS.md). Heights are
// stored in double, row-major with j = 0 at the *smallest* y; image writers flip rows
// so that image row 0 is the largest y.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace scallop {

struct GridSpec {
  double originX = 0, originY = 0;  // the grid's minimum corner (stock.min x, y), mm
  double spacing = 0;               // cell side, mm
  int64_t nx = 0, ny = 0;
  // Index of this grid's cell (0, 0) in a larger grid with the same origin: a band of
  // a map too large to hold. Centres are computed from the full grid's indices, so a
  // band's cells are bit for bit the full grid's (shifting the origin would round).
  int64_t offsetI = 0, offsetJ = 0;

  int64_t cells() const { return nx * ny; }
  double cellCentreX(int64_t i) const { return originX + (double(offsetI + i) + 0.5) * spacing; }
  double cellCentreY(int64_t j) const { return originY + (double(offsetJ + j) + 0.5) * spacing; }
  // Rows [j0, j1) of this grid, full width.
  GridSpec rows(int64_t j0, int64_t j1) const {
    GridSpec g = *this;
    g.offsetJ += j0;
    g.ny = j1 - j0;
    return g;
  }
};

// Grid over [minX, maxX] x [minY, maxY] with cells of side `spacing`:
// nx = ceil((maxX - minX) / spacing - 1e-9) (at least 1), likewise ny.
GridSpec gridCovering(double minX, double minY, double maxX, double maxY, double spacing);

class ZMap {
 public:
  ZMap() = default;
  ZMap(const GridSpec& grid, double initialHeight);

  const GridSpec& grid() const { return grid_; }
  int64_t nx() const { return grid_.nx; }
  int64_t ny() const { return grid_.ny; }

  double at(int64_t i, int64_t j) const { return heights_[size_t(j * grid_.nx + i)]; }
  double& at(int64_t i, int64_t j) { return heights_[size_t(j * grid_.nx + i)]; }
  const std::vector<double>& heights() const { return heights_; }
  std::vector<double>& heights() { return heights_; }

  double minHeight() const;
  double maxHeight() const;

 private:
  GridSpec grid_;
  std::vector<double> heights_;
};

}  // namespace scallop
