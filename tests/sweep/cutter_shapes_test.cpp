// The named cutter shapes (sweep/cutter_shapes.h): each chain against its closed form
// (tangent points, centres, radii, the widest point), checked to be a chain at all by
// a private check written from CutterProfile's contract (contiguous from the tip, arcs
// through both ends about their centre, turning only towards the solid), and every
// parameter error naming its key.
#include "sweep/cutter_shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "base/constants.h"
#include "base/input_error.h"
#include "tests/sweep/profile_chain_check.h"

namespace scallop {
namespace {

constexpr double kDeg = kRadPerDeg;

TEST(CutterShapes, TaperBallTangentPointAndFlank) {
  TaperBallShape shape;
  shape.tipRadius = 2, shape.taperDeg = 5, shape.fluteLength = 30;
  const auto chain = taperBallChain(shape, "tool");
  expectValidChain(chain, /*smooth=*/true);
  ASSERT_EQ(chain.size(), 2u);
  const double b = 5 * kDeg;
  // The ball about (0, r) meets the cone at (r cos b, r (1 - sin b)).
  EXPECT_EQ(chain[0].arcRadius, 2);
  EXPECT_EQ(chain[0].centreRho, 0);
  EXPECT_EQ(chain[0].centreS, 2);
  EXPECT_NEAR(chain[0].rho1, 2 * std::cos(b), 1e-12);
  EXPECT_NEAR(chain[0].s1, 2 * (1 - std::sin(b)), 1e-12);
  // The flank rises at b from the axis to the flute top.
  EXPECT_NEAR((chain[1].rho1 - chain[1].rho0) / (chain[1].s1 - chain[1].s0), std::tan(b), 1e-12);
  EXPECT_EQ(chain[1].s1, 30);

  // The flute diameter form: the same chain as the length that gives that diameter.
  TaperBallShape byDiameter = shape;
  byDiameter.fluteLength = 0;
  byDiameter.fluteDiameter = 2 * chain[1].rho1;
  const auto same = taperBallChain(byDiameter, "tool");
  ASSERT_EQ(same.size(), 2u);
  EXPECT_NEAR(same[1].s1, 30, 1e-9);
}

TEST(CutterShapes, TaperBullCornerTangentToBottomAndFlank) {
  TaperBullShape shape;
  shape.tipDiameter = 6, shape.cornerRadius = 1, shape.taperDeg = 10, shape.fluteLength = 20;
  const auto chain = taperBullChain(shape, "tool");
  expectValidChain(chain, true);
  ASSERT_EQ(chain.size(), 3u);
  const double b = 10 * kDeg;
  const double e = 3 - (1 - std::sin(b)) / std::cos(b);
  EXPECT_NEAR(chain[0].rho1, e, 1e-12);  // the flat bottom ends where the corner starts
  EXPECT_EQ(chain[0].s1, 0);
  EXPECT_NEAR(chain[1].centreRho, e, 1e-12);
  EXPECT_EQ(chain[1].centreS, 1);
  // The flank, extended down, passes through (tip_diameter / 2, 0).
  const ProfileSegment& flank = chain[2];
  const double slope = (flank.rho1 - flank.rho0) / (flank.s1 - flank.s0);
  EXPECT_NEAR(slope, std::tan(b), 1e-12);
  EXPECT_NEAR(flank.rho0 - flank.s0 * slope, 3, 1e-12);
  // Without a corner radius: the sharp tapered end mill.
  shape.cornerRadius = 0;
  const auto sharp = taperBullChain(shape, "tool");
  expectValidChain(sharp, false);
  ASSERT_EQ(sharp.size(), 2u);
  EXPECT_EQ(sharp[0].rho1, 3);
}

TEST(CutterShapes, ConeVBitChamferAndDrillPoint) {
  ConeShape vbit;
  vbit.angleDeg = 90, vbit.diameter = 6, vbit.fluteLength = 10;
  const auto chain = coneChain(vbit, "tool");
  expectValidChain(chain, false);
  ASSERT_EQ(chain.size(), 2u);
  EXPECT_EQ(chain[0].rho0, 0);
  EXPECT_EQ(chain[0].s0, 0);  // a sharp point on the axis
  EXPECT_EQ(chain[0].rho1, 3);
  EXPECT_NEAR(chain[0].s1, 3, 1e-12);  // 90 degrees: as high as wide
  EXPECT_EQ(chain[1].s1, 10);

  ConeShape chamfer = vbit;
  chamfer.tipDiameter = 1;
  const auto flatTip = coneChain(chamfer, "tool");
  expectValidChain(flatTip, false);
  ASSERT_EQ(flatTip.size(), 3u);
  EXPECT_EQ(flatTip[0].rho1, 0.5);
  EXPECT_NEAR(flatTip[1].s1, 2.5, 1e-12);

  // A 118-degree drill point whose flute length is exactly the cone: no cylinder.
  ConeShape drill;
  drill.angleDeg = 118, drill.diameter = 8;
  drill.fluteLength = 4 / std::tan(59 * kDeg);
  const auto point = coneChain(drill, "tool");
  expectValidChain(point, false);
  EXPECT_EQ(point.size(), 1u);
}

TEST(CutterShapes, BarrelWidestPointAndCorner) {
  BarrelShape shape;
  shape.diameter = 12, shape.formRadius = 85, shape.tipRadius = 1, shape.fluteLength = 10;
  const auto chain = barrelChain(shape, "tool");
  expectValidChain(chain, true);
  ASSERT_EQ(chain.size(), 3u);
  const ProfileSegment& side = chain[2];
  // The side arc's centre is across the axis at the equator (half the flute length by
  // default), so its widest point is the diameter there.
  EXPECT_EQ(side.arcRadius, 85);
  EXPECT_NEAR(side.centreRho + 85, 6, 1e-12);
  EXPECT_EQ(side.centreS, 5);
  // The corner touches the bottom at (e, 0) and lies inside the side circle.
  const ProfileSegment& corner = chain[1];
  EXPECT_EQ(corner.centreS, 1);
  EXPECT_EQ(corner.rho0, chain[0].rho1);
  EXPECT_NEAR(std::hypot(corner.centreRho - side.centreRho, corner.centreS - side.centreS), 84,
              1e-9);
  shape.equatorHeight = 3;
  EXPECT_EQ(barrelChain(shape, "tool")[2].centreS, 3);
}

TEST(CutterShapes, OvalTipBallAndSideArc) {
  OvalShape shape;
  shape.diameter = 10, shape.formRadius = 30, shape.tipRadius = 2, shape.fluteLength = 12;
  const auto chain = ovalChain(shape, "tool");
  expectValidChain(chain, true);
  ASSERT_EQ(chain.size(), 2u);
  EXPECT_EQ(chain[0].centreRho, 0);
  EXPECT_EQ(chain[0].centreS, 2);
  const ProfileSegment& side = chain[1];
  EXPECT_NEAR(side.centreRho + 30, 5, 1e-12);
  EXPECT_NEAR(std::hypot(side.centreRho, side.centreS - 2), 28, 1e-9);
  EXPECT_EQ(side.s1, 12);
}

TEST(CutterShapes, TaperBarrelTangentAtTheReferenceDiameter) {
  TaperBarrelShape shape;
  shape.tipRadius = 2, shape.formRadius = 250, shape.taperDeg = 10;
  shape.referenceDiameter = 8, shape.fluteLength = 20;
  const auto chain = taperBarrelChain(shape, "tool");
  expectValidChain(chain, true);
  ASSERT_EQ(chain.size(), 2u);
  const ProfileSegment& side = chain[1];
  const double b = 10 * kDeg;
  // The side arc passes through diameter 8 where its outward normal is (cos b, -sin b),
  // i.e. its tangent makes b with the axis, and is tangent to the tip ball.
  const double refRho = side.centreRho + 250 * std::cos(b);
  const double refS = side.centreS - 250 * std::sin(b);
  EXPECT_NEAR(refRho, 4, 1e-9);
  EXPECT_GT(refS, side.s0);
  EXPECT_LT(refS, side.s1);
  EXPECT_NEAR(std::hypot(side.centreRho, side.centreS - 2), 248, 1e-9);
}

TEST(CutterShapes, LensTipArcCornerAndCylinder) {
  LensShape shape;
  shape.diameter = 10, shape.formRadius = 20, shape.cornerRadius = 1, shape.fluteLength = 15;
  const auto chain = lensChain(shape, "tool");
  expectValidChain(chain, true);
  ASSERT_EQ(chain.size(), 3u);
  EXPECT_EQ(chain[0].centreRho, 0);
  EXPECT_EQ(chain[0].centreS, 20);
  EXPECT_EQ(chain[1].centreRho, 4);
  EXPECT_NEAR(std::hypot(chain[1].centreRho, chain[1].centreS - 20), 19, 1e-9);
  EXPECT_EQ(chain[2].rho0, 5);
  EXPECT_EQ(chain[2].rho1, 5);
  EXPECT_EQ(chain[2].s1, 15);
}

// Each bad parameter is an InputError whose field names the key.
TEST(CutterShapes, ErrorsNameTheKey) {
  TaperBallShape tb;
  tb.tipRadius = 2, tb.taperDeg = 0, tb.fluteLength = 30;
  expectRejectedNaming([&] { taperBallChain(tb, "tool"); }, "tool.taper_deg");
  tb.taperDeg = 5, tb.fluteLength = 0.01;
  expectRejectedNaming([&] { taperBallChain(tb, "tool"); }, "tool.flute_length");
  tb.fluteLength = 30, tb.fluteDiameter = 8;
  expectRejectedNaming([&] { taperBallChain(tb, "tool"); }, "tool.flute_diameter");
  tb.tipRadius = -1;
  expectRejectedNaming([&] { taperBallChain(tb, "tools.3"); }, "tools.3.tip_radius");

  TaperBullShape tbu;
  tbu.tipDiameter = 2, tbu.cornerRadius = 1.5, tbu.taperDeg = 5, tbu.fluteLength = 10;
  expectRejectedNaming([&] { taperBullChain(tbu, "tool"); }, "tool.corner_radius");

  ConeShape cone;
  cone.angleDeg = 180, cone.diameter = 6, cone.fluteLength = 10;
  expectRejectedNaming([&] { coneChain(cone, "tool"); }, "tool.angle_deg");
  cone.angleDeg = 60, cone.tipDiameter = 6;
  expectRejectedNaming([&] { coneChain(cone, "tool"); }, "tool.tip_diameter");
  cone.tipDiameter = 0, cone.fluteLength = 1;
  expectRejectedNaming([&] { coneChain(cone, "tool"); }, "tool.flute_length");

  BarrelShape barrel;
  barrel.diameter = 12, barrel.formRadius = 5, barrel.fluteLength = 10;
  expectRejectedNaming([&] { barrelChain(barrel, "tool"); }, "tool.form_radius");
  barrel.formRadius = 85, barrel.tipRadius = 6;
  expectRejectedNaming([&] { barrelChain(barrel, "tool"); }, "tool.tip_radius");
  barrel.tipRadius = 1, barrel.equatorHeight = 11;
  expectRejectedNaming([&] { barrelChain(barrel, "tool"); }, "tool.equator_height");

  TaperBarrelShape taperBarrel;
  taperBarrel.tipRadius = 2, taperBarrel.formRadius = 1, taperBarrel.taperDeg = 10;
  taperBarrel.referenceDiameter = 8, taperBarrel.fluteLength = 20;
  expectRejectedNaming([&] { taperBarrelChain(taperBarrel, "tool"); }, "tool.form_radius");
  taperBarrel.formRadius = 250, taperBarrel.referenceDiameter = 3;
  expectRejectedNaming([&] { taperBarrelChain(taperBarrel, "tool"); }, "tool.reference_diameter");

  OvalShape oval;
  oval.diameter = 10, oval.formRadius = 30, oval.tipRadius = 5, oval.fluteLength = 12;
  expectRejectedNaming([&] { ovalChain(oval, "tool"); }, "tool.tip_radius");
  oval.tipRadius = 2, oval.fluteLength = 1;
  expectRejectedNaming([&] { ovalChain(oval, "tool"); }, "tool.flute_length");

  LensShape lens;
  lens.diameter = 10, lens.formRadius = 4, lens.fluteLength = 15;
  expectRejectedNaming([&] { lensChain(lens, "tool"); }, "tool.form_radius");
  lens.formRadius = 20, lens.cornerRadius = 5;
  expectRejectedNaming([&] { lensChain(lens, "tool"); }, "tool.corner_radius");
}

}  // namespace
}  // namespace scallop
