// The simulated path interval (analysis/simulated_interval) against the closed forms
// of the seeds, the exact computational procedure, and the brute-force reference.
// No simulated number is written down here: every expectation is computed.
#include "analysis/simulated_interval.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "analysis/path_interval.h"
#include "sweep/brute_force_reference.h"
#include "base/constants.h"

namespace scallop {
namespace {

constexpr double kAcceptanceMm = 1e-4;  // the acceptance bound
constexpr double kExactMm = 1e-6;       // what the exact geometry actually achieves

struct Posture {
  double leadDeg, tiltDeg;
};

TEST(SimulatedInterval, FloorIsTheDepthRulePlane) {
  for (const Posture& p : {Posture{0, 0}, Posture{5, 0}, Posture{10, 7}, Posture{0, -12}}) {
    SimulatedPass pass(Cutter::make(CutterType::Bull, 3, 1), p.leadDeg, p.tiltDeg);
    EXPECT_NEAR(pass.heightAboveFloor(pass.floorPositionMm()), 0, 1e-9);
    EXPECT_GE(pass.heightAboveFloor(pass.floorPositionMm() + 0.3), -1e-12);
    EXPECT_GE(pass.heightAboveFloor(pass.floorPositionMm() - 0.3), -1e-12);
  }
}

// Seed 001 Eq. (1): the ball leaves the circle of its sphere in any posture, centred on
// the ball's centre, so both sides equal sqrt(2 R h - h^2).
TEST(SimulatedInterval, BallMatchesSeed001Eq1InAnyPosture) {
  for (double R : {3.0, 5.0}) {
    for (const Posture& p : {Posture{0, 0}, Posture{10, 0}, Posture{0, 15}, Posture{20, -10}}) {
      SimulatedPass pass(Cutter::make(CutterType::Ball, R), p.leadDeg, p.tiltDeg);
      for (double h : {0.01, 0.05, 0.1, 0.5}) {
        const double want = std::sqrt(2 * R * h - h * h);
        const SideIntervals s = pass.halfIntervals(h);
        ASSERT_TRUE(s.reachable) << s.reason;
        EXPECT_NEAR(s.plusMm, want, kAcceptanceMm);
        EXPECT_NEAR(s.plusMm, want, kExactMm)
            << "R=" << R << " lead=" << p.leadDeg << " tilt=" << p.tiltDeg << " h=" << h;
        EXPECT_NEAR(s.minusMm, want, kExactMm);
      }
    }
  }
}

// Seed 000 Eq. (11) with Rcr = 0: a flat end mill inclined by rho along the feed leaves
// L/2 = R sqrt(1 - ((R sin rho - h) / (R sin rho))^2).
TEST(SimulatedInterval, InclinedFlatEndMillMatchesTheEllipse) {
  const double R = 3;
  for (double rho : {5.0, 10.0, 20.0, 45.0}) {
    SimulatedPass pass(Cutter::make(CutterType::Flat, R), rho, 0);
    const double depth = R * std::sin(degToRad(rho));
    for (double h : {0.02, 0.05, 0.2, 0.9 * depth}) {
      if (h >= depth) continue;
      const double want = R * std::sqrt(1 - std::pow((depth - h) / depth, 2));
      const SideIntervals s = pass.halfIntervals(h);
      ASSERT_TRUE(s.reachable) << s.reason;
      EXPECT_NEAR(s.plusMm, want, kAcceptanceMm);
      EXPECT_NEAR(s.plusMm, want, kExactMm) << "rho=" << rho << " h=" << h;
      EXPECT_NEAR(s.minusMm, want, kExactMm) << "rho=" << rho << " h=" << h;
    }
  }
}

// For lead-only postures the computational procedure (seed 000 Fig. 1) is exact
// geometry too: the two must agree, and the seed's printed 3D values sit below both.
TEST(SimulatedInterval, BullWithLeadMatchesTheComputationalProcedure) {
  struct Case {
    double R, r, lead, h;
  };
  for (const Case& c :
       {Case{3, 1, 5, 0.05}, Case{3, 1, 5, 0.10}, Case{3, 1, 10, 0.05}, Case{3, 1, 10, 0.10},
        Case{6, 2, 5, 0.05}, Case{6, 2, 10, 0.10}, Case{5, 1, 5, 0.05}, Case{7, 3, 5, 0.10},
        Case{4, 2, 45, 0.5}, Case{3, 1, -10, 0.05}, Case{3, 1, 0, 0.05}}) {
    SimulatedPass pass(Cutter::make(CutterType::Bull, c.R, c.r), c.lead, 0);
    const SideIntervals s = pass.halfIntervals(c.h);
    ASSERT_TRUE(s.reachable) << s.reason;
    const ProcedureResult want = halfIntervalComputational(c.R, c.r, c.lead, c.h);
    ASSERT_TRUE(want.applicable) << want.reason;
    EXPECT_NEAR(s.plusMm, want.value, kExactMm) << c.R << " " << c.r << " " << c.lead << " " << c.h;
    EXPECT_NEAR(s.minusMm, want.value, kExactMm);
  }
}

// The brute-force reference (tests/sweep/brute_force_reference.h) shares no code with
// the simulation. For any posture: the reference height crosses h inside a small
// bracket around the simulated root, and bisection on the reference lands on it.
double referenceRoot(const ref::RefCutter& rc, const SimulatedPass& pass, double h, double y) {
  const Vec3 along{pass.halfLengthMm(), 0, 0};
  auto f = [&](double yy) {
    const ref::RefHit hit = ref::sweptLowest(rc, pass.tip() - along, pass.tip() + along,
                                             pass.axis(), 0, pass.centreY() + yy);
    return hit.hit ? hit.z - h : HUGE_VAL;
  };
  double a = y - 0.01, b = y + 0.01;
  double fa = f(a), fb = f(b);
  if (fa > fb) std::swap(a, b), std::swap(fa, fb);
  EXPECT_LT(fa, 0);
  EXPECT_GT(fb, 0);
  for (int i = 0; i < 60; ++i) {
    const double m = 0.5 * (a + b);
    (f(m) < 0 ? a : b) = m;
  }
  return 0.5 * (a + b);
}

struct BullCase {
  double R, r, lead, tilt, h;
};
const BullCase kBullCases[] = {{3, 1, 5, 0, 0.05},   {3, 1, 10, 0, 0.10}, {6, 2, 5, 0, 0.05},
                               {3, 1, 5, 7, 0.05},   {3, 1, 0, 10, 0.05}, {4, 1.5, 15, -8, 0.1},
                               {3, 0.5, 30, 20, 0.2}};

TEST(SimulatedInterval, BullMatchesBruteForceInAnyPosture) {
  for (const BullCase& c : kBullCases) {
    SimulatedPass pass(Cutter::make(CutterType::Bull, c.R, c.r), c.lead, c.tilt);
    const ref::RefCutter rc = ref::makeRefCutter(CutterType::Bull, c.R, c.r);
    // The floor of the reference: the cutter's lowest point by its own support value.
    EXPECT_NEAR(pass.tip().z - ref::supportValue(rc, pass.axis(), Vec3{0, 0, -1}), 0, 1e-9);
    const SideIntervals s = pass.halfIntervals(c.h);
    ASSERT_TRUE(s.reachable) << s.reason;
    EXPECT_NEAR(referenceRoot(rc, pass, c.h, s.plusMm), s.plusMm, kAcceptanceMm);
    EXPECT_NEAR(-referenceRoot(rc, pass, c.h, -s.minusMm), s.minusMm, kAcceptanceMm);
    if (c.tilt == 0) {
      EXPECT_NEAR(s.plusMm, s.minusMm, kExactMm) << "lead only is symmetric";
    }
  }
}

// (b) Two passes 2 L/2 apart leave exactly h, by the simulation and by the reference.
TEST(SimulatedInterval, TwoPassesAtTheExactIntervalLeaveH) {
  for (const BullCase& c : kBullCases) {
    SimulatedPass pass(Cutter::make(CutterType::Bull, c.R, c.r), c.lead, c.tilt);
    const SideIntervals s = pass.halfIntervals(c.h);
    ASSERT_TRUE(s.reachable) << s.reason;
    const double stepOver = 2 * s.halfIntervalMm();
    const SimulatedCusp cusp = pass.cusp(stepOver);
    ASSERT_TRUE(cusp.covered);
    EXPECT_NEAR(cusp.heightMm, c.h, 1e-9) << c.R << " lead=" << c.lead << " tilt=" << c.tilt;
    EXPECT_NEAR(cusp.positionMm, s.plusMm, 1e-5);

    const ref::RefCutter rc = ref::makeRefCutter(CutterType::Bull, c.R, c.r);
    const Vec3 along{pass.halfLengthMm(), 0, 0}, next{0, stepOver, 0};
    const std::vector<ref::RefMove> moves = {
        {pass.tip() - along, pass.tip() + along, pass.axis()},
        {pass.tip() + next - along, pass.tip() + next + along, pass.axis()}};
    const double y0 = pass.centreY() + pass.floorPositionMm();
    // 401 samples: the reference refines its extremes by golden section anyway.
    EXPECT_NEAR(ref::cuspHeight(rc, moves, 0, y0, 0, y0 + stepOver, 401), c.h, kAcceptanceMm);
  }
}

// With lead only, the cusp of passes 2x apart is the profile's height at x.
TEST(SimulatedInterval, CuspOfSymmetricPassesIsTheProfileHeight) {
  SimulatedPass pass(Cutter::make(CutterType::Bull, 3, 1), 5, 0);
  for (double x : {0.5, 1.086, 1.442, 1.547, 2.5}) {
    const SimulatedCusp cusp = pass.cusp(2 * x);
    ASSERT_TRUE(cusp.covered);
    EXPECT_NEAR(cusp.heightMm, pass.heightAboveFloor(x), 1e-9) << x;
    EXPECT_NEAR(cusp.positionMm, x, 1e-5) << x;
  }
}

// Sub-cell: the z-map only brackets the root, so its spacing does not show.
TEST(SimulatedInterval, ResultDoesNotDependOnTheBracketSpacing) {
  SimulatedIntervalOptions coarse, fine;
  coarse.bracketSpacingMm = 0.25;
  fine.bracketSpacingMm = 0.001;
  const Cutter bull = Cutter::make(CutterType::Bull, 3, 1);
  SimulatedPass a(bull, 5, 7, coarse), b(bull, 5, 7, fine);
  const SideIntervals sa = a.halfIntervals(0.05), sb = b.halfIntervals(0.05);
  ASSERT_TRUE(sa.reachable && sb.reachable);
  EXPECT_NEAR(sa.plusMm, sb.plusMm, 1e-10);
  EXPECT_NEAR(sa.minusMm, sb.minusMm, 1e-10);
  EXPECT_NEAR(a.cusp(2.0).heightMm, b.cusp(2.0).heightMm, 1e-10);
}

TEST(SimulatedInterval, ProfileIsAZMapColumnAboveTheFloor) {
  SimulatedPass pass(Cutter::make(CutterType::Ball, 3), 0, 0);
  const ScallopProfile p = pass.profile(-1, 1, 0.25);
  ASSERT_EQ(p.position.size(), 9u);
  for (size_t k = 0; k < p.position.size(); ++k) {
    EXPECT_NEAR(p.position[k], -1 + 0.25 * double(k), 1e-12);
    EXPECT_NEAR(p.height[k], 3 - std::sqrt(9 - p.position[k] * p.position[k]), 1e-9);
  }
}

TEST(SimulatedInterval, BeyondTheCutterIsNotReachable) {
  // A flat end mill without inclination leaves a flat floor and a vertical wall.
  SimulatedPass flat(Cutter::make(CutterType::Flat, 3), 0, 0);
  SideIntervals s = flat.halfIntervals(0.05);
  EXPECT_FALSE(s.reachable);
  EXPECT_NE(s.reason.find("beyond the cutter"), std::string::npos) << s.reason;
  // Above R sin(rho) the inclined flat end mill's ellipse ends at the flank.
  SimulatedPass inclined(Cutter::make(CutterType::Flat, 3), 5, 0);
  EXPECT_TRUE(inclined.halfIntervals(0.99 * 3 * std::sin(degToRad(5))).reachable);
  EXPECT_FALSE(inclined.halfIntervals(1.01 * 3 * std::sin(degToRad(5))).reachable);
  // The ball's sphere ends at its equator, R above the floor.
  SimulatedPass ball(Cutter::make(CutterType::Ball, 3), 0, 0);
  EXPECT_TRUE(ball.halfIntervals(2.9).reachable);
  EXPECT_FALSE(ball.halfIntervals(3.1).reachable);
  EXPECT_FALSE(ball.halfIntervals(0).reachable);
  EXPECT_FALSE(ball.halfIntervals(-0.1).reachable);
  EXPECT_FALSE(ball.halfIntervals(std::nan("")).reachable);
}

TEST(SimulatedInterval, PassesThatDoNotOverlapLeaveAnUncutStrip) {
  SimulatedPass pass(Cutter::make(CutterType::Bull, 3, 1), 5, 0);
  EXPECT_FALSE(pass.cusp(6.5).covered);
  EXPECT_TRUE(pass.cusp(5.9).covered);
}

}  // namespace
}  // namespace scallop
