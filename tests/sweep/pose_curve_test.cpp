// PoseCurve's machine kinds (sweep/pose_curve.h): the table-table forward kinematics
// against LinuxCNC's trtfuncs formulas written out here term by term, and the tip's
// velocity, acceleration and proven acceleration and jerk bounds against finite
// differences; and the slerp's axis (its own sine and cosine for small angles) against
// the same formula in long double.
#include "sweep/pose_curve.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "sweep/machine_reference.h"
#include "tests/support/random_cases.h"

namespace scallop {
namespace {

test::MachineMove randomCase(std::mt19937_64& rng, int k) {
  return test::randomMachineMove(rng, k % 2 ? RotaryKinematics::TableAC : RotaryKinematics::TableBC,
                                 {20, 5, 50, 20, 0.8, 0.6, 3, 1.5, 30, 10});
}

TEST(PoseCurve, ForwardKinematicsAreTrtfuncs) {
  std::mt19937_64 rng(7);
  for (int k = 0; k < 200; ++k) {
    const test::MachineMove c = randomCase(rng, k);
    const RotaryMotion& m = c.motion;
    const PoseCurve curve = PoseCurve::jointLinear(c.machine, m);
    ASSERT_FALSE(curve.linearTip());
    for (double t : {0.0, 0.3, 0.71, 1.0}) {
      const Vec3 j = m.joints0 + (m.joints1 - m.joints0) * t;
      const double tilt = m.tilt0 + (m.tilt1 - m.tilt0) * t,
                   spin = m.spin0 + (m.spin1 - m.spin0) * t;
      const Vec3 want = trtForward(c.machine, j, tilt, spin), got = curve.tip(t);
      EXPECT_NEAR(length(got - want), 0, 1e-12 * (1 + length(want))) << k << " t " << t;
      EXPECT_NEAR(length(machineTip(c.machine, j, tilt, spin) - want), 0,
                  1e-12 * (1 + length(want)));
      const Vec3 a = curve.axis(t), wantAxis = conventionAxis(c.machine.kinematics, tilt, spin);
      EXPECT_NEAR(length(a - wantAxis), 0, 1e-14) << k;
    }
  }
}

// At zero angles the table is square: the tip is the joints (LinuxCNC's home pose).
TEST(PoseCurve, ForwardKinematicsAtZeroAnglesIsTheIdentity) {
  TableMachine m;
  m.pivot = {3, -4, 5};
  m.offset = {1, 2, 60};
  for (RotaryKinematics k : {RotaryKinematics::TableBC, RotaryKinematics::TableAC}) {
    m.kinematics = k;
    const Vec3 tip = machineTip(m, {7, 8, 9}, 0, 0);
    EXPECT_NEAR(length(tip - Vec3{7, 8, 9}), 0, 1e-13);
  }
}

// Velocity against a central difference, and |tip''|, |tip'''| by finite differences
// below the bounds at every sample.
TEST(PoseCurve, TipVelocityAndBoundsAgreeWithFiniteDifferences) {
  std::mt19937_64 rng(11);
  double worstAccelRatio = 0, worstJerkRatio = 0;
  for (int k = 0; k < 100; ++k) {
    const test::MachineMove c = randomCase(rng, k);
    const PoseCurve curve = PoseCurve::jointLinear(c.machine, c.motion);
    const double accel = curve.tipAccelBound(), jerk = curve.tipJerkBound();
    ASSERT_GT(accel, 0);
    ASSERT_GT(jerk, 0);
    auto f = [&](double t) { return curve.tip(t); };
    for (int s = 0; s <= 400; ++s) {
      const double t = 0.01 + 0.98 * s / 400.0;
      const double h1 = 1e-5;
      const Vec3 v = (f(t + h1) - f(t - h1)) / (2 * h1);
      // Central-difference error: h^2 / 6 |tip'''|, plus round-off.
      EXPECT_NEAR(length(curve.tipVelocity(t) - v), 0, h1 * h1 * jerk + 1e-8 * (1 + length(v)))
          << k;
      // tipAcceleration: central differences of tipVelocity.
      const Vec3 dv = (curve.tipVelocity(t + h1) - curve.tipVelocity(t - h1)) / (2 * h1);
      EXPECT_NEAR(length(curve.tipAcceleration(t) - dv), 0, 1e-6 * (1 + length(dv))) << k;
      const double h2 = 1e-3;
      const Vec3 a = (f(t + h2) - f(t) * 2 + f(t - h2)) / (h2 * h2);
      const Vec3 j =
          (f(t + 2 * h2) - f(t + h2) * 2 + f(t - h2) * 2 - f(t - 2 * h2)) / (2 * h2 * h2 * h2);
      // Differences of degree n are a mean of the n-th derivative: within the bound
      // up to round-off (the slack is far below the bounds, of order 1e2 to 1e4).
      EXPECT_LE(length(a), accel * (1 + 1e-6) + 1e-4) << k << " t " << t;
      EXPECT_LE(length(j), jerk * (1 + 1e-6) + 1e-2) << k << " t " << t;
      worstAccelRatio = std::fmax(worstAccelRatio, length(a) / accel);
      worstJerkRatio = std::fmax(worstJerkRatio, length(j) / jerk);
    }
  }
  std::printf("tip'' / bound up to %.3f, tip''' / bound up to %.3f\n", worstAccelRatio,
              worstJerkRatio);
}

// A pure spin of a horizontal lever: |tip''| = wC^2 |q| exactly, the bound itself.
TEST(PoseCurve, AccelerationBoundIsTightForAPureSpin) {
  TableMachine m;  // pivot and offsets zero: tip = Rz(-C) Ry(-B) joints
  RotaryMotion r;
  r.tcp = false;
  r.spin0 = 0.2, r.spin1 = 1.4;
  r.joints0 = r.joints1 = {10, 0, 0};
  const PoseCurve curve = PoseCurve::jointLinear(m, r);
  const double w = 1.2, h = 1e-4, t = 0.5;
  const Vec3 a = (curve.tip(t + h) - curve.tip(t) * 2 + curve.tip(t - h)) / (h * h);
  EXPECT_NEAR(curve.tipAccelBound(), w * w * 10, 1e-12);
  EXPECT_NEAR(length(a), curve.tipAccelBound(), 1e-5);
}

TEST(PoseCurve, LinearTipKindsHaveZeroBounds) {
  const Vec3 p0{1, 2, 3}, p1{4, -1, 0};
  const PoseCurve slerp = PoseCurve::linear({p0, {0, 0, 1}}, {p1, normalize(Vec3{0.3, 0, 1})});
  const PoseCurve rotary = PoseCurve::rotary(RotaryKinematics::TableAC, p0, p1, 0.1, 0.5, -1, 2);
  for (const PoseCurve& c : {slerp, rotary}) {
    EXPECT_TRUE(c.linearTip());
    EXPECT_EQ(c.tipAccelBound(), 0);
    EXPECT_EQ(c.tipJerkBound(), 0);
    EXPECT_EQ(c.tipVelocity(0.4), p1 - p0);
  }
  // TCP off with constant angles: the rotation is fixed, so the tip is a line.
  RotaryMotion still;
  still.tcp = false;
  still.tilt0 = still.tilt1 = 0.3;
  still.spin0 = still.spin1 = 1.1;
  still.joints1 = {5, 0, 0};
  TableMachine m;
  m.offset = {1, 0, 40};
  EXPECT_TRUE(PoseCurve::jointLinear(m, still).linearTip());
}

// axis(t) = u cos(phi t) + v sin(phi t) for turns from 1e-9 rad to 3 rad, against the
// same written in long double with the library's sinl and cosl: within 4e-16 per
// component (a few units in the last place), unit to 4e-16, and exactly the end axes at
// t = 0 and 1. Small angles take the curve's own Taylor series (pose_curve.cpp), large
// ones the library.
TEST(PoseCurve, SlerpAxisIsTheGreatCircleToTheLastBits) {
  std::mt19937_64 rng(71);
  std::uniform_real_distribution<double> u(-1, 1);
  double worst = 0, worstUnit = 0;
  int samples = 0;
  for (int k = 0; k < 200; ++k) {
    const double turn = std::pow(10.0, -9 + 9.5 * (k / 199.0));  // 1e-9 .. ~3.2 rad
    if (turn >= 3.1) continue;
    const Vec3 a0 = normalize(Vec3{0.5 * u(rng), 0.5 * u(rng), 1});
    const Vec3 w = normalize(cross(a0, Vec3{u(rng), u(rng), u(rng)}));
    const Vec3 a1 = a0 * std::cos(turn) + cross(w, a0) * std::sin(turn);
    const PoseCurve c = PoseCurve::linear({{0, 0, 0}, a0}, {{1, 0, 0}, a1});
    if (c.constantAxis()) continue;
    // The curve's own u and v: a0 (normalised again, as the curve does) and the unit
    // vector across it towards a1.
    const Vec3 u0 = normalize(a0), v = normalize(a1 - u0 * dot(u0, a1));
    EXPECT_EQ(c.axis(0).x, u0.x);
    EXPECT_EQ(c.axis(0).z, u0.z);
    const long double phi = std::atan2(length(cross(u0, normalize(a1))), dot(u0, normalize(a1)));
    for (int s = 1; s < 16; ++s) {
      const double t = s / 16.0 + 1e-3 * u(rng);
      const long double ang = phi * (long double)t;
      const long double cs = std::cos(ang), sn = std::sin(ang);
      const Vec3 got = c.axis(t);
      const long double ex = u0.x * cs + v.x * sn, ey = u0.y * cs + v.y * sn,
                        ez = u0.z * cs + v.z * sn;
      const double e =
          double(std::max({std::fabs(got.x - ex), std::fabs(got.y - ey), std::fabs(got.z - ez)}));
      worst = std::max(worst, e);
      const long double len2 =
          (long double)got.x * got.x + (long double)got.y * got.y + (long double)got.z * got.z;
      worstUnit = std::max(worstUnit, double(std::fabs(std::sqrt(len2) - 1)));
      EXPECT_LE(e, 4e-16) << "turn " << turn << " t " << t;
      ++samples;
    }
  }
  std::printf("PoseCurve slerp axis: %d samples, worst %.3g from long double, |axis| - 1 %.3g\n",
              samples, worst, worstUnit);
  EXPECT_LE(worstUnit, 4e-16);
  EXPECT_GE(samples, 2500);
}

}  // namespace
}  // namespace scallop
