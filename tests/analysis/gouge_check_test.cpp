// The exact cylinder-triangle penetration depth (analysis/gouge_check.h) against hand
// computations and against dense sampling of the triangle, and the vertex test.
#include "analysis/gouge_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace scallop {
namespace {

// Horizontal cylinder along +y: tip (0, 0, R), R = 2, L = 10.
Cylinder horizontal() {
  return {{0, 0, 2}, {0, 1, 0}, 2.0, 10.0};
}

TEST(TrianglePenetration, TangentPlaneHasZeroDepth) {
  const Cylinder c = horizontal();
  // The plane z = 0 touches the flank along the line x = 0, z = 0.
  EXPECT_LE(trianglePenetration({Vec3{-30, -30, 0}, Vec3{30, -30, 0}, Vec3{0, 60, 0}}, c), 1e-15);
}

TEST(TrianglePenetration, FacetInteriorWithEveryVertexOutside) {
  const Cylinder c = horizontal();
  // The plane z = 0.5 is 1.5 from the axis (z = 2): depth 2 - 1.5 = 0.5, although all
  // three vertices are tens of millimetres away.
  const std::array<Vec3, 3> tri = {Vec3{-50, -50, 0.5}, Vec3{50, -50, 0.5}, Vec3{0, 100, 0.5}};
  EXPECT_NEAR(trianglePenetration(tri, c), 0.5, 1e-12);
  for (const Vec3& v : tri) EXPECT_FALSE(vertexInside(v, c, 1e-9));
}

TEST(TrianglePenetration, EdgeCrossingTheCutter) {
  const Cylinder c = horizontal();
  // A vertical triangle in the plane y = 5 whose top edge z = 1 + 0.1 x crosses the
  // disk: its closest point to the axis (0, 2) in the xz plane is on that edge line,
  // distance |0.1*0 - 2 + 1| / sqrt(1.01) = 1 / sqrt(1.01).
  const std::array<Vec3, 3> tri = {Vec3{-40, 5, 1 - 4.0}, Vec3{40, 5, 1 + 4.0}, Vec3{0, 5, -30}};
  EXPECT_NEAR(trianglePenetration(tri, c), 2 - 1 / std::sqrt(1.01), 1e-12);
  for (const Vec3& v : tri) EXPECT_FALSE(vertexInside(v, c, 1e-9));
}

TEST(TrianglePenetration, OnlyTheFluteCounts) {
  const Cylinder c = horizontal();
  // Crossing the axis line, but beyond the flute (y > 10) or behind the tip (y < 0).
  EXPECT_EQ(trianglePenetration({Vec3{-5, 11, 0}, Vec3{5, 11, 0}, Vec3{0, 12, 5}}, c), 0.0);
  EXPECT_EQ(trianglePenetration({Vec3{-5, -1, 0}, Vec3{5, -1, 0}, Vec3{0, -2, 5}}, c), 0.0);
  // Crossing it inside: the axis meets the triangle, depth R.
  EXPECT_NEAR(trianglePenetration({Vec3{-5, 3, 0}, Vec3{5, 3, 0}, Vec3{0, 3, 5}}, c), 2.0, 1e-15);
  // Straddling the tip plane y = 0: clipped, still meets the axis.
  EXPECT_NEAR(trianglePenetration({Vec3{-5, -3, 2}, Vec3{5, -3, 2}, Vec3{0, 3, 2}}, c), 2.0, 1e-15);
}

TEST(VertexTest, InsideMeansWithinTheFluteAndCloserThanR) {
  const Cylinder c = horizontal();
  EXPECT_TRUE(vertexInside({0.5, 5, 1.5}, c, 1e-9));
  EXPECT_FALSE(vertexInside({0.5, 10.5, 1.5}, c, 1e-9));  // beyond the flute
  EXPECT_FALSE(vertexInside({0.5, -0.5, 1.5}, c, 1e-9));  // behind the tip
  EXPECT_FALSE(vertexInside({0, 5, 0}, c, 1e-9));         // on the flank
  EXPECT_FALSE(vertexInside({2.1, 5, 2}, c, 1e-9));
}

// Dense sampling of the triangle (barycentric grid) is an independent lower bound of
// the exact maximum, and close to it: |grad (R - d)| <= 1, so within the sample spacing.
TEST(TrianglePenetration, AgreesWithDenseSampling) {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> u(-1, 1);
  int positive = 0;
  for (int trial = 0; trial < 300; ++trial) {
    Cylinder c;
    c.axis = normalize(Vec3{u(rng), u(rng), u(rng)});
    c.tip = {u(rng), u(rng), u(rng)};
    c.radius = 1 + 0.5 * (u(rng) + 1);
    c.length = 2 + 2 * (u(rng) + 1);
    const Vec3 centre = c.tip + c.axis * (0.5 * c.length);
    std::array<Vec3, 3> tri;
    for (auto& v : tri) v = centre + Vec3{u(rng), u(rng), u(rng)} * 4.0;
    const double exact = trianglePenetration(tri, c);
    const int n = 400;
    double sampled = 0, spacing = 0;
    for (int i = 0; i < 3; ++i) spacing = std::max(spacing, length(tri[i] - tri[(i + 1) % 3]) / n);
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const Vec3 p =
            tri[0] + (tri[1] - tri[0]) * (double(i) / n) + (tri[2] - tri[0]) * (double(j) / n);
        const double s = dot(p - c.tip, c.axis);
        if (s < 0 || s > c.length) continue;
        sampled = std::max(sampled, c.radius - length(p - c.tip - c.axis * s));
      }
    EXPECT_GE(exact, sampled - 1e-12) << "trial " << trial;
    // Near the slab's ends the sampled set can miss a sliver; allow a few spacings.
    EXPECT_LE(exact, sampled + 3 * spacing + 1e-12) << "trial " << trial;
    positive += exact > 0;
  }
  EXPECT_GT(positive, 50);
}

}  // namespace
}  // namespace scallop
