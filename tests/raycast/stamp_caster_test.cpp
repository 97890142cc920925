// The stamping baseline against the exact pipeline: never below it (stamps are subsets
// of the swept solid), within 1e-4 mm of it at the derived step, and independent of
// the number of threads.
#include "raycast/stamp_caster.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>

#include "base/constants.h"
#include "raycast/simulation.h"
#include "sweep/raster.h"
#include "tools/run/bench_cases.h"

namespace scallop {
namespace {

struct Difference {
  double max = -HUGE_VAL, min = HUGE_VAL;
};

Difference compare(const ZMap& stamped, const ZMap& exact) {
  Difference d;
  for (size_t k = 0; k < exact.heights().size(); ++k) {
    const double e = stamped.heights()[k] - exact.heights()[k];
    d.max = std::max(d.max, e);
    d.min = std::min(d.min, e);
  }
  return d;
}

void expectStampedWithinTolerance(const Cutter& cutter, const ToolPath& path, const Box3& stock,
                                  double spacing) {
  const GridSpec grid = gridCovering(stock.min.x, stock.min.y, stock.max.x, stock.max.y, spacing);
  const SimulationResult exact = simulate(cutter, path, stock, grid);
  const StampSimulationResult stamped = simulateStamped(cutter, path, stock, grid);
  const Difference d = compare(stamped.map, exact.map);
  EXPECT_GE(d.min, -1e-9) << "a stamp is part of the swept solid: never below the exact map";
  EXPECT_LE(d.max, 1e-4) << "step " << stamped.stamp.minStep << " mm";
  EXPECT_GT(stamped.stamp.positions, 0u);
  // The stock was cut at all (the comparison is not between two flat maps).
  EXPECT_LT(exact.map.minHeight(), stock.max.z - 0.1);
}

TEST(StampCaster, StepFollowsTheCurvatureOfTheLowerBoundary) {
  const Vec3 z{0, 0, 1};
  EXPECT_NEAR(stampStepFor(Cutter::make(CutterType::Ball, 3), z, 1e-4), 0.5 * std::sqrt(8e-4 * 3),
              1e-15);
  EXPECT_NEAR(stampStepFor(Cutter::make(CutterType::Bull, 3, 1), z, 1e-4), 0.5 * std::sqrt(8e-4),
              1e-15);
  // A tilted flat cutter's heel is a sharp edge: the error grows linearly with the step.
  const Vec3 tilted = leadTiltAxis({1, 0, 0}, 5, 0);
  EXPECT_NEAR(stampStepFor(Cutter::make(CutterType::Flat, 3), tilted, 1e-4),
              0.5 * 1e-4 / std::tan(degToRad(5)), 1e-12);
}

// Bull R3 r1 passes 0.8 mm apart and 0.5 mm deep over `stock`, the axis led 5 degrees.
const Cutter kBull = Cutter::make(CutterType::Bull, 3, 1);
ToolPath bullLeadRaster(const Box3& stock) {
  RasterSpec spec;
  spec.stepOver = 0.8;
  spec.depth = 0.5;
  spec.leadDeg = 5;
  return makeRaster(kBull, stock, spec);
}

TEST(StampCaster, BullRasterWithLeadWithinTolerance) {
  const Box3 stock({0, 0, -2}, {1.0, 1.7, 0});
  expectStampedWithinTolerance(kBull, bullLeadRaster(stock), stock, 0.02);
}

TEST(StampCaster, BallRasterCutIntoShortMovesWithinTolerance) {
  const Cutter cutter = Cutter::make(CutterType::Ball, 2);
  const Box3 stock({0, 0, -2}, {1.0, 1.0, 0});
  RasterSpec spec;
  spec.stepOver = 0.5;
  spec.depth = 0.3;
  spec.tiltDeg = 10;
  spec.segmentLength = 0.05;
  expectStampedWithinTolerance(cutter, makeRaster(cutter, stock, spec), stock, 0.02);
}

TEST(StampCaster, FreeformFiveAxisWithinTolerance) {
  const Cutter cutter = Cutter::make(CutterType::Bull, 3, 1);
  const Box3 stock({2, 3, -2}, {3, 4, 0.6});
  expectStampedWithinTolerance(cutter, makeFreeformPath(cutter, stock, 0.5, 0.05, 5), stock, 0.02);
}

TEST(StampCaster, ResultDoesNotDependOnThreads) {
  const Cutter& cutter = kBull;
  const Box3 stock({0, 0, -2}, {2, 2, 0});
  const ToolPath path = bullLeadRaster(stock);
  const GridSpec grid = gridCovering(0, 0, 2, 2, 0.05);
  StampOptions options;
  options.tileCells = 8;  // several tiles, so both threads take some
  StampSimulationResult one, two;
  tbb::task_arena(1).execute([&] { one = simulateStamped(cutter, path, stock, grid, options); });
  tbb::task_arena(2).execute([&] { two = simulateStamped(cutter, path, stock, grid, options); });
  EXPECT_EQ(heightsHash(one.map), heightsHash(two.map));
  EXPECT_EQ(one.stamp.exactEvaluations, two.stamp.exactEvaluations);
}

TEST(StampCaster, EmptyPathLeavesTheStock) {
  ZMap map(gridCovering(0, 0, 1, 1, 0.1), 0.25);
  const StampStats stats = stampZMap({}, map);
  EXPECT_EQ(stats.positions, 0u);
  EXPECT_EQ(map.minHeight(), 0.25);
  EXPECT_EQ(map.maxHeight(), 0.25);
}

}  // namespace
}  // namespace scallop
