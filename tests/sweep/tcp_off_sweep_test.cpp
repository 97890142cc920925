// Moves of a table-table machine with TCP off (CONVENTIONS.md "Machines"): the joints
// move linearly, so the tip follows the forward kinematics along a curve while the axis
// turns. SweptMove sweeps such a move exactly (swept_move.cpp's bounds with the tip's
// acceleration, ray_clearance.cpp's curve bound); the reference sweeps the same pose
// curve, written from trtfuncs and the convention's axis formulas by the test itself.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "sweep/brute_force_reference.h"
#include "sweep/machine_reference.h"
#include "sweep/pose_curve.h"
#include "sweep/swept_move.h"

namespace scallop {
namespace {

TEST(TcpOffSweep, JointLinearMovesAgreeWithBruteForce) {
  std::mt19937_64 rng(1717);
  std::uniform_real_distribution<double> u(-1, 1);
  int hits = 0, misses = 0, grazing = 0;
  double worst = 0;
  const unsigned long long unprovenBefore = SweptMove::unprovenSearches();
  for (int k = 0; k < 48; ++k) {
    TableMachine machine;
    machine.kinematics = k % 2 ? RotaryKinematics::TableAC : RotaryKinematics::TableBC;
    machine.pivot = {4 * u(rng), 4 * u(rng), -3 + 2 * u(rng)};
    machine.offset = {2 * u(rng), 2 * u(rng), 5 * u(rng)};
    RotaryMotion m;
    m.tcp = false;
    // Rotary steps of up to 3 and 6 degrees in one block, as 5-axis programs have them.
    m.tilt0 = 0.5 * u(rng), m.tilt1 = m.tilt0 + 0.05 * u(rng);
    m.spin0 = 3 * u(rng), m.spin1 = m.spin0 + 0.1 * u(rng);
    m.joints0 = {3 * u(rng), 3 * u(rng), 2 * u(rng)};
    m.joints1 = m.joints0 + Vec3{2 * u(rng), 2 * u(rng), 0.5 * u(rng)};
    const CutterType type =
        k % 3 == 0 ? CutterType::Ball : (k % 3 == 1 ? CutterType::Bull : CutterType::Flat);
    const Cutter cutter = Cutter::make(type, 3, 1, 12);
    const ref::RefCutter refCutter = ref::makeRefCutter(type, 3, 1, 12);
    const PoseCurve curve = PoseCurve::jointLinear(machine, m);
    ASSERT_FALSE(curve.linearTip());
    const SweptMove move(cutter, curve);
    ASSERT_TRUE(move.turning());

    auto tilt = [&](double t) { return m.tilt0 + (m.tilt1 - m.tilt0) * t; };
    auto spin = [&](double t) { return m.spin0 + (m.spin1 - m.spin0) * t; };
    ref::RefCurve refCurve;
    refCurve.axis = [&](double t) { return conventionAxis(machine.kinematics, tilt(t), spin(t)); };
    refCurve.tip = [&](double t) {
      return trtForward(machine, m.joints0 + (m.joints1 - m.joints0) * t, tilt(t), spin(t));
    };
    refCurve.p0 = refCurve.tip(0), refCurve.p1 = refCurve.tip(1);
    // Lines over the tip's path, out to the cutter's radius.
    const Vec3 mid = refCurve.tip(0.5);
    const double half = 0.5 * length(refCurve.p1 - refCurve.p0) + 3;
    for (int q = 0; q < 8; ++q) {
      const double x = mid.x + half * u(rng), y = mid.y + half * u(rng);
      double depth = 0;
      const ref::RefHit r = ref::turningLowest(refCutter, refCurve, x, y, 401, &depth);
      const LowestPoint lp = move.lowestPoint(x, y);
      if (std::fabs(depth) < 1e-5) {
        ++grazing;
        continue;
      }
      ASSERT_EQ(lp.hit, r.hit) << "move " << k << " (" << x << ", " << y << ")";
      if (!r.hit) {
        ++misses;
        continue;
      }
      ++hits;
      worst = std::max(worst, std::fabs(lp.z - r.z));
      EXPECT_NEAR(lp.z, r.z, 1e-6)
          << "move " << k << " " << toString(type) << " (" << x << ", " << y << ")";
    }
  }
  std::printf(
      "TCP off: %d hits, %d misses, %d grazing skipped; worst |kernel - reference| = %.3g mm\n",
      hits, misses, grazing, worst);
  EXPECT_GE(hits, 200);
  EXPECT_EQ(SweptMove::unprovenSearches(), unprovenBefore);
}

}  // namespace
}  // namespace scallop
