// The tip-ball fast path of general cutters (sweep/tip_ball.h): which profiles have a ball
// tip, and the heights it gives against the certified search (the general kernel, which
// does not use it) on constant-axis and turning moves of tapered balls and taper barrels.
#include "sweep/tip_ball.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "base/constants.h"
#include "sweep/certified_search.h"
#include "sweep/cutter_shapes.h"
#include "sweep/pose_curve.h"
#include "sweep/swept_move.h"

namespace scallop {
namespace {

Cutter taperBall(double r, double taperDeg) {
  TaperBallShape s;
  s.tipRadius = r, s.taperDeg = taperDeg, s.fluteLength = 12 * r;
  return cutterOfChain(CutterType::TaperBall, taperBallChain(s, "tool"), "tool");
}

Cutter taperBarrel() {  // bench B6's
  TaperBarrelShape s;
  s.tipRadius = 2, s.formRadius = 250, s.taperDeg = 10, s.referenceDiameter = 8;
  s.fluteLength = 20;
  return cutterOfChain(CutterType::TaperBarrel, taperBarrelChain(s, "tool"), "tool");
}

TEST(TipBall, FoundOnBallTippedProfilesOnly) {
  const TipBall b = tipBallOf(taperBall(1, 5));
  ASSERT_TRUE(b.valid);
  EXPECT_NEAR(b.radius, 1, 1e-12);
  const double beta = degToRad(5);  // the flank is tangent at (r cos b, r (1 - sin b))
  EXPECT_NEAR(b.splitS, 1 - std::sin(beta), 1e-9);
  EXPECT_NEAR(b.splitWidth, std::cos(beta), 1e-9);
  EXPECT_TRUE(tipBallOf(taperBarrel()).valid);
  OvalShape oval;
  oval.diameter = 10, oval.formRadius = 8, oval.tipRadius = 2, oval.fluteLength = 10;
  EXPECT_TRUE(tipBallOf(cutterOfChain(CutterType::Oval, ovalChain(oval, "t"), "t")).valid);
  // A flat bottom, a point, a lens's small corner arc after its tip arc: none.
  TaperBullShape bull;
  bull.tipDiameter = 4, bull.cornerRadius = 0.5, bull.taperDeg = 5, bull.fluteLength = 10;
  EXPECT_FALSE(
      tipBallOf(cutterOfChain(CutterType::TaperBull, taperBullChain(bull, "t"), "t")).valid);
  ConeShape cone;
  cone.angleDeg = 90, cone.diameter = 6, cone.fluteLength = 10;
  EXPECT_FALSE(tipBallOf(cutterOfChain(CutterType::Cone, coneChain(cone, "t"), "t")).valid);
  LensShape lens;
  lens.diameter = 10, lens.formRadius = 20, lens.cornerRadius = 1, lens.fluteLength = 10;
  EXPECT_FALSE(tipBallOf(cutterOfChain(CutterType::Lens, lensChain(lens, "t"), "t")).valid);
  EXPECT_FALSE(tipBallOf(Cutter::make(CutterType::Ball, 3)).valid);
}

// Random moves (constant axes and turns of up to 0.6 rad, leads up to 60 degrees) and
// lines over them: the move's height (the tip ball's where the rest provably stays above
// it) equals the certified search's within the 1e-9 mm both are proven to, hit for hit.
TEST(TipBall, HeightsAgreeWithCertifiedSearch) {
  std::mt19937_64 rng(3307);
  std::uniform_real_distribution<double> u(-1, 1), u01(0, 1);
  int hits = 0, fast = 0;
  double worst = 0;
  for (int k = 0; k < 24; ++k) {
    const Cutter c = k % 3 == 2 ? taperBarrel() : taperBall(0.5 + u01(rng), 1 + 10 * u01(rng));
    const double lead = degToRad((k % 4) * 20), turn = k % 2 ? 0.6 * u01(rng) : 0;
    const double phi = 2 * kPi * u01(rng);
    const Vec3 a0{std::sin(lead) * std::cos(phi), std::sin(lead) * std::sin(phi), std::cos(lead)};
    const double lead1 = lead + turn;
    const Vec3 a1{std::sin(lead1) * std::cos(phi), std::sin(lead1) * std::sin(phi),
                  std::cos(lead1)};
    const Vec3 p0{u(rng), u(rng), u(rng)};
    const Vec3 p1 = p0 + Vec3{3 * u(rng), 3 * u(rng), k % 5 == 0 ? u(rng) : 0.1 * u(rng)};
    const PoseCurve curve = PoseCurve::linear({p0, a0}, {p1, a1});
    const SweptMove move(c, curve);
    const Cutter ballCutter = tipBallCutter(tipBallOf(c));
    const SweptMove ball(ballCutter, curve);
    const TurningBounds bounds{std::hypot(c.fluteLength, c.radius), move.bounds().max.z + 1,
                               curve.tipSpeedBound()};
    const Box3 box = ball.bounds();
    for (int q = 0; q < 10; ++q) {
      const double x = 0.5 * (box.min.x + box.max.x) + 0.6 * (box.max.x - box.min.x) * u(rng);
      const double y = 0.5 * (box.min.y + box.max.y) + 0.6 * (box.max.y - box.min.y) * u(rng);
      const LowestPoint got = move.lowestPoint(x, y);
      const LowestPoint want = certifiedLowestPoint(c, curve, bounds, x, y, HUGE_VAL);
      ASSERT_EQ(got.hit, want.hit) << "k " << k << " (" << x << ", " << y << ")";
      if (!got.hit) continue;
      ++hits;
      const LowestPoint viaBall = ball.lowestPoint(x, y);
      fast += viaBall.hit && viaBall.z == got.z;
      worst = std::max(worst, std::fabs(got.z - want.z));
      EXPECT_NEAR(got.z, want.z, 1.5e-9) << "k " << k << " (" << x << ", " << y << ")";
      // A cutoff just below the height may make a miss (never another height), one
      // above keeps it.
      const LowestPoint below = move.lowestPoint(x, y, nullptr, got.z - 1e-6);
      EXPECT_TRUE(!below.hit || below.z == got.z) << "k " << k;
      const LowestPoint above = move.lowestPoint(x, y, nullptr, got.z + 1e-6);
      EXPECT_TRUE(above.hit && above.z == got.z) << "k " << k;
    }
  }
  std::printf("tip ball: %d hits, %d by the tip ball; worst vs certified %.2e mm\n", hits, fast,
              worst);
  EXPECT_GT(hits, 120);
  EXPECT_GT(fast * 4, hits);  // random lines: many lie up the flank, where it falls back
}

// The scene's constant-axis treatment (SweptMove::takesSectionMemo): a tip ball on a
// constant axis takes a section memo and a cutoff, and neither changes a height: along a
// row of lines, one memo shared by every line and the cutoff of the lowest so far give
// the same bits as no memo and no cutoff (a miss only where the height is at or above
// the cutoff). A turning move, and a cutter without a ball tip, take none.
TEST(TipBall, ConstantAxisTakesSectionMemoAndKeepsHeights) {
  const Cutter c = taperBall(1, 5);
  const Vec3 axis{0, 0, 1};
  const SweptMove move(c, PoseCurve::linear({{0, 0, 0}, axis}, {{4, 0.5, -0.2}, axis}));
  ASSERT_TRUE(move.turning());  // a general cutter: no SweptSegment of its own
  EXPECT_TRUE(move.takesSectionMemo());
  const Vec3 tilted = normalize(Vec3{0.3, 0, 1});
  EXPECT_FALSE(
      SweptMove(c, PoseCurve::linear({{0, 0, 0}, axis}, {{4, 0, 0}, tilted})).takesSectionMemo());
  TaperBullShape bull;
  bull.tipDiameter = 4, bull.cornerRadius = 0.5, bull.taperDeg = 5, bull.fluteLength = 10;
  const Cutter noBall = cutterOfChain(CutterType::TaperBull, taperBullChain(bull, "t"), "t");
  EXPECT_FALSE(SweptMove(noBall, PoseCurve::linear({{0, 0, 0}, axis}, {{4, 0, 0}, axis}))
                   .takesSectionMemo());
  EXPECT_TRUE(SweptMove(Cutter::make(CutterType::Ball, 1),
                        PoseCurve::linear({{0, 0, 0}, axis}, {{4, 0, 0}, axis}))
                  .takesSectionMemo());

  int hits = 0, memoUses = 0;
  for (double y = -1.2; y <= 1.7; y += 0.37) {
    SectionMemo memo;
    double lowest = HUGE_VAL;
    for (double x = -1.3; x <= 5.3; x += 0.29) {
      const LowestPoint plain = move.lowestPoint(x, y);
      const LowestPoint memoised = move.lowestPoint(x, y, &memo, lowest);
      memoUses += memo.owner != nullptr;
      if (plain.hit && plain.z < lowest) {
        ++hits;
        ASSERT_TRUE(memoised.hit) << x << " " << y;
        EXPECT_EQ(memoised.z, plain.z) << x << " " << y;
        EXPECT_EQ(memoised.normal.z, plain.normal.z) << x << " " << y;
        lowest = plain.z;
      } else {
        EXPECT_TRUE(!memoised.hit || memoised.z == plain.z) << x << " " << y;
      }
    }
  }
  EXPECT_GT(hits, 20);
  EXPECT_GT(memoUses, 100);  // the memo given was the one the ball's segment used
}

}  // namespace
}  // namespace scallop
