// APT's 7-parameter cutter (sweep/apt_cutter.h) in every case CONVENTIONS.md "Cutter
// shapes" describes: end mills become ball/flat/bull, a tapered ball's d is
// 2r(1 - sin b)/cos b and its chain is the taper_ball's, V-bits and bottom cones, sharp
// corners, corner centres at any consistent e, and each inconsistent value named.
#include "sweep/apt_cutter.h"

#include <gtest/gtest.h>

#include <cmath>

#include "base/constants.h"
#include "sweep/cutter_shapes.h"
#include "tests/sweep/profile_chain_check.h"

namespace scallop {
namespace {

constexpr double kDeg = kRadPerDeg;

void expectSameChain(const std::vector<ProfileSegment>& a, const std::vector<ProfileSegment>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR(a[i].rho0, b[i].rho0, 1e-12) << i;
    EXPECT_NEAR(a[i].s0, b[i].s0, 1e-12) << i;
    EXPECT_NEAR(a[i].rho1, b[i].rho1, 1e-12) << i;
    EXPECT_NEAR(a[i].s1, b[i].s1, 1e-12) << i;
    EXPECT_EQ(a[i].arcRadius, b[i].arcRadius) << i;
    EXPECT_NEAR(a[i].centreRho, b[i].centreRho, 1e-12) << i;
    EXPECT_NEAR(a[i].centreS, b[i].centreS, 1e-12) << i;
  }
}

TEST(AptCutter, EndMillsKeepTheirTypes) {
  const Cutter ball = aptCutter({6, 3, 0, 3, 0, 0, 20}, "tool");
  EXPECT_EQ(ball.type, CutterType::Ball);
  EXPECT_EQ(ball.radius, 3);
  EXPECT_EQ(ball.fluteLength, 20);
  EXPECT_FALSE(ball.general());
  const Cutter flat = aptCutter({6, 0, 0, 0, 0, 0, 20}, "tool");
  EXPECT_EQ(flat.type, CutterType::Flat);
  const Cutter flatAtCorner = aptCutter({6, 0, 3, 0, 0, 0, 20}, "tool");
  EXPECT_EQ(flatAtCorner.type, CutterType::Flat);
  const Cutter bull = aptCutter({6, 1, 2, 1, 0, 0, 20}, "tool");
  EXPECT_EQ(bull.type, CutterType::Bull);
  EXPECT_EQ(bull.cornerRadius, 1);
  // Their chains are the end mills' profiles too.
  const auto chain = aptCutterChain({6, 1, 2, 1, 0, 0, 20}, "tool");
  expectValidChain(chain, true);
  ASSERT_EQ(chain.size(), 3u);
  EXPECT_EQ(chain[0].rho1, 2);
  EXPECT_EQ(chain[1].centreRho, 2);
  EXPECT_EQ(chain[1].centreS, 1);
  EXPECT_EQ(chain[2].rho0, 3);
  EXPECT_EQ(chain[2].s0, 1);
}

TEST(AptCutter, TaperedBallIsTheTaperBallChain) {
  const double r = 1.5, b = 7;
  const double d = 2 * r * (1 - std::sin(b * kDeg)) / std::cos(b * kDeg);
  const auto apt = aptCutterChain({d, r, 0, r, 0, b, 25}, "tool");
  expectValidChain(apt, true);
  TaperBallShape shape;
  shape.tipRadius = r, shape.taperDeg = b, shape.fluteLength = 25;
  expectSameChain(apt, taperBallChain(shape, "tool"));
  // A d that does not fit r and b puts the corner off the axis: e = 0 is then named.
  expectRejectedNaming([&] { aptCutterChain({d + 0.01, r, 0, r, 0, b, 25}, "tool"); }, "tool.e");
}

TEST(AptCutter, TaperedBullIsTheTaperBullChain) {
  const double d = 6, r = 1, b = 10;
  const double e = d / 2 - r * (1 - std::sin(b * kDeg)) / std::cos(b * kDeg);
  TaperBullShape shape;
  shape.tipDiameter = d, shape.cornerRadius = r, shape.taperDeg = b, shape.fluteLength = 20;
  expectSameChain(aptCutterChain({d, r, e, r, 0, b, 20}, "tool"), taperBullChain(shape, "tool"));
}

TEST(AptCutter, VBitAndBottomConesAreTheConeChain) {
  // CONVENTIONS.md's example: a 120-degree V-bit with a sharp tip.
  const double d = 6, h = 10;
  const auto apt = aptCutterChain({d, 0, 0, 0, 30, 0, h}, "tool");
  expectValidChain(apt, false);
  ConeShape cone;
  cone.angleDeg = 120, cone.diameter = d, cone.fluteLength = h;
  expectSameChain(apt, coneChain(cone, "tool"));
  EXPECT_EQ(aptCutter({d, 0, 0, 0, 30, 0, h}, "tool").type, CutterType::Profile);
  // The sharp corner given as e, f at the corner point is as good as 0, 0.
  expectSameChain(aptCutterChain({d, 0, 3, 3 * std::tan(30 * kDeg), 30, 0, h}, "tool"), apt);
  // A bottom cone with a rounded corner: tangent to the cone and the flank.
  // n2 . (C - P) = r puts the centre at e = 2; n1 . C = r then gives f = 2 / cos 30.
  const auto rounded = aptCutterChain({6, 1, 2, 2 / std::cos(30 * kDeg), 30, 0, 10}, "tool");
  expectValidChain(rounded, true);
}

TEST(AptCutter, CornerCentreAcrossTheBottomCone) {
  // alpha > 0 with the corner's centre on the axis: a ball nose on a cone, the bottom
  // line a short cone from the tip to the ball.
  const double r = 2, a = 20 * kDeg;
  // The bottom line at a from the tip is at r from (0, f) when f = r / cos a; the flank
  // (b = 0) at r from the axis, so d = 2 r.
  const double f = r / std::cos(a);
  const auto chain = aptCutterChain({2 * r, r, 0, f, 20, 0, 10}, "tool");
  expectValidChain(chain, true);
  ASSERT_EQ(chain.size(), 3u);
  EXPECT_NEAR(chain[0].rho1, r * std::sin(a), 1e-12);
  EXPECT_NEAR(chain[1].centreS, f, 1e-12);
}

TEST(AptCutter, InconsistentValuesAreNamed) {
  expectRejectedNaming([] { aptCutterChain({6, 1, 2.1, 1, 0, 0, 20}, "tool"); }, "tool.e");
  expectRejectedNaming([] { aptCutterChain({6, 1, 2, 1.01, 0, 0, 20}, "tool"); }, "tool.f");
  expectRejectedNaming([] { aptCutterChain({6, 0, 1, 0, 0, 0, 20}, "tool"); }, "tool.e");
  expectRejectedNaming([] { aptCutterChain({6, 1, 2, 1, 60, 30, 20}, "tool"); }, "tool.b");
  expectRejectedNaming([] { aptCutterChain({6, 1, 2, 1, -5, 0, 20}, "tool"); }, "tool.a");
  expectRejectedNaming([] { aptCutterChain({0, 1, 2, 1, 0, 0, 20}, "tool"); }, "tool.d");
  expectRejectedNaming([] { aptCutterChain({6, -1, 2, 1, 0, 0, 20}, "tool"); }, "tool.r");
  expectRejectedNaming([] { aptCutterChain({6, 1, 2, 1, 0, 0, 0.5}, "tool"); }, "tool.h");
  // A corner larger than the tool: its centre across the axis.
  expectRejectedNaming([] { aptCutterChain({6, 4, -1, 4, 0, 0, 20}, "tool"); }, "tool.e");
  // Within 1e-6 mm is consistent.
  EXPECT_NO_THROW(aptCutterChain({6, 1, 2 + 5e-7, 1 - 5e-7, 0, 0, 20}, "tool"));
}

}  // namespace
}  // namespace scallop
