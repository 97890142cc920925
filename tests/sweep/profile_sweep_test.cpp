// profileSweepLowestPoint (sweep/profile_sweep.h), the constant-axis path of general
// cutters: on random profiles (profile_cases.h) and constant-axis moves (level feeds,
// ramps, plunges, a standing tip) it decides almost every line, and what it returns
// agrees with the certified search within 1e-9 mm and with the brute-force reference
// within 1e-6 mm; a cutoff only turns heights at or above it into misses.
#include "sweep/profile_sweep.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "base/constants.h"
#include "sweep/brute_force_reference.h"
#include "sweep/certified_search.h"
#include "sweep/pose_curve.h"
#include "sweep/profile_cases.h"
#include "sweep/swept_move.h"
#include "sweep/tip_ball.h"

namespace scallop {
namespace {

TEST(ProfileSweep, AgreesWithCertifiedSearchAndBruteForce) {
  std::mt19937_64 rng(3304);
  std::uniform_real_distribution<double> u(-1, 1), u01(0, 1);
  int decided = 0, undecided = 0, hits = 0, misses = 0;
  double worstCertified = 0, worstReference = 0;
  for (int k = 0; k < 48; ++k) {
    const test::ProfileCase pc = test::randomProfileCase(rng, k);
    const Cutter c = pc.cutter();
    ref::RefCutter rc;
    rc.R = pc.maxWidth(), rc.L = pc.fluteLength();
    rc.width = [pc](double s) { return pc.width(s); };
    // Polar angles up to 90 degrees (k % 3 == 0: vertical).
    const Vec3 axis0 =
        k % 3 == 0 ? Vec3{0, 0, 1} : ref::unitFromAngles(0.5 * kPi * u01(rng), 2 * kPi * u01(rng));
    const Vec3 p0{u(rng), u(rng), u(rng)};
    const Vec3 p1 = p0 + test::randomMoveEnd(rng, k);
    const PoseCurve curve = PoseCurve::linear({p0, axis0}, {p1, axis0});
    const Vec3 a = curve.axis(0);
    const SweptMove move(c, curve);
    const Box3 box = move.bounds();
    const TurningBounds bounds{std::hypot(c.fluteLength, c.radius), box.max.z + 1, length(p1 - p0)};
    for (int q = 0; q < 8; ++q) {
      const double x = 0.5 * (box.min.x + box.max.x) + 0.55 * (box.max.x - box.min.x) * u(rng);
      const double y = 0.5 * (box.min.y + box.max.y) + 0.55 * (box.max.y - box.min.y) * u(rng);
      const ProfileSweepResult got = profileSweepLowestPoint(*c.profile, a, p0, p1, x, y);
      if (!got.decided) {
        ++undecided;
        continue;
      }
      ++decided;
      const LowestPoint want = certifiedLowestPoint(c, curve, bounds, x, y, HUGE_VAL);
      const ref::RefHit brute = ref::sweptLowest(rc, p0, p1, a, x, y);
      ASSERT_EQ(got.point.hit, want.hit) << pc.name << " k " << k << " (" << x << ", " << y << ")";
      ASSERT_EQ(got.point.hit, brute.hit) << pc.name << " k " << k;
      if (!got.point.hit) {
        ++misses;
        continue;
      }
      ++hits;
      worstCertified = std::max(worstCertified, std::fabs(got.point.z - want.z));
      worstReference = std::max(worstReference, std::fabs(got.point.z - brute.z));
      EXPECT_NEAR(got.point.z, want.z, 1e-9) << pc.name << " k " << k;
      EXPECT_NEAR(got.point.z, brute.z, 1e-6) << pc.name << " k " << k;
      // The move's own answer (the dispatch) is this one, or for a ball-tipped profile
      // the tip ball's (tip_ball.h), within the gap both are proven to.
      const LowestPoint viaMove = move.lowestPoint(x, y);
      if (tipBallOf(c).valid)
        EXPECT_NEAR(viaMove.z, got.point.z, 1.5e-9);
      else
        EXPECT_EQ(viaMove.z, got.point.z);
      // A cutoff above the height keeps it, one below makes a miss.
      const ProfileSweepResult above =
          profileSweepLowestPoint(*c.profile, a, p0, p1, x, y, got.point.z + 1e-6);
      EXPECT_TRUE(above.decided && above.point.hit && above.point.z == got.point.z);
      const ProfileSweepResult below =
          profileSweepLowestPoint(*c.profile, a, p0, p1, x, y, got.point.z - 1e-6);
      EXPECT_FALSE(below.decided && below.point.hit);
    }
  }
  std::printf(
      "profile sweep: %d decided (%d hits, %d misses), %d undecided; worst vs certified %.2e, "
      "vs brute force %.2e mm\n",
      decided, hits, misses, undecided, worstCertified, worstReference);
  EXPECT_GT(hits, 150);
  EXPECT_LE(undecided * 20, decided + undecided);  // at most 5 % fall back
}

}  // namespace
}  // namespace scallop
