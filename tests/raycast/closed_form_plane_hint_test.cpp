// A whole move's culling planes come from closedFormPlaneHint (swept_scene.cpp) instead
// of exact evaluations: for a ball with a vertical axis (B9's) its normal must be the
// exact lowest point's (or the planes cull less than they did), and for any cutter and
// axis the plane through the solid's support must lie below every exact height.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "raycast/scene_tiles.h"
#include "sweep/cutter.h"
#include "sweep/swept_move.h"
#include "sweep/swept_segment.h"

namespace scallop {
namespace {

using namespace scene_detail;

TEST(ClosedFormPlaneHint, ExactNormalForVerticalBall) {
  std::mt19937 rng(20261204);
  std::uniform_real_distribution<double> unit(-1, 1);
  const Cutter cutters[] = {Cutter::make(CutterType::Ball, 1), Cutter::make(CutterType::Ball, 3)};
  int compared = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const Cutter& cutter = cutters[trial % 2];
    const Vec3 start{unit(rng), unit(rng), unit(rng)};
    // Short moves, as the whole-move tiles have them, rising or falling up to 0.3 mm/mm.
    const double len = 0.05 + 0.2 * std::fabs(unit(rng)), heading = 3.2 * unit(rng);
    const Vec3 end =
        start + Vec3{len * std::cos(heading), len * std::sin(heading), 0.3 * len * unit(rng)};
    const SweptMove move(SweptSegment(cutter, start, end, {0, 0, 1}));
    for (int i = 0; i < 50; ++i) {
      const double x = start.x + 0.9 * cutter.radius * unit(rng);
      const double y = start.y + 0.9 * cutter.radius * unit(rng);
      const LowestPoint hint = closedFormPlaneHint(move, x, y);
      const LowestPoint exact = move.planeHint(x, y);
      ASSERT_EQ(hint.hit, exact.hit && exact.normal.z < -1e-9) << trial << " " << x << " " << y;
      if (!hint.hit) continue;
      EXPECT_NEAR(hint.normal.x, exact.normal.x, 1e-6) << trial << " " << x << " " << y;
      EXPECT_NEAR(hint.normal.y, exact.normal.y, 1e-6) << trial << " " << x << " " << y;
      EXPECT_NEAR(hint.normal.z, exact.normal.z, 1e-6) << trial << " " << x << " " << y;
      ++compared;
    }
  }
  EXPECT_GT(compared, 500);
}

TEST(ClosedFormPlaneHint, PlanesLieBelowEveryHeightForTiltedAxes) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  const Cutter cutters[] = {Cutter::make(CutterType::Ball, 1), Cutter::make(CutterType::Bull, 3, 1),
                            Cutter::make(CutterType::Flat, 2)};
  for (int trial = 0; trial < 15; ++trial) {
    const Cutter& cutter = cutters[trial % 3];
    const Vec3 start{unit(rng), unit(rng), unit(rng)};
    const Vec3 end = start + Vec3{0.2 * unit(rng), 0.2 * unit(rng), 0.05 * unit(rng)};
    const Vec3 axis = normalize(Vec3{0.4 * unit(rng), 0.4 * unit(rng), 1});
    const SweptMove move(SweptSegment(cutter, start, end, axis));
    for (int s = 0; s < 5; ++s) {
      const double sx = start.x + cutter.radius * unit(rng),
                   sy = start.y + cutter.radius * unit(rng);
      const LowestPoint hint = closedFormPlaneHint(move, sx, sy);
      TilePlane plane;
      if (!planeFrom(move, hint, sx, sy, plane)) continue;
      for (int i = 0; i < 200; ++i) {
        const double x = start.x + 1.5 * cutter.radius * unit(rng);
        const double y = start.y + 1.5 * cutter.radius * unit(rng);
        const LowestPoint lp = move.planeHint(x, y);
        if (lp.hit) {
          EXPECT_LE(plane.a + plane.b * x + plane.c * y, lp.z + 1e-9) << trial;
        }
      }
    }
  }
}

}  // namespace
}  // namespace scallop
