// A cutter of any profile given to SweptMove as a SweptSegment (the sweep of merged
// collinear moves, and analysis/simulated_interval's pass) is swept as its own solid:
// SweptSegment's closed form knows only ball, flat and bull, so such a move must go
// through the certified search. Checked against the brute-force reference with the
// profile's own width w(s), on a barrel whose axis lies nearly horizontal (tilt
// 88.5 deg), where the flat cylinder of its largest width dips up to 0.3 mm lower.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "base/constants.h"
#include "sweep/brute_force_reference.h"
#include "sweep/cutter_profile.h"
#include "sweep/cutter_shapes.h"
#include "sweep/raster.h"
#include "sweep/swept_move.h"
#include "sweep/swept_segment.h"
#include "tests/sweep/profile_cases.h"

namespace scallop {
namespace {

// The barrel of tests/sweep/profile_cases.h (test::barrelCutter).
constexpr double kFormRadius = test::kBarrelFormRadius;
constexpr double kFormCentreRho = test::kBarrelFormCentreRho,
                 kFormCentreS = test::kBarrelFormCentreS;

TEST(ProfileSegmentMove, BarrelAlongAMoveMatchesBruteForce) {
  double p1Rho = 0, p1S = 0;
  test::barrelP1(&p1Rho, &p1S);
  const Cutter barrel = test::barrelCutter();
  ref::RefCutter rc;
  rc.R = 5;
  rc.L = 30;
  rc.width = [=](double s) {
    if (s <= p1S) return p1Rho * s / p1S;
    if (s <= kFormCentreS)
      return kFormCentreRho +
             std::sqrt(kFormRadius * kFormRadius - (s - kFormCentreS) * (s - kFormCentreS));
    return 5.0;
  };
  const Vec3 axis = leadTiltAxis(Vec3{1, 0, 0}, 0, 88.5);
  const Vec3 start{-40, 0, 0}, end{40, 0, 0};
  const SweptMove move{SweptSegment(barrel, start, end, axis)};
  int hits = 0;
  for (double y : {0.05, 0.5, 2.0, 4.0, 10.0, 20.0, 28.0})
    for (double x : {0.0, 3.7}) {
      const LowestPoint got = move.lowestPoint(x, y);
      const ref::RefHit want = ref::sweptLowest(rc, start, end, axis, x, y);
      ASSERT_EQ(got.hit, want.hit) << x << " " << y;
      if (!want.hit) continue;
      ++hits;
      EXPECT_NEAR(got.z, want.z, 1e-6) << "x " << x << " y " << y;
    }
  EXPECT_GT(hits, 10);
}

}  // namespace
}  // namespace scallop
