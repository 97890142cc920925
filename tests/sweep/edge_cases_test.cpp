// Numerical edge cases of the whole exact pipeline (sweep -> scene -> z-map, as
// `scallop simulate` runs it), each against a closed form evaluated here at every cell
// centre. The single-segment geometry of the same cases (zero-length moves, plunges,
// a horizontal axis) is checked against brute force in swept_segment_test.cpp and
// brute_force_reference_test.cpp; these tests add the grid, the culling tiles and
// the stock top around them.
//
// Stock thinner than the depth: the z-map holds the lowest point of the swept solid
// (README: the swept envelope's lowest point per cell), also below stock.min.z, where
// the cutter went through the part; the heights are not clamped, so a path that cuts
// through shows instead of being hidden.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "raycast/simulation.h"
#include "sweep/cutter.h"
#include "sweep/raster.h"

namespace scallop {
namespace {

constexpr double kTol = 1e-9;  // mm; the contract is 1e-6 (CONVENTIONS.md)

ToolPath path(std::initializer_list<std::pair<Pose, Pose>> moves) {
  ToolPath p;
  for (const auto& [from, to] : moves) p.moves.push_back(Move{from, to, false});
  return p;
}

// Lowest point of a vertical ball cutter (tip T, radius R) on the line through
// (x, y): the sphere's bottom, T.z + R - sqrt(R^2 - d^2) for d <= R; none beyond.
double ballBottom(const Vec3& tip, double R, double x, double y) {
  const double d2 = (x - tip.x) * (x - tip.x) + (y - tip.y) * (y - tip.y);
  return d2 <= R * R ? tip.z + R - std::sqrt(R * R - d2) : HUGE_VAL;
}

// Every cell of `map` equals min(stock top, expected(x, y)) to kTol.
void expectMap(const ZMap& map, double top, const std::function<double(double, double)>& expected,
               int* cellsCut = nullptr) {
  const GridSpec& g = map.grid();
  int cut = 0;
  for (int64_t j = 0; j < g.ny; ++j)
    for (int64_t i = 0; i < g.nx; ++i) {
      const double x = g.cellCentreX(i), y = g.cellCentreY(j);
      const double want = std::min(top, expected(x, y));
      cut += want < top;
      ASSERT_NEAR(map.at(i, j), want, kTol)
          << "cell (" << i << ", " << j << ") at " << x << ", " << y;
    }
  if (cellsCut) *cellsCut = cut;
}

const Vec3 kUp{0, 0, 1};

TEST(EdgeCases, ZeroLengthMoveLeavesTheCuttersOwnBottom) {
  const Cutter ball = Cutter::make(CutterType::Ball, 0.5);
  const Box3 stock({0, 0, -1}, {2, 2, 0});
  const Vec3 tip{1.03, 0.97, -0.3};
  const SimulationResult r =
      simulate(ball, path({{{tip, kUp}, {tip, kUp}}}), stock, gridCovering(0, 0, 2, 2, 0.02));
  int cut = 0;
  expectMap(
      r.map, 0, [&](double x, double y) { return ballBottom(tip, 0.5, x, y); }, &cut);
  EXPECT_GT(cut, 1000);  // a disk of radius sqrt(0.5^2 - 0.2^2) = 0.458 mm: ~1650 cells
}

TEST(EdgeCases, PurePlungeEqualsTheCutterStampedAtTheBottom) {
  const Cutter ball = Cutter::make(CutterType::Ball, 0.5);
  const Box3 stock({0, 0, -1}, {2, 2, 0});
  const Vec3 top{1, 1, 0.8}, bottom{1, 1, -0.35};
  for (const bool down : {true, false}) {
    SCOPED_TRACE(down ? "plunge down" : "retract up");
    const ToolPath p =
        down ? path({{{top, kUp}, {bottom, kUp}}}) : path({{{bottom, kUp}, {top, kUp}}});
    const SimulationResult r = simulate(ball, p, stock, gridCovering(0, 0, 2, 2, 0.025));
    expectMap(r.map, 0, [&](double x, double y) { return ballBottom(bottom, 0.5, x, y); });
  }
}

TEST(EdgeCases, ExactlyHorizontalAxisCutsWithTheCylindersLowestLine) {
  // Flat cutter R = 0.4, flute 2, axis exactly +x, tip at (0.5, y, -0.1) moved from
  // y = 1 to y = 2: the cylinder (x from 0.5 to 2.5) has its lowest line at
  // z = -0.1 - sqrt(R^2 - e^2), e = the distance of the cell's y from [1, 2].
  const double R = 0.4;
  const Cutter flat = Cutter::make(CutterType::Flat, R, 0, 2.0);
  const Vec3 axis{1, 0, 0};
  const Box3 stock({0, 0, -1}, {3, 3, 0});
  const SimulationResult r =
      simulate(flat, path({{{{0.5, 1, -0.1}, axis}, {{0.5, 2, -0.1}, axis}}}), stock,
               gridCovering(0, 0, 3, 3, 0.03));
  expectMap(r.map, 0, [&](double x, double y) {
    if (x < 0.5 || x > 2.5) return HUGE_VAL;
    const double e = std::max({0.0, 1 - y, y - 2});
    return e <= R ? -0.1 - std::sqrt(R * R - e * e) : HUGE_VAL;
  });
}

TEST(EdgeCases, CutterThatNeverTouchesLeavesTheStockTopEverywhere) {
  const Cutter bull = Cutter::make(CutterType::Bull, 1, 0.25);
  const Box3 stock({0, 0, -1}, {3, 3, 0.5});
  // Above the top (the lowest point is at z = 0.5 + 1e-9), and beside the stock.
  const ToolPath p = path({{{{-1, 1, 0.5 + 1e-9}, kUp}, {{4, 2, 0.5 + 1e-9}, kUp}},
                           {{{5, -3, -0.5}, kUp}, {{5, 6, -0.5}, kUp}}});
  const SimulationResult r = simulate(bull, p, stock, gridCovering(0, 0, 3, 3, 0.05));
  for (double h : r.map.heights()) ASSERT_EQ(h, 0.5);
  EXPECT_EQ(r.cast.exactEvaluations, 0u);  // culled without a single evaluation
}

TEST(EdgeCases, StockThinnerThanTheDepthKeepsTheCuttersEnvelope) {
  const Cutter ball = Cutter::make(CutterType::Ball, 0.5);
  const Box3 stock({0, 0, -0.1}, {2, 2, 0});  // 0.1 mm thick, cut 0.4 deep
  const Vec3 tip{1, 1, -0.4};
  const SimulationResult r =
      simulate(ball, path({{{tip, kUp}, {tip, kUp}}}), stock, gridCovering(0, 0, 2, 2, 0.02));
  expectMap(r.map, 0, [&](double x, double y) { return ballBottom(tip, 0.5, x, y); });
  EXPECT_NEAR(r.map.minHeight(), -0.4 + 0.5 - std::sqrt(0.25 - 2 * 0.01 * 0.01), kTol);
  EXPECT_LT(r.map.minHeight(), stock.min.z);
}

TEST(EdgeCases, GridOfOneCell) {
  const Cutter ball = Cutter::make(CutterType::Ball, 0.5);
  const Vec3 tip{0.1, 0.05, -0.2};
  for (const double spacing : {0.3, 5.0}) {  // exactly the stock, and far larger
    SCOPED_TRACE(spacing);
    const Box3 stock({0, 0, -1}, {0.3, 0.3, 0});
    const GridSpec g = gridCovering(0, 0, 0.3, 0.3, spacing);
    ASSERT_EQ(g.cells(), 1);
    const SimulationResult r = simulate(ball, path({{{tip, kUp}, {tip, kUp}}}), stock, g);
    expectMap(r.map, 0, [&](double x, double y) { return ballBottom(tip, 0.5, x, y); });
  }
}

TEST(EdgeCases, StepOverLargerThanTheCutterLeavesStockTopRidges) {
  // Ball R = 0.5 passes 1.5 mm apart (3 R): between |dy| > R the stock top is untouched;
  // within, the cross profile is the ball's, z = floor + R - sqrt(R^2 - dy^2).
  const Cutter ball = Cutter::make(CutterType::Ball, 0.5);
  const Box3 stock({0, 0, -1}, {4, 4, 0});
  RasterSpec spec;
  spec.direction = 'x';
  spec.stepOver = 1.5;
  spec.depth = 0.3;
  const SimulationResult r =
      simulate(ball, makeRaster(ball, stock, spec), stock, gridCovering(0, 0, 4, 4, 0.025));
  int cut = 0;
  expectMap(
      r.map, 0,
      [&](double, double y) {
        double best = HUGE_VAL;
        for (double pass = 0; pass <= 4; pass += 1.5)
          best = std::min(best, ballBottom({0, pass, -0.3}, 0.5, 0, y));
        return best;
      },
      &cut);
  // Untouched ridges: rows whose centre is more than sqrt(R^2 - (R - 0.3)^2) = 0.458
  // from every pass; about half the map.
  EXPECT_GT(cut, 160 * 60);
  EXPECT_LT(cut, 160 * 100);
}

}  // namespace
}  // namespace scallop
