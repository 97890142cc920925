// minimal.cpp: the scallop library walked through once, in order.
//
// A ball cutter cuts one straight groove through a block; scallop computes the exact
// height of the machined surface on a grid of cells and we read one height back. The
// groove's cross-section is a circle of the cutter's radius, so the height has a closed
// form: the program checks it and exits 1 if it disagrees (CMake runs it as a test).
//
// The data flows one way, as in `scallop simulate`:
//   cutter + tool path -> swept solids -> scene -> z-map (one height a cell).
// Lengths are in mm throughout.
#include <cmath>
#include <cstdio>

#include "base/constants.h"
#include "base/vec3.h"
#include "raycast/simulation.h"
#include "raycast/zmap.h"
#include "sweep/cutter.h"
#include "sweep/pose.h"

int main() {
  using namespace scallop;

  // 1. The cutter. Cutter::make checks its sizes (it throws InputError naming the field
  //    for a bad one) and fills in the defaults: a ball end mill of radius R = 3 mm with
  //    the default flute length, 4 R. Other shapes: sweep/cutter.h, sweep/cutter_shapes.h.
  const double radius = 3.0;
  const Cutter cutter = Cutter::make(CutterType::Ball, radius);

  // 2. The stock: a block 20 x 10 mm, 5 mm deep, its top at z = 0. Every cell of the
  //    map starts at the stock's top.
  const Box3 stock({0, 0, -5}, {20, 10, 0});

  // 3. The tool path: a list of moves, each from one pose to the next. A pose is the
  //    tip (the centre of the cutter's bottom, on its axis) and the unit tool axis,
  //    pointing from the tip to the shank. One move here, along x through the middle of
  //    the block with the tip 0.5 mm deep and the axis vertical. A move may also turn
  //    its axis (5-axis) or follow an arc (sweep/pose.h); makeRaster (sweep/raster.h)
  //    builds a whole raster with lead and tilt.
  const double depth = 0.5, grooveY = 5.0;
  const Vec3 up{0, 0, 1};
  ToolPath path;
  Move groove;
  groove.from = {Vec3{-5, grooveY, -depth}, up};
  groove.to = {Vec3{25, grooveY, -depth}, up};
  path.moves.push_back(groove);

  // 4. The grid: square cells of side 0.1 mm covering the stock's top. Cell (i, j) has
  //    its centre at (originX + (i + 1/2) s, originY + (j + 1/2) s).
  const GridSpec grid = gridCovering(stock.min.x, stock.min.y, stock.max.x, stock.max.y, 0.1);

  // 5. Simulate: sweep every move into its exact solid, build the culling scene, and
  //    lower each cell to the lowest point of the swept solids above its centre (in
  //    parallel; the heights do not depend on the thread count).
  const SimulationResult result = simulate(cutter, path, stock, grid);

  // 6. Read a height. The cell (100, 50) has its centre at x = 10.05, y = 5.05: 0.05 mm
  //    beside the groove's centre line, where the ball's circle is a little above the
  //    tip's lowest point.
  const int64_t i = 100, j = 50;
  const double dy = grid.cellCentreY(j) - grooveY;
  const double height = result.map.at(i, j);
  const double expected = -depth + radius - std::sqrt(radius * radius - dy * dy);
  std::printf("%lld x %lld cells, %.2f exact evaluations a cell\n", (long long)grid.nx,
              (long long)grid.ny, result.cast.evaluationsPerCell());
  std::printf("height at (%.3f, %.3f) mm: %.9f mm (closed form %.9f mm)\n", grid.cellCentreX(i),
              grid.cellCentreY(j), height, expected);

  // Every height is exact to kHeightToleranceMm (base/constants.h) against the true solid.
  return std::fabs(height - expected) <= kHeightToleranceMm ? 0 : 1;
}
