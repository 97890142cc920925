// Cusp heights of simulated rasters against the closed forms of the seeds.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/scallop_profile.h"
#include "base/constants.h"
#include "raycast/simulation.h"
#include "sweep/brute_force_reference.h"
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
  const Box3 stock({0, 0, -5}, {4 * spacing, 2 * stepOver, 0});
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
      const double R = 3, s = R * std::sin(degToRad(rhoDeg));
      const double halfL = R * std::sqrt(1 - std::pow((s - h) / s, 2));
      const double cusp = simulatedCusp(Cutter::make(CutterType::Flat, R), 2 * halfL, rhoDeg, 0.01);
      EXPECT_NEAR(cusp, h, 1e-4) << "rho=" << rhoDeg << " h=" << h;
    }
  }
}

// Bull cutters with lead (and tilt): no closed form, so the reference is the
// brute-force union of the same moves (tests/sweep/brute_force_reference.h), which
// shares no code with the simulation.
TEST(Cusp, BullWithLeadMatchesBruteForce) {
  struct Case {
    double R, r, leadDeg, tiltDeg, stepOver;
  };
  for (const Case& k : {Case{3, 1, 5, 0, 2.884}, Case{3, 1, 10, 0, 2.166}, Case{6, 2, 5, 0, 4.23},
                        Case{3, 1, 5, 7, 2.0}}) {
    const Cutter bull = Cutter::make(CutterType::Bull, k.R, k.r);
    const double spacing = k.stepOver / 201;  // the midpoint between passes is a cell centre
    const Box3 stock({0, 0, -5}, {4 * spacing, 2 * k.stepOver, 0});
    RasterSpec spec;
    spec.stepOver = k.stepOver;
    spec.depth = 1.0;
    spec.leadDeg = k.leadDeg;
    spec.tiltDeg = k.tiltDeg;
    const ToolPath path = makeRaster(bull, stock, spec);
    const GridSpec grid = gridCovering(0, 0, stock.max.x, stock.max.y, spacing);
    const SimulationResult sim = simulate(bull, path, stock, grid);

    const ref::RefCutter rc = ref::makeRefCutter(CutterType::Bull, k.R, k.r);
    std::vector<ref::RefMove> moves;
    for (const Move& m : path.moves)
      if (!m.rapid) moves.push_back({m.from.tip, m.to.tip, m.from.axis});

    // Every cell of one column, between the first two passes, against the reference.
    const int64_t i = 2;
    const double x = grid.cellCentreX(i);
    double worst = 0;
    for (int64_t j = 0; j < grid.ny; ++j) {
      const double y = grid.cellCentreY(j);
      if (y > k.stepOver) break;
      const ref::RefHit want = ref::unionLowest(rc, moves, x, y);
      ASSERT_TRUE(want.hit);
      worst = std::max(worst, std::fabs(sim.map.at(i, j) - std::min(want.z, stock.max.z)));
    }
    EXPECT_LT(worst, 1e-6) << "R=" << k.R << " lead=" << k.leadDeg << " tilt=" << k.tiltDeg;

    // The cusp itself: the highest point between the passes above the lowest one.
    const double refCusp = ref::cuspHeight(rc, moves, x, 0, x, k.stepOver);
    const ScallopProfile profile = columnProfile(sim.map, i);
    double lowest = HUGE_VAL;
    for (size_t n = 0; n < profile.position.size(); ++n)
      if (profile.position[n] <= k.stepOver) lowest = std::min(lowest, profile.height[n]);
    const double cusp = cuspHeight(profile, 0, k.stepOver, lowest);
    const double tol = k.tiltDeg == 0 ? 1e-4 : 1e-3;  // tilted: the cusp falls between cells
    EXPECT_NEAR(cusp, refCusp, tol)
        << "R=" << k.R << " lead=" << k.leadDeg << " tilt=" << k.tiltDeg;
  }
}

}  // namespace
}  // namespace scallop
