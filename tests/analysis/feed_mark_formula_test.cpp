// The feed-mark closed forms (analysis/feed_mark_formula.h), checked against the
// geometry they come from: the circle's chord, the threshold's defining equality, the
// regimes' continuity at the threshold, and where they do not apply.
#include "analysis/feed_mark_formula.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "base/constants.h"

namespace scallop {
namespace {

Cutter withRunout(Cutter c, double runout, int flutes = 2) {
  c.teeth = CutterTeeth::make(flutes, 0, runout, 0, c.radius);
  return c;
}

TEST(FeedMarkFormula, CircleHeightOverItsChord) {
  for (double rho : {0.5, 1.0, 3.0}) {
    for (double chord : {0.01, 0.1, 0.5}) {
      const double h = circularMarkHeight(rho, chord);
      // The chord's end lies on the circle: (chord/2)^2 + (rho - h)^2 = rho^2.
      EXPECT_NEAR(0.25 * chord * chord + (rho - h) * (rho - h), rho * rho, 1e-14);
      // Against the parabola: h = c^2/(8 rho) + c^4/(128 rho^3) + c^6/(1024 rho^5) + ...,
      // a series of positive terms each at most c^2 / (8 rho^2) <= 1/8 of the one before.
      // h = rho - sqrt(...) cancels: its rounding is a few ulps of rho.
      const double p = chord * chord / (8 * rho),
                   rounding = 4 * rho * std::numeric_limits<double>::epsilon();
      const double rest = h - p - std::pow(chord, 4) / (128 * std::pow(rho, 3));
      EXPECT_GE(rest, -rounding);
      EXPECT_LE(rest, 2 * std::pow(chord, 6) / (1024 * std::pow(rho, 5)) + rounding);
    }
  }
}

TEST(FeedMarkFormula, ThresholdSatisfiesItsEquality) {
  for (double lead : {5.0, 15.0, 45.0, -15.0}) {
    for (double fz : {0.02, 0.1, 0.3}) {
      const double rho = 3, x = runoutThreshold(rho, lead, fz);
      const double l = std::fabs(lead) * kPi / 180;
      const double dz = 2 * x * std::sin(l), sigma = 2 * x * std::cos(l);
      EXPECT_GT(x, 0);
      EXPECT_NEAR(dz, (fz - sigma) * (fz + sigma) / (2 * rho), 1e-15) << lead << " " << fz;
      // rho* / (fz^2 / (4 rho sin(lead))) = (sqrt(1 + e) - 1) / (e / 2) with
      // e = fz^2 cos^2 / (rho^2 sin^2): 1 - e/4 + e^2/8 - ..., alternating for e < 1.
      const double e = std::pow(fz * std::cos(l) / (rho * std::sin(l)), 2);
      const double ratio = x / (fz * fz / (4 * rho * std::sin(l)));
      if (e < 0.5) {
        EXPECT_LE(1 - ratio, e / 4 + 1e-12) << lead << " " << fz;
        EXPECT_GE(1 - ratio, e / 4 - e * e / 8 - 1e-12) << lead << " " << fz;
      }
    }
  }
}

TEST(FeedMarkFormula, BallAndBullWithLead) {
  const FeedMarkPrediction ball = predictFeedMarks(Cutter::make(CutterType::Ball, 3), 15, 0, 0.1);
  ASSERT_TRUE(ball.applicable) << ball.reason;
  EXPECT_EQ(ball.profileRadiusMm, 3);
  EXPECT_EQ(ball.spacingMm, 0.1);
  EXPECT_EQ(ball.heightMm, circularMarkHeight(3, 0.1));
  EXPECT_NEAR(ball.heightParabolaMm, 0.01 / 24, 1e-18);
  EXPECT_TRUE(ball.hasRunoutThreshold);
  EXPECT_EQ(ball.runoutThresholdMm, runoutThreshold(3, 15, 0.1));
  EXPECT_EQ(ball.regime, "no runout");
  const FeedMarkPrediction bull =
      predictFeedMarks(Cutter::make(CutterType::Bull, 5, 1), 10, 0, 0.1);
  ASSERT_TRUE(bull.applicable) << bull.reason;
  EXPECT_EQ(bull.profileRadiusMm, 1);  // the corner radius
  EXPECT_EQ(bull.heightMm, circularMarkHeight(1, 0.1));
  Cutter four = Cutter::make(CutterType::Ball, 3);
  four.teeth.flutes = 4;
  EXPECT_FALSE(predictFeedMarks(four, 15, 0, 0.1).hasRunoutThreshold);
}

TEST(FeedMarkFormula, RunoutRegimesMeetAtTheThreshold) {
  const Cutter ball = Cutter::make(CutterType::Ball, 3);
  const double fz = 0.1, star = runoutThreshold(3, 15, fz);
  const FeedMarkPrediction below = predictFeedMarks(withRunout(ball, star * (1 - 1e-9)), 15, 0, fz);
  const FeedMarkPrediction above = predictFeedMarks(withRunout(ball, star * (1 + 1e-9)), 15, 0, fz);
  EXPECT_EQ(below.regime, "both teeth cut");
  EXPECT_EQ(below.spacingMm, fz);
  EXPECT_EQ(above.regime, "one tooth cuts");
  EXPECT_EQ(above.spacingMm, 2 * fz);
  EXPECT_EQ(above.heightMm, circularMarkHeight(3, 2 * fz));
  // At the threshold the higher tooth's arc passes through the lower tooth's cusp:
  // both regimes give the parabolic cusp of arcs 2 fz apart, (2 fz)^2 / (8 rho).
  EXPECT_NEAR(below.heightMm, 4 * fz * fz / 24, 1e-11);
  EXPECT_NEAR(above.heightParabolaMm, 4 * fz * fz / 24, 1e-18);
  // Without runout the parabolic marks are fz^2 / (8 rho); a small runout deepens them.
  const FeedMarkPrediction small = predictFeedMarks(withRunout(ball, 1e-4), 15, 0, fz);
  EXPECT_GT(small.heightMm, fz * fz / 24);
  EXPECT_LT(small.heightMm, below.heightMm);
}

TEST(FeedMarkFormula, WhereItDoesNotApply) {
  const Cutter ball = Cutter::make(CutterType::Ball, 3);
  EXPECT_FALSE(predictFeedMarks(Cutter::make(CutterType::Flat, 3), 15, 0, 0.1).applicable);
  EXPECT_FALSE(predictFeedMarks(ball, 0, 0, 0.1).applicable);
  EXPECT_FALSE(predictFeedMarks(ball, 15, 5, 0.1).applicable);
  EXPECT_FALSE(predictFeedMarks(ball, 15, 0, 6).applicable);  // fz >= 2 rho_f
  EXPECT_FALSE(predictFeedMarks(withRunout(ball, 1e-3, 3), 15, 0, 0.1).applicable);
  Cutter phased = withRunout(ball, 1e-3);
  phased.teeth.runoutPhaseDeg = 90;
  EXPECT_FALSE(predictFeedMarks(phased, 15, 0, 0.1).applicable);
  phased.teeth.runoutPhaseDeg = 180;
  EXPECT_TRUE(predictFeedMarks(phased, 15, 0, 0.1).applicable);
  for (const auto& p : {predictFeedMarks(ball, 0, 0, 0.1), predictFeedMarks(ball, 15, 5, 0.1)})
    EXPECT_FALSE(p.reason.empty());
}

}  // namespace
}  // namespace scallop
