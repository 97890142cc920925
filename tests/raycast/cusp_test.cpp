// Cusp heights of simulated rasters against the closed forms of the seeds.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/scallop_profile.h"
#include "raycast/simulation.h"
#include "sweep/raster.h"

namespace scallop {
namespace {

// Simulates passes along x, `passes` of them `stepOver` apart, on a grid whose cell
// centres fall exactly on the cusp lines y = (k + 1/2) stepOver, so the cusp is
// sampled, not interpolated. Returns the highest cusp above the floor between the
// first two passes, mm.
double simulatedCusp(const Cutter& cutter, double stepOver, double leadDeg, double targetSpacing) {
  const int half = std::max(1, int(std::lround(stepOver / (2 * targetSpacing) - 0.5)));
  const double spacing = stepOver / (2 * half + 1);  // L/2 = (half + 1/2) spacing
  Box3 stock;
  stock.extend({0, 0, -5});
  stock.extend({4 * spacing, 2 * stepOver, 0});
  RasterSpec spec;
  spec.stepOver = stepOver;
  spec.depth = 1.0;
  spec.leadDeg = leadDeg;
  const ToolPath path = makeRaster(cutter, stock, spec);
  const GridSpec grid = gridCovering(stock.min.x, stock.min.y, stock.max.x, stock.max.y, spacing);
  const SimulationResult sim = simulate(cutter, path, stock, grid);
  const ScallopProfile profile = columnProfile(sim.map, 1);
  // Between pass 0 (y = 0) and pass 1 (y = stepOver).
  return cuspHeight(profile, 0, stepOver, stock.max.z - spec.depth);
}

TEST(Cusp, BallRasterMatchesSeed001Eq1) {
  for (double R : {3.0, 5.0}) {
    for (double h : {0.01, 0.05, 0.1}) {
      const double halfL = std::sqrt(2 * R * h - h * h);  // seed 001 Eq. (1)
      const double cusp = simulatedCusp(Cutter::make(CutterType::Ball, R), 2 * halfL, 0, 0.01);
      EXPECT_NEAR(cusp, h, 1e-4) << "R=" << R << " h=" << h;
      EXPECT_NEAR(cusp, h, 1e-9) << "exact evaluation, cusp sampled on a cell centre";
    }
  }
}

TEST(Cusp, InclinedFlatEndMillMatchesEllipse) {
  // Seed 000 Eq. (11) with Rcr = 0: a flat disk of radius R tilted by rho along the feed
  // leaves the cusp h at L/2 = R sqrt(1 - ((R sin rho - h) / (R sin rho))^2).
  for (double rhoDeg : {5.0, 10.0, 20.0}) {
    for (double h : {0.02, 0.05}) {
      const double R = 3, s = R * std::sin(rhoDeg * M_PI / 180);
      const double halfL = R * std::sqrt(1 - std::pow((s - h) / s, 2));
      const double cusp = simulatedCusp(Cutter::make(CutterType::Flat, R), 2 * halfL, rhoDeg, 0.01);
      EXPECT_NEAR(cusp, h, 1e-4) << "rho=" << rhoDeg << " h=" << h;
    }
  }
}

}  // namespace
}  // namespace scallop
