// The closed forms of the cutter shapes, each against the simulated truth
// (SimulatedPass: passes swept and ray-cast, the cusp refined on the exact heights) and
// the exact path interval (PassSection), which share only the cutter's support map:
//   * a V-bit's groove in a plane: at depth d, its walls are the cone's lines, so the
//     groove is d deep and 2 d tan(theta / 2) wide (theta the included angle);
//   * a tapered ball at zero lead on a plane leaves exactly the ball's scallop of its tip
//     radius, r - sqrt(r^2 - w^2 / 4) for passes w apart, while the cusp stays below the
//     taper's tangent point (w / 2 <= r cos b).
// (The barrel's side at the lead that puts the contact on its form arc is
// tests/analysis/contact_curvature_test.cpp's BarrelFormArcAgainstTheExactSection.)
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/pass_section.h"
#include "analysis/simulated_interval.h"
#include "base/constants.h"
#include "sweep/cutter_shapes.h"

namespace scallop {
namespace {

constexpr double kExactMm = 1e-9;

// (The 90-degree V-bit found a defect: PassSection called its groove "beyond the cutter",
// its face normal being the bisection's first direction; analysis/pass_section.cpp.)
TEST(CutterShapeClosedForms, VBitGrooveIsTheConesDepthAndWidth) {
  for (const double angleDeg : {60.0, 90.0, 118.0}) {
    ConeShape vbit;
    vbit.angleDeg = angleDeg;
    vbit.diameter = 6;
    vbit.fluteLength = 10;
    const Cutter cutter = cutterOfChain(CutterType::Cone, coneChain(vbit, "tool"), "tool");
    const double halfAngle = degToRad(angleDeg / 2);
    const SimulatedPass pass(cutter, 0, 0);
    const PassSection section = PassSection::of(cutter, 0, 0);
    EXPECT_NEAR(section.floorZ(), 0, kExactMm) << angleDeg;  // the groove's bottom: the tip
    for (const double depth : {0.1, 0.5, 1.2}) {
      const double halfWidth = depth * std::tan(halfAngle);
      const SideIntervals sim = pass.halfIntervals(depth);
      ASSERT_TRUE(sim.reachable) << sim.reason;
      EXPECT_NEAR(sim.plusMm, halfWidth, kExactMm) << angleDeg << " " << depth;
      EXPECT_NEAR(sim.minusMm, halfWidth, kExactMm) << angleDeg << " " << depth;
      for (const int sign : {1, -1}) {
        const SectionSide side = section.sideFromCentre(depth, sign);
        ASSERT_TRUE(side.reachable);
        EXPECT_NEAR(side.offset.mid(), halfWidth, kExactMm) << angleDeg << " " << depth;
      }
    }
  }
}

TEST(CutterShapeClosedForms, TaperBallAtZeroLeadLeavesItsTipBallsScallop) {
  for (const double taperDeg : {3.0, 10.0, 25.0}) {
    TaperBallShape shape;
    shape.tipRadius = 1;
    shape.taperDeg = taperDeg;
    shape.fluteLength = 12;
    const Cutter cutter =
        cutterOfChain(CutterType::TaperBall, taperBallChain(shape, "tool"), "tool");
    const double r = shape.tipRadius, b = degToRad(taperDeg);
    const SimulatedPass pass(cutter, 0, 0);
    const PassSection section = PassSection::of(cutter, 0, 0);
    for (const double w : {0.2, 0.8, 1.5, 1.8}) {
      if (w / 2 > r * std::cos(b)) continue;  // the cusp would be on the taper
      const double ball = r - std::sqrt(r * r - w * w / 4);
      const SimulatedCusp cusp = pass.cusp(w);
      ASSERT_TRUE(cusp.covered) << taperDeg << " " << w;
      EXPECT_NEAR(cusp.heightMm, ball, kExactMm) << taperDeg << " " << w;
      double exact = 0;
      std::string reason;
      ASSERT_TRUE(section.scallop(w, &exact, &reason)) << reason;
      EXPECT_NEAR(exact, ball, kExactMm) << taperDeg << " " << w;
    }
  }
}

}  // namespace
}  // namespace scallop
