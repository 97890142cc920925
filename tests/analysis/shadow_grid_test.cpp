// ShadowGrid (analysis/shadow_grid.h): a line along n through a point of a box finds that
// box in the cell of its (u, v) coordinates, for random boxes and directions.
#include "analysis/shadow_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace scallop {
namespace {

TEST(ShadowGrid, ALineThroughABoxFindsIt) {
  std::mt19937_64 rng(34);
  std::uniform_real_distribution<double> u01(0, 1), u11(-1, 1);
  for (int round = 0; round < 20; ++round) {
    std::vector<Box3> boxes;
    for (int k = 0; k < 50; ++k) {
      const Vec3 lo{20 * u11(rng), 20 * u11(rng), 5 * u11(rng)};
      boxes.push_back({lo, lo + Vec3{6 * u01(rng), 0.5 * u01(rng), 2 * u01(rng)}});
    }
    Vec3 n{u11(rng), u11(rng), u11(rng)};
    n = n / length(n);
    const Vec3 e = std::fabs(n.x) < 0.5 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 u = cross(n, e) / length(cross(n, e)), v = cross(n, u);
    ShadowGrid grid;
    ASSERT_TRUE(grid.build(boxes, u, v, 1e-6));
    for (int k = 0; k < 50; ++k) {
      const Box3& b = boxes[size_t(k)];
      for (int s = 0; s < 20; ++s) {
        // A point of the box (its 8 corners first), moved along n.
        const auto at = [&](double lo, double hi, int bit) {
          const double t = s < 8 ? double((s >> bit) & 1) : u01(rng);
          return lo + t * (hi - lo);
        };
        const Vec3 q{at(b.min.x, b.max.x, 0), at(b.min.y, b.max.y, 1), at(b.min.z, b.max.z, 2)};
        const Vec3 p = q + n * (30 * u11(rng));
        size_t count = 0;
        const uint32_t* ids = grid.boxesAt(dot(p, u), dot(p, v), count);
        ASSERT_TRUE(std::binary_search(ids, ids + count, uint32_t(k)))
            << "round " << round << " box " << k << " sample " << s;
      }
    }
  }
}

TEST(ShadowGrid, NoBoxesNoCandidatesAndFarPointsHaveNone) {
  ShadowGrid grid;
  EXPECT_TRUE(grid.build({}, {1, 0, 0}, {0, 1, 0}, 1e-6));
  size_t count = 1;
  grid.boxesAt(0, 0, count);
  EXPECT_EQ(count, 0u);
  ASSERT_TRUE(grid.build({Box3{{0, 0, 0}, {1, 1, 1}}}, {1, 0, 0}, {0, 1, 0}, 1e-6));
  grid.boxesAt(0.5, 0.5, count);
  EXPECT_EQ(count, 1u);
  grid.boxesAt(3, 0.5, count);
  EXPECT_EQ(count, 0u);
}

}  // namespace
}  // namespace scallop
