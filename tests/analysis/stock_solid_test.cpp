// StockSolid::reachesAbove's highest point within a rapid's reach, against closed forms
// on a wedge whose top rises linearly: z = x / 10 over [0, 10] x [0, 10], bottom at -1.
#include "analysis/stock_solid.h"

#include <gtest/gtest.h>

#include <array>
#include <vector>

namespace scallop {
namespace {

StockSolid wedge() {
  const Vec3 b00{0, 0, -1}, b10{10, 0, -1}, b11{10, 10, -1}, b01{0, 10, -1};
  const Vec3 t00{0, 0, 0}, t10{10, 0, 1}, t11{10, 10, 1}, t01{0, 10, 0};
  // Each quad's corners counter-clockwise seen from outside, as two triangles.
  const std::vector<std::array<Vec3, 4>> quads = {
      {b00, b01, b11, b10},  // bottom
      {t00, t10, t11, t01},  // sloped top
      {b00, b10, t10, t00},  // y = 0
      {b10, b11, t11, t10},  // x = 10
      {b11, b01, t01, t11},  // y = 10
      {b01, b00, t00, t01},  // x = 0
  };
  std::vector<std::array<Vec3, 3>> soup;
  for (const auto& q : quads) {
    soup.push_back({q[0], q[1], q[2]});
    soup.push_back({q[0], q[2], q[3]});
  }
  TriangleMesh mesh = meshFromTriangles(soup);
  checkClosedSolid(mesh, "wedge");
  return StockSolid(std::move(mesh));
}

TEST(StockSolid, HighestPointWithinReachOfARapid) {
  const StockSolid solid = wedge();
  Vec3 met;
  // A rapid along x = 2 across the whole wedge, reach 1: the top is highest where the
  // reach ends uphill, x = 3, z = 0.3.
  ASSERT_TRUE(solid.reachesAbove({2, -5, 0}, {2, 15, 0}, 1.0, -0.5, &met));
  EXPECT_NEAR(met.z, 0.3, 1e-9);
  EXPECT_NEAR(met.x, 3, 1e-9);
  // A short rapid inside the wedge's footprint, reach 1: the uphill end of its capsule,
  // (5 + 1, 5), z = 0.6 (neither a corner nor an edge of the top).
  ASSERT_TRUE(solid.reachesAbove({4, 4, 0}, {5, 5, 0}, 1.0, -0.5, &met));
  EXPECT_NEAR(met.z, 0.6, 1e-12);
  EXPECT_NEAR(met.x, 6, 1e-12);
  EXPECT_NEAR(met.y, 5, 1e-12);
  // Beyond the high edge, x = 10.5 with reach 1: the edge itself, z = 1.
  ASSERT_TRUE(solid.reachesAbove({10.5, 2, 0}, {10.5, 3, 0}, 1.0, -0.5, &met));
  EXPECT_NEAR(met.z, 1, 1e-12);
  // Beside the wedge's low side, out of reach, and over it above its top: nothing.
  EXPECT_FALSE(solid.reachesAbove({-1.5, 2, 0}, {-1.5, 8, 0}, 1.0, -0.5));
  EXPECT_FALSE(solid.reachesAbove({2, 2, 0}, {8, 8, 0}, 1.0, 1.0));
}

}  // namespace
}  // namespace scallop
