// The z-map caster: region queries, memos and threads change the speed, never a bit.
#include "raycast/zmap_caster.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

#include "raycast/simulation.h"
#include "sweep/contact_knots.h"
#include "sweep/raster.h"
#include "sweep/tool_path_sweep.h"
#include "tests/support/band_check.h"

namespace scallop {
namespace {

// A raster with lead and tilt, and a curved 5-axis path of short moves whose axis turns.
struct Fixture {
  Cutter cutter = Cutter::make(CutterType::Bull, 3, 1);
  Box3 stock{{0, 0, -3}, {4, 3, 0}};
  ToolPath path;
};

// The fixtures' surface z = -0.5 + 0.2 sin x cos y, and the tool axis CAM holds over it:
// the surface normal leaned 0.08 along +x.
Vec3 surfaceTip(double x, double y) {
  return {x, y, -0.5 + 0.2 * std::sin(x) * std::cos(y)};
}
Vec3 surfaceAxis(double x, double y) {
  const Vec3 normal =
      normalize(Vec3{-0.2 * std::cos(x) * std::cos(y), 0.2 * std::sin(x) * std::sin(y), 1});
  return normalize(normal + Vec3{0.08, 0, 0});
}

Fixture rasterFixture() {
  Fixture f;
  RasterSpec spec;
  spec.stepOver = 1.1;
  spec.depth = 0.4;
  spec.leadDeg = 7;
  spec.tiltDeg = 3;
  spec.zigzag = true;
  f.path = makeRaster(f.cutter, f.stock, spec);
  return f;
}

Fixture freeformFixture() {
  Fixture f;
  // Each move holds the (leaned) surface normal of its midpoint as its axis, as a 5-axis
  // post-processor's linear moves do; the axis jumps between moves.
  for (double y = -0.5; y <= 3.5; y += 0.9) {
    for (int k = 0; k < 60; ++k) {
      const double xa = -3.5 + 0.18 * k, xb = xa + 0.18;
      const Vec3 axis = surfaceAxis(0.5 * (xa + xb), y);
      f.path.moves.push_back(Move{{surfaceTip(xa, y), axis}, {surfaceTip(xb, y), axis}, false});
    }
  }
  return f;
}

// The same surface as CAM writes it for a 5-axis machine: a tool axis at every CL point,
// so the axis turns inside every move (one turning primitive per move).
Fixture turningFixture() {
  Fixture f;
  auto pose = [](double x, double y) { return Pose{surfaceTip(x, y), surfaceAxis(x, y)}; };
  for (double y = -0.5; y <= 3.5; y += 0.9)
    for (int k = 0; k < 60; ++k)
      f.path.moves.push_back(Move{pose(-3.5 + 0.18 * k, y), pose(-3.5 + 0.18 * (k + 1), y), false});
  return f;
}

ZMap cast(const Fixture& f, double spacing, int64_t regionCells, int threads,
          int64_t tileCells = 0) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
  const GridSpec grid =
      gridCovering(f.stock.min.x, f.stock.min.y, f.stock.max.x, f.stock.max.y, spacing);
  SimulationOptions options;
  options.cast.regionCells = regionCells;
  options.cast.tileCells = tileCells;
  return simulate(f.cutter, f.path, f.stock, grid, options).map;
}

TEST(ZMapCaster, RegionQueriesEqualCellByCellBitForBit) {
  for (const Fixture& f : {rasterFixture(), freeformFixture(), turningFixture()}) {
    const ZMap cellByCell = cast(f, 0.013, 1, 2);
    for (int64_t region : {4, 16, 33}) {
      const ZMap regions = cast(f, 0.013, region, 2);
      ASSERT_EQ(regions.heights().size(), cellByCell.heights().size());
      EXPECT_EQ(regions.heights(), cellByCell.heights()) << "region " << region;
    }
    // Something was really cut, or the comparison would prove nothing.
    EXPECT_LT(cellByCell.minHeight(), f.stock.max.z - 0.1);
  }
}

TEST(ZMapCaster, ThreadCountDoesNotChangeABit) {
  for (const Fixture& f : {freeformFixture(), turningFixture()})
    EXPECT_EQ(cast(f, 0.011, 16, 1).heights(), cast(f, 0.011, 16, 2).heights());
}

// The work items' size (128 cells on large grids, 64 on small ones) decides only where
// regions start and which winner they carry.
TEST(ZMapCaster, TileSizeDoesNotChangeABit) {
  const Fixture f = turningFixture();
  const ZMap reference = cast(f, 0.009, 0, 2, 64);
  for (int64_t tile : {128, 37})
    EXPECT_EQ(cast(f, 0.009, 0, 2, tile).heights(), reference.heights()) << "tile " << tile;
}

// Bands of rows cast from one scene (a map too large to hold, --tiled) are the whole
// map's rows, bit for bit.
TEST(ZMapCaster, BandsEqualTheWholeMapBitForBit) {
  const Fixture f = turningFixture();
  const GridSpec grid =
      gridCovering(f.stock.min.x, f.stock.min.y, f.stock.max.x, f.stock.max.y, 0.017);
  const std::unique_ptr<SweptScene> scene = buildScene(f.cutter, f.path, f.stock, grid.spacing);
  ZMap whole(grid, f.stock.max.z);
  castZMap(*scene, whole);
  expectBandsEqualWhole(*scene, whole, 37, f.stock.max.z);
}

TEST(ZMapCaster, EveryCellIsTheMinimumOverAllSegments) {
  // Against the definition with no culling at all: each cell's height is the minimum of
  // the stock top and every swept segment's exact lowest point.
  for (const Fixture& f : {freeformFixture(), turningFixture()}) {
    const ZMap map = cast(f, 0.05, 16, 2);
    std::vector<SweptMove> segs = sweepToolPath(f.cutter, f.path);
    const GridSpec& g = map.grid();
    // The scene gives turning moves the knot spacing of its grid (contact_knots.h): a
    // height is a function of the move, its spacing and the line.
    for (SweptMove& s : segs) s.setContactKnotSpacing(contactKnotSpacingFor(g.spacing));
    for (int64_t j = 0; j < g.ny; j += 3) {
      for (int64_t i = 0; i < g.nx; i += 3) {
        double want = f.stock.max.z;
        for (const SweptMove& s : segs) {
          const LowestPoint lp = s.lowestPoint(g.cellCentreX(i), g.cellCentreY(j));
          if (lp.hit) want = std::min(want, lp.z);
        }
        ASSERT_EQ(map.at(i, j), want) << i << " " << j;
      }
    }
  }
}

}  // namespace
}  // namespace scallop
