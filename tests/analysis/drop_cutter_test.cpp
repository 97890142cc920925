// Drop-cutter (analysis/drop_cutter.h) against its definition: the highest tip height
// at which some triangle point p within R of the axis touches the cutter, max of
// p.z - h(d), evaluated by brute force over a dense barycentric sampling of the
// triangle, and against closed forms for a ball on a vertex and on a plane.
#include "analysis/drop_cutter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace scallop {
namespace {

double profile(const Cutter& c, double d) {
  const double rb = c.bottomRadius(), r = c.cornerRadius;
  if (d <= rb) return 0;
  return r - std::sqrt(std::max(0.0, r * r - (d - rb) * (d - rb)));
}

// Max of p.z - h(d(p)) over n(n+1)/2 sample points of the triangle (-inf if none).
double bruteForce(const Cutter& c, const std::array<Vec3, 3>& t, double x, double y, int n) {
  double best = -HUGE_VAL;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const double a = double(i) / n, b = double(j) / n;
      const Vec3 p = t[0] * (1 - a - b) + t[1] * a + t[2] * b;
      const double d = std::hypot(p.x - x, p.y - y);
      if (d <= c.radius) best = std::max(best, p.z - profile(c, d));
    }
  return best;
}

TEST(DropCutter, MatchesBruteForceOnRandomTriangles) {
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> u(-1, 1);
  const Cutter cutters[] = {Cutter::make(CutterType::Ball, 1.0),
                            Cutter::make(CutterType::Flat, 1.0),
                            Cutter::make(CutterType::Bull, 1.0, 0.3)};
  int hits = 0;
  double worst = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Cutter& c = cutters[trial % 3];
    std::array<Vec3, 3> t;
    for (Vec3& v : t) v = {1.5 * u(rng), 1.5 * u(rng), 0.8 * u(rng)};
    const double x = u(rng), y = u(rng);
    const DropContact exact = dropOnTriangle(c, t, x, y);
    const int n = 400;
    const double brute = bruteForce(c, t, x, y, n);
    if (!exact.hit) {
      EXPECT_EQ(brute, -HUGE_VAL) << trial;
      continue;
    }
    ++hits;
    // Never below a sampled touching point; above it by no more than the sampling
    // can miss (a slope of at most ~ tan(89 deg) over half the sample spacing would be
    // too generous: the triangles here have |slope| < 3, the spacing is < 0.01).
    EXPECT_GE(exact.tipZ, brute - 1e-12) << trial;
    worst = std::max(worst, exact.tipZ - brute);
    EXPECT_LE(exact.tipZ - brute, 0.03) << trial;
    // The contact point is on the triangle's plane, within R of the axis, and touches.
    const double d = std::hypot(exact.point.x - x, exact.point.y - y);
    EXPECT_LE(d, c.radius + 1e-12);
    EXPECT_NEAR(exact.point.z - profile(c, d), exact.tipZ, 1e-9) << trial;
  }
  EXPECT_GT(hits, 150);
  std::printf("drop-cutter vs brute force: %d contacts, largest excess %.2e mm\n", hits, worst);
}

TEST(DropCutter, BallOnAVertexAndOnAPlaneAreClosedForm) {
  const Cutter ball = Cutter::make(CutterType::Ball, 2.0);
  // A small triangle whose highest point, a vertex at distance 1 from the axis, decides.
  const std::array<Vec3, 3> spike{{{1, 0, 0.5}, {1.5, 0.2, -3}, {1.5, -0.2, -3}}};
  const DropContact v = dropOnTriangle(ball, spike, 0, 0);
  ASSERT_TRUE(v.hit);
  EXPECT_NEAR(v.tipZ, 0.5 - (2 - std::sqrt(3.0)), 1e-12);
  // The plane z = 0.5 x under a ball at the origin: touching, the centre is R from the
  // plane, i.e. R sqrt(1 + 0.5^2) above it vertically, so the tip is at R (sqrt(1.25) - 1).
  const std::array<Vec3, 3> plane{{{-10, -10, -5}, {10, -10, 5}, {0, 10, 0}}};
  const DropContact p = dropOnTriangle(ball, plane, 0, 0);
  ASSERT_TRUE(p.hit);
  EXPECT_NEAR(p.tipZ, 2 * (std::sqrt(1.25) - 1), 1e-12);
}

TEST(DropCutter, MeshDropTakesTheHighestTriangle) {
  TriangleMesh mesh = meshFromTriangles(
      {{{{-5, -5, 0}, {5, -5, 0}, {0, 5, 0}}}, {{{0.5, 0, 1}, {3, 1, 1}, {3, -1, 1}}}});
  const Cutter bull = Cutter::make(CutterType::Bull, 1.0, 0.25);
  const DropCutter dc(bull, mesh);
  // The raised triangle's nearest point (0.5, 0, 1) is inside the flat bottom.
  EXPECT_NEAR(dc.drop(0, 0).tipZ, 1.0, 1e-12);
  EXPECT_NEAR(dc.drop(-3, -3).tipZ, 0.0, 1e-12);
  EXPECT_FALSE(dc.drop(20, 20).hit);
}

}  // namespace
}  // namespace scallop
