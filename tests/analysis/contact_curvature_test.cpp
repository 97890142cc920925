// The effective radius at the contact (analysis/contact_curvature): its exact cases
// (ball, seed 000 Eq. (9) for a bull at lead only, the corner arc at tilt only) and,
// where it is an approximation, its measured difference from the exact procedure
// (analysis/pass_section) for bull and barrel cutters.
#include "analysis/contact_curvature.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "analysis/pass_section.h"
#include "analysis/simulated_interval.h"
#include "base/constants.h"
#include "sweep/cutter_profile.h"
#include "sweep/cutter_shapes.h"
#include "sweep/raster.h"
#include "tests/sweep/profile_cases.h"

namespace scallop {
namespace {

struct Posture {
  double leadDeg, tiltDeg;
};

TEST(ContactCurvature, BallIsItsRadiusInAnyPosture) {
  for (double lead : {0.0, 10.0, -30.0})
    for (double tilt : {0.0, 20.0}) {
      const ProcedureResult r =
          effectiveRadiusAtContact(Cutter::make(CutterType::Ball, 3), lead, tilt);
      ASSERT_TRUE(r.applicable) << r.reason;
      EXPECT_DOUBLE_EQ(r.value, 3);
    }
}

TEST(ContactCurvature, BullAtLeadOnlyIsRedonnetsEq9) {
  for (double lead : {1.0, 5.0, 10.0, 45.0, -10.0}) {
    const ProcedureResult got =
        effectiveRadiusAtContact(Cutter::make(CutterType::Bull, 3, 1), lead, 0);
    const ProcedureResult want = effectiveRadiusRedonnet(3, 1, lead);
    ASSERT_TRUE(got.applicable && want.applicable);
    EXPECT_NEAR(got.value, want.value, 1e-12 * want.value) << lead;
  }
}

// Tilt only: the section is the corner arc itself, R_eff = r, and the closed form
// is then exact while the scallop stays on the arc (pass_section_test checks the
// exact side).
TEST(ContactCurvature, BullAtTiltOnlyIsItsCornerArcAndExact) {
  const Cutter bull = Cutter::make(CutterType::Bull, 4, 1.5);
  const ProcedureResult r = effectiveRadiusAtContact(bull, 0, 30);
  ASSERT_TRUE(r.applicable);
  EXPECT_NEAR(r.value, 1.5, 1e-12);
  const double h = 0.1;  // below 1.5 (1 - cos 30 deg) = 0.2
  EXPECT_NEAR(halfIntervalEffectiveRadius(bull, 0, 30, h).value,
              halfIntervalExact(bull, 0, 30, h).value, 1e-9);
}

TEST(ContactCurvature, CornersLinesAndRingsAreNotApplicable) {
  EXPECT_FALSE(effectiveRadiusAtContact(Cutter::make(CutterType::Flat, 3), 10, 0).applicable);
  EXPECT_FALSE(effectiveRadiusAtContact(Cutter::make(CutterType::Flat, 3), 0, 0).applicable);
  EXPECT_FALSE(effectiveRadiusAtContact(Cutter::make(CutterType::Bull, 3, 1), 0, 0).applicable);
  EXPECT_FALSE(effectiveRadiusAtContact(Cutter::make(CutterType::Ball, 3), 90, 0).applicable);
}

// With lead and tilt the osculating circle is an approximation of the bull's section:
// its L/2 against the exact one, measured (see docs/validation.md).
TEST(ContactCurvature, BullWithLeadAndTiltIsCloseToExact) {
  struct Case {
    double lead, tilt, h, boundMm;  // bound: the measured difference, rounded up
  };
  for (const Case& c :
       {Case{5, 5, 0.01, 1.8e-3}, Case{10, 20, 0.01, 1.2e-3}, Case{10, 20, 0.05, 1.3e-2}}) {
    const Cutter bull = Cutter::make(CutterType::Bull, 3, 1);
    const ProcedureResult approx = halfIntervalEffectiveRadius(bull, c.lead, c.tilt, c.h);
    const ProcedureResult exact = halfIntervalExact(bull, c.lead, c.tilt, c.h);
    ASSERT_TRUE(approx.applicable && exact.applicable);
    std::printf("bull 3/1 lead %g tilt %g h %g: L/2 effective radius %.6f, exact %.6f mm\n", c.lead,
                c.tilt, c.h, approx.value, exact.value);
    EXPECT_NEAR(approx.value, exact.value, c.boundMm);
  }
}

// A barrel (circle-segment) cutter for the tests, from its definition: in the (rho, s)
// half-plane a line from the tip (0, 0) to P1, the form arc of radius Rf = 250 mm
// centred at (-245, 15) (across the axis) from P1 to P2 = (5, 15), whose normals span
// -3..0 deg from +rho, the flank rho = 5 up to s = 30 and the cap. Its support map:
// the best of the profile's vertices and the arc point whose normal is the direction's
// (when it lies on the arc), turned about the axis.
constexpr double kFormRadius = test::kBarrelFormRadius;
constexpr double kFormCentreRho = test::kBarrelFormCentreRho,
                 kFormCentreS = test::kBarrelFormCentreS;

Vec3 barrelSupport(const Vec3& axis, const Vec3& dir) {
  const double along = dot(dir, axis);
  Vec3 radial = dir - axis * along;
  double across = length(radial);
  Vec3 e = across > 1e-300 ? radial / across : normalize(cross(axis, Vec3{0, 1, 0}));
  double p1Rho = 0, p1S = 0;
  test::barrelP1(&p1Rho, &p1S);
  const double vertices[][2] = {{0, 0}, {p1Rho, p1S}, {5, 15}, {5, 30}, {0, 30}};
  double bestRho = 0, bestS = 0, best = -HUGE_VAL;
  auto consider = [&](double rho, double s) {
    if (across * rho + along * s > best) best = across * rho + along * s, bestRho = rho, bestS = s;
  };
  for (const auto& v : vertices) consider(v[0], v[1]);
  const double angle = std::atan2(along, across);
  if (angle >= -degToRad(test::kBarrelFormSpanDeg) && angle <= 0)
    consider(kFormCentreRho + kFormRadius * std::cos(angle),
             kFormCentreS + kFormRadius * std::sin(angle));
  return e * bestRho + axis * bestS;
}

// R_eff of contact_curvature.h for the form arc, written out for this barrel.
double barrelEffectiveRadius(const Vec3& a) {
  const double sinPsi = std::hypot(a.x, a.y), sin2Beta = a.y * a.y / (sinPsi * sinPsi);
  return kFormRadius * sin2Beta + (kFormCentreRho / sinPsi + kFormRadius) * (1 - sin2Beta);
}

// A barrel's side on the plane at the tilt that puts the contact on the form arc
// leaves the form arc's profile (exact); with a lead too, or with the feed along the
// meridian (lead only), the osculating circle is an approximation: measured here.
TEST(ContactCurvature, BarrelFormArcAgainstTheExactSection) {
  struct Case {
    double lead, tilt, h, boundMm;  // bound: the measured difference, rounded up
  };
  for (const Case& c : {Case{0, 88.5, 0.005, 1e-9}, Case{0, 88.5, 0.05, 1e-9},
                        Case{20, 88, 0.005, 1e-8}, Case{88.5, 0, 0.005, 2e-6}}) {
    const Vec3 a = leadTiltAxis(Vec3{1, 0, 0}, c.lead, c.tilt);
    const PassSection section([a](const Vec3& d) { return barrelSupport(a, d); }, 0);
    Enclosure width;
    ASSERT_TRUE(section.stepOver(c.h, &width));
    EXPECT_LE(width.width(), 2e-9);
    const double rEff = barrelEffectiveRadius(a);
    const ProcedureResult approx = circularHalfInterval("barrel", {true, rEff, {}}, c.h, 1e3);
    ASSERT_TRUE(approx.applicable) << approx.reason;
    std::printf(
        "barrel Rf 250 lead %g tilt %g h %g: R_eff %.6f mm, L/2 effective radius %.9f, "
        "exact %.9f mm\n",
        c.lead, c.tilt, c.h, rEff, approx.value, 0.5 * width.mid());
    EXPECT_NEAR(approx.value, 0.5 * width.mid(), c.boundMm);
  }
}

// The same barrel as a cutter of the general kernel (sweep/cutter_profile.h,
// test::barrelCutter): its contact arc found on the profile and its exact section by its
// own support map agree with the test's own barrel above, and so does the simulated pass
// of it.
TEST(ContactCurvature, BarrelCutterOfTheGeneralKernelAgrees) {
  const Cutter barrel = test::barrelCutter();
  for (const Posture& p : {Posture{0, 88.5}, Posture{20, 88}, Posture{88.5, 0}}) {
    const Vec3 a = leadTiltAxis(Vec3{1, 0, 0}, p.leadDeg, p.tiltDeg);
    const ProcedureResult rEff = effectiveRadiusAtContact(barrel, p.leadDeg, p.tiltDeg);
    ASSERT_TRUE(rEff.applicable) << rEff.reason;
    EXPECT_NEAR(rEff.value, barrelEffectiveRadius(a), 1e-9 * rEff.value);
    const PassSection own([a](const Vec3& d) { return barrelSupport(a, d); }, 0);
    Enclosure width;
    ASSERT_TRUE(own.stepOver(0.005, &width));
    const ProcedureResult exact = halfIntervalExact(barrel, p.leadDeg, p.tiltDeg, 0.005);
    ASSERT_TRUE(exact.applicable) << exact.reason;
    EXPECT_NEAR(exact.value, 0.5 * width.mid(), 1e-9);
    // The simulated pass (a swept move of this cutter, ray-cast) stays on or above its
    // floor, the plane through the cutter's lowest point, and touches it.
    const SimulatedPass pass(barrel, p.leadDeg, p.tiltDeg);
    EXPECT_NEAR(pass.heightAboveFloor(pass.floorPositionMm()), 0, 1e-9);
    const ScallopProfile section = pass.profile(-pass.reachMinusMm(), pass.reachPlusMm(), 0.05);
    EXPECT_GE(*std::min_element(section.height.begin(), section.height.end()), -1e-9);
    const SideIntervals sides = pass.halfIntervals(0.005);
    ASSERT_TRUE(sides.reachable) << sides.reason;
    EXPECT_NEAR(sides.halfIntervalMm(), exact.value, 1e-9);
  }
}

}  // namespace
}  // namespace scallop
