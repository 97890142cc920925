// A freeform 5-axis finishing path as CAM writes it (the turning-axis issue's case):
// bull R3 r1, tips on z = 0.5 sin(2 pi x/10) cos(2 pi y/14), the axis the surface normal
// leaned 5 deg towards the feed given at every CL point 0.05 mm apart, passes 0.5 mm
// apart. A window of it simulated at 2 um against the brute-force reference, cell by
// cell, with no culling and no code of sweep/*.cpp on the reference's side.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "base/constants.h"
#include "raycast/simulation.h"
#include "sweep/brute_force_reference.h"

namespace scallop {
namespace {

double surface(double x, double y) {
  return 0.5 * std::sin(2 * kPi * x / 10) * std::cos(2 * kPi * y / 14);
}

Vec3 leanedNormal(double x, double y) {
  const double fx = 0.5 * (2 * kPi / 10) * std::cos(2 * kPi * x / 10) * std::cos(2 * kPi * y / 14);
  const double fy = -0.5 * (2 * kPi / 14) * std::sin(2 * kPi * x / 10) * std::sin(2 * kPi * y / 14);
  const Vec3 n = normalize(Vec3{-fx, -fy, 1});
  const Vec3 along = normalize(Vec3{1, 0, 0} - n * n.x);  // the feed in the tangent plane
  const double lean = degToRad(5);
  return normalize(n * std::cos(lean) + along * std::sin(lean));
}

// Passes along +X over [x0, x1] at y = y0, y0 + 0.5, ... <= y1, a CL point every 0.05 mm.
ToolPath freeformClPath(double x0, double x1, double y0, double y1) {
  ToolPath path;
  const int points = int(std::round((x1 - x0) / 0.05));
  for (double y = y0; y <= y1 + 1e-9; y += 0.5) {
    for (int i = 0; i < points; ++i) {
      const double xa = x0 + 0.05 * i, xb = xa + 0.05;
      path.moves.push_back(Move{{{xa, y, surface(xa, y)}, leanedNormal(xa, y)},
                                {{xb, y, surface(xb, y)}, leanedNormal(xb, y)},
                                false});
    }
  }
  return path;
}

// The reference's lowest point of the whole path on the line (x, y): for each move, a
// cheap lower bound first (the cutter at mid-move grown by the farthest any of its
// points travels in half the move, which holds every pose of the move), and the dense
// turningLowest only where that bound can beat the best so far.
double referenceHeight(const ref::RefCutter& c, const ToolPath& path, double x, double y,
                       double ceiling) {
  struct Entry {
    double bound;
    size_t move;
  };
  std::vector<Entry> order;
  const double reach = std::hypot(c.L, c.R);
  for (size_t k = 0; k < path.moves.size(); ++k) {
    const Move& m = path.moves[k];
    const double phi = std::acos(std::fmin(1.0, dot(m.from.axis, m.to.axis)));
    const double grow = 0.5 * (length(m.to.tip - m.from.tip) + phi * reach) + 1e-9;
    const Vec3 axis = ref::slerp(m.from.axis, m.to.axis, 0.5);
    const Vec3 tip = (m.from.tip + m.to.tip) * 0.5 - axis * grow;
    const ref::RefCutter grown{c.R + grow, c.r + grow, c.L + 2 * grow};
    const ref::RefHit h = ref::stationaryLowest(grown, tip, axis, x, y);
    if (h.hit && h.z < ceiling) order.push_back({h.z, k});
  }
  std::sort(order.begin(), order.end(),
            [](const Entry& a, const Entry& b) { return a.bound < b.bound; });
  double best = ceiling;
  for (const Entry& e : order) {
    if (e.bound >= best) break;
    const Move& m = path.moves[e.move];
    const ref::RefCurve curve{m.from.tip, m.to.tip,
                              [&](double t) { return ref::slerp(m.from.axis, m.to.axis, t); }};
    const ref::RefHit h = ref::turningLowest(c, curve, x, y, 201);
    if (h.hit) best = std::min(best, h.z);
  }
  return best;
}

TEST(TurningPath, FreeformWindowAtTwoMicronsMatchesTheBruteForce) {
  const Cutter cutter = Cutter::make(CutterType::Bull, 3, 1);
  const ref::RefCutter refCutter = ref::makeRefCutter(CutterType::Bull, 3, 1);
  // The window [6.2, 6.3] x [3.1, 3.2] mm at 2 um, with the passes and CL points that
  // can reach it.
  const Box3 stock({6.2, 3.1, -2}, {6.3, 3.2, 0.6});
  const ToolPath path = freeformClPath(2, 10.5, -0.5, 7);
  const GridSpec grid = gridCovering(6.2, 3.1, 6.3, 3.2, 0.002);
  const SimulationResult sim = simulate(cutter, path, stock, grid);
  ASSERT_EQ(grid.cells(), 2500);

  std::mt19937_64 rng(13);
  std::uniform_int_distribution<int64_t> pick(0, grid.nx - 1);
  double worst = 0;
  for (int n = 0; n < 16; ++n) {
    const int64_t i = pick(rng), j = pick(rng);
    const double x = grid.cellCentreX(i), y = grid.cellCentreY(j);
    const double want = referenceHeight(refCutter, path, x, y, stock.max.z);
    ASSERT_LT(want, stock.max.z);  // the window is cut everywhere
    worst = std::max(worst, std::fabs(sim.map.at(i, j) - want));
    EXPECT_NEAR(sim.map.at(i, j), want, 1e-6) << "cell " << i << " " << j;
  }
  std::printf("freeform window: worst |exact - brute force| = %.3g mm over 16 cells\n", worst);
  EXPECT_EQ(SweptMove::unprovenSearches(), 0u);
}

}  // namespace
}  // namespace scallop
