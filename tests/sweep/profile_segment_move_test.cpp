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

namespace scallop {
namespace {

// The barrel of tests/analysis/contact_curvature_test.cpp: a line from the tip to P1,
// the form arc of radius 250 mm centred at (rho, s) = (-245, 15) up to (5, 15), the
// flank rho = 5 up to s = 30.
constexpr double kFormRadius = 250, kFormCentreRho = -245, kFormCentreS = 15;

TEST(ProfileSegmentMove, BarrelAlongAMoveMatchesBruteForce) {
  const double span = degToRad(3);
  const double p1Rho = kFormCentreRho + kFormRadius * std::cos(span);
  const double p1S = kFormCentreS - kFormRadius * std::sin(span);
  std::vector<ProfileSegment> chain(3);
  chain[0] = {0, 0, p1Rho, p1S, 0};
  chain[1] = {p1Rho, p1S, 5, 15, kFormRadius};
  chain[2] = {5, 15, 5, 30, 0};
  const Cutter barrel = cutterOfChain(CutterType::Profile, chain, "test");
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
