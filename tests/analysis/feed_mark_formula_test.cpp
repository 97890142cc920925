// The feed-mark closed forms (analysis/feed_mark_formula.h), checked against the
// geometry they come from: the circle's chord, the threshold's defining equality, the
// regimes' continuity at the threshold, and where they do not apply.
#include "analysis/feed_mark_formula.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "base/constants.h"
#include "sweep/cutter_shapes.h"

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
      const double l = degToRad(std::fabs(lead));
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
  // The parabolas: at rho* the higher tooth's arc passes through the lower tooth's cusp,
  // so both sides of it give the parabolic cusp of arcs 2 fz apart, (2 fz)^2 / (8 rho).
  const FeedMarkPrediction below = predictFeedMarks(withRunout(ball, star * (1 - 1e-9)), 15, 0, fz);
  const FeedMarkPrediction above = predictFeedMarks(withRunout(ball, star * (1 + 1e-9)), 15, 0, fz);
  EXPECT_NEAR(below.heightParabolaMm, 4 * fz * fz / 24, 1e-11);
  EXPECT_NEAR(above.heightParabolaMm, 4 * fz * fz / 24, 1e-11);
  // The circles: their threshold lies near rho* (the parabola is their osculating
  // approximation, fz^2 / rho_f^2 ~ 1e-3 apart here); found by bisection on the regime,
  // the heights meet there at the circles' cusp of arcs 2 fz apart.
  double lo = 0.5 * star, hi = 2 * star;
  ASSERT_EQ(predictFeedMarks(withRunout(ball, lo), 15, 0, fz).regime, "both teeth cut");
  ASSERT_EQ(predictFeedMarks(withRunout(ball, hi), 15, 0, fz).regime, "one tooth cuts");
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (predictFeedMarks(withRunout(ball, mid), 15, 0, fz).regime == "both teeth cut" ? lo : hi) = mid;
  }
  EXPECT_NEAR(lo / star, 1, 1e-2);
  const FeedMarkPrediction both = predictFeedMarks(withRunout(ball, lo), 15, 0, fz);
  const FeedMarkPrediction one = predictFeedMarks(withRunout(ball, hi), 15, 0, fz);
  // At the threshold the higher tooth's valley closes: the marks it leaves just below
  // are too shallow to count (spacingMm counts valleys as measureFeedMarks does), well
  // below it they are fz apart.
  EXPECT_EQ(both.cuttingTeeth.size(), 2u);
  EXPECT_LT(both.valleyDepthsMm[1], 1e-12);
  EXPECT_EQ(both.spacingMm, 2 * fz);
  EXPECT_EQ(predictFeedMarks(withRunout(ball, 0.5 * star), 15, 0, fz).spacingMm, fz);
  EXPECT_EQ(one.spacingMm, 2 * fz);
  EXPECT_EQ(one.cuttingTeeth, std::vector<int>{0});  // phase 0 pushes tooth 0 out
  EXPECT_NEAR(both.heightMm, circularMarkHeight(3, 2 * fz), 1e-12);
  EXPECT_NEAR(one.heightMm, circularMarkHeight(3, 2 * fz), 1e-15);
  // Without runout the marks are the circle of chord fz; a small runout deepens them.
  const FeedMarkPrediction small = predictFeedMarks(withRunout(ball, 1e-4), 15, 0, fz);
  EXPECT_GT(small.heightMm, circularMarkHeight(3, fz));
  EXPECT_LT(small.heightMm, both.heightMm);
}

// The arcs' positions and depths against the geometry they come from: tooth k's edge
// point at the contact, moved by its offsets and the runout's share, for teeth of any
// pitch, helix and runout phase (the formula is written from the move's frame, this
// from the cutter's: r and a explicitly).
TEST(FeedMarkFormula, ToothMarksAreTheEdgesMovedByTheirErrors) {
  CutterTeeth teeth = CutterTeeth::make(3, 20, 0.002, 75, 3);
  teeth.editToothAnglesDeg() = {0, 110, 230};
  teeth.editToothOffsets() = {{0.001, -0.0005}, {0, 0.0008}, {-0.0004, 0}};
  const double lead = degToRad(25), fz = 0.07, hc = 3 * (1 - std::cos(lead));
  const std::vector<ToothMark> marks = toothMarks(teeth, 3, hc, lead, fz);
  ASSERT_EQ(marks.size(), 3u);
  const double rx = std::cos(lead), rz = -std::sin(lead), ax = std::sin(lead), az = std::cos(lead);
  for (int k = 0; k < 3; ++k) {
    const double psi = degToRad(teeth.toothAnglesDeg()[size_t(k)]);
    // At the moment tooth k's edge at hc faces the contact, the runout vector's angle
    // from the contact direction is (runout phase) - (psi_k + hc tan(beta) / R).
    const double rel = degToRad(75) - (psi + hc * std::tan(degToRad(20)) / 3);
    const double q = 0.002 * std::cos(rel) + teeth.toothOffsets()[size_t(k)].radial;
    const double da = teeth.toothOffsets()[size_t(k)].axial;
    const double x = q * rx - da * ax, z = q * rz - da * az;  // the edge's displacement
    EXPECT_NEAR(marks[size_t(k)].positionMm, 3 * fz * psi / (2 * kPi) + x, 1e-15) << k;
    EXPECT_NEAR(marks[size_t(k)].lowerMm, -z, 1e-15) << k;
  }
}

// The envelope against a dense sampling of the lowest arc.
TEST(FeedMarkFormula, EnvelopeOfArcsAgainstSampling) {
  const double rho = 2, period = 0.3;
  const std::vector<ToothMark> marks = {{0.0, 0.0}, {0.09, 0.0021}, {0.21, -0.0007}};
  const MarkEnvelope e = markEnvelope(marks, period, rho);
  ASSERT_TRUE(e.valid);
  double top = -HUGE_VAL, bottom = HUGE_VAL;
  std::vector<bool> seen(3, false);
  const int n = 300000;
  for (int i = 0; i < n; ++i) {
    const double x = period * i / n;
    double z = HUGE_VAL;
    int who = -1;
    for (int k = 0; k < 3; ++k)
      for (int copy = -1; copy <= 1; ++copy) {
        const double u = x - marks[size_t(k)].positionMm - copy * period;
        const double v = -marks[size_t(k)].lowerMm + rho - std::sqrt(rho * rho - u * u);
        if (v < z) z = v, who = k;
      }
    seen[size_t(who)] = true;
    top = std::max(top, z), bottom = std::min(bottom, z);
  }
  // Sampling misses a cusp by at most its slope (< 0.2 / rho) times half a step.
  EXPECT_LE(top - bottom, e.peakToValleyMm + 1e-15);
  EXPECT_GE(top - bottom, e.peakToValleyMm - 0.1 * period / n);
  std::vector<int> cutting;
  for (int k = 0; k < 3; ++k)
    if (seen[size_t(k)]) cutting.push_back(k);
  EXPECT_EQ(e.cuttingTeeth, cutting);
  // Here tooth 1 lies 2.1 um deep between the others: the three cut.
  EXPECT_EQ(cutting.size(), 3u);
  // Arcs 2 rho apart do not meet.
  EXPECT_FALSE(markEnvelope({{0, 0}}, 2 * rho, rho).valid);
}

TEST(FeedMarkFormula, WhereItDoesNotApply) {
  const Cutter ball = Cutter::make(CutterType::Ball, 3);
  EXPECT_FALSE(predictFeedMarks(Cutter::make(CutterType::Flat, 3), 15, 0, 0.1).applicable);
  EXPECT_FALSE(predictFeedMarks(ball, 0, 0, 0.1).applicable);
  EXPECT_FALSE(predictFeedMarks(ball, 15, 5, 0.1).applicable);
  EXPECT_FALSE(predictFeedMarks(ball, 15, 0, 6).applicable);  // fz >= 2 rho_f
  // A raked edge leaves sheared arcs: said, not predicted as if it were not raked; a
  // rake of zero changes nothing.
  Cutter raked = ball;
  raked.teeth.editToothRakes() = {{5, 0}, {0, 0}};
  const FeedMarkPrediction r = predictFeedMarks(raked, 15, 0, 0.1);
  EXPECT_FALSE(r.applicable);
  EXPECT_NE(r.reason.find("raked edge"), std::string::npos) << r.reason;
  raked.teeth.editToothRakes() = {{0, 0}, {0, 0}};
  EXPECT_TRUE(predictFeedMarks(raked, 15, 0, 0.1).applicable);
  // A leaning bull touches with its corner arc; a cone with its sharp point (or, at its
  // half-angle's complement, along its flank): no arc.
  EXPECT_TRUE(predictFeedMarks(Cutter::make(CutterType::Bull, 5, 1), 3, 0, 0.1).applicable);
  ConeShape vbit;
  vbit.angleDeg = 90, vbit.diameter = 6, vbit.fluteLength = 10;
  const Cutter cone = cutterOfChain(CutterType::Cone, coneChain(vbit, "tool"), "tool");
  for (const double lead : {15.0, 45.0}) {
    const FeedMarkPrediction p = predictFeedMarks(cone, lead, 0, 0.1);
    EXPECT_FALSE(p.applicable) << lead;
    EXPECT_NE(p.reason.find("not on an arc"), std::string::npos) << p.reason;
  }
  // Runout of any phase and flute count is covered now.
  EXPECT_TRUE(predictFeedMarks(withRunout(ball, 1e-3, 3), 15, 0, 0.1).applicable);
  Cutter phased = withRunout(ball, 1e-3);
  phased.teeth.runoutPhaseDeg = 90;
  EXPECT_TRUE(predictFeedMarks(phased, 15, 0, 0.1).applicable);
  for (const auto& p : {predictFeedMarks(ball, 0, 0, 0.1), predictFeedMarks(ball, 15, 5, 0.1)})
    EXPECT_FALSE(p.reason.empty());
}

}  // namespace
}  // namespace scallop
