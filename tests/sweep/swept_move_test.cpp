// Acceptance tests of SweptMove (one primitive per move, whatever its axis does) and
// PoseCurve: heights of turning moves against the independent brute-force reference
// (brute_force_reference.h, turningLowest), constant-axis moves against the
// constant-axis kernel bit for bit, the culling support bound, determinism.
#include "sweep/swept_move.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "base/constants.h"
#include "base/input_error.h"
#include "sweep/brute_force_reference.h"
#include "sweep/pose_curve.h"
#include "tests/support/random_cases.h"

namespace scallop {
namespace {

using ref::unitFromAngles;

struct RandomCase {
  Cutter cutter;
  ref::RefCutter refCutter;
  Vec3 p0, p1, a0, a1;
};

// Cutters of all three types, axes from vertical to horizontal, turns up to 90 degrees
// in one move, and tip motions that are level feeds, ramps, plunges or none at all.
RandomCase randomCase(std::mt19937_64& rng, int k) {
  std::uniform_real_distribution<double> u(0, 1);
  RandomCase c;
  const test::CutterShape s = test::randomCutterShape(rng, k);
  c.cutter = Cutter::make(s.type, s.radius, s.cornerRadius, s.fluteLength);
  c.refCutter = ref::makeRefCutter(s.type, s.radius, s.cornerRadius, s.fluteLength);
  // Polar angles in [0, 90] deg for both ends; the turn is at most 90 degrees.
  for (;;) {
    c.a0 = unitFromAngles(0.5 * kPi * u(rng), 2 * kPi * u(rng));
    c.a1 = unitFromAngles(0.5 * kPi * u(rng), 2 * kPi * u(rng));
    if (dot(c.a0, c.a1) >= 1e-3 && dot(c.a0, c.a1) < 1 - 1e-6) break;
  }
  c.p0 = {0, 0, 0};
  switch (k % 4) {
    case 0:  // level feed
      c.p1 = {3 * (u(rng) - 0.5), 3 * (u(rng) - 0.5), 0};
      break;
    case 1:  // ramp
      c.p1 = {3 * (u(rng) - 0.5), 3 * (u(rng) - 0.5), 2 * (u(rng) - 0.5)};
      break;
    case 2:  // plunge or retract
      c.p1 = {0, 0, 2 * (u(rng) - 0.5)};
      break;
    default:  // the axis turns about a standing tip
      c.p1 = c.p0;
      break;
  }
  return c;
}

// The reference height and whether the line merely grazes the solid (then hit or miss
// is a matter of resolution, and such lines are counted but not compared).
struct Reference {
  ref::RefHit hit;
  bool grazing = false;
};
Reference referenceAt(const ref::RefCutter& c, const ref::RefCurve& curve, double x, double y) {
  Reference r;
  double depth = 0;
  r.hit = ref::turningLowest(c, curve, x, y, 401, &depth);
  r.grazing = std::fabs(depth) < 1e-5;
  return r;
}

TEST(SweptMove, RandomTurningMovesAgreeWithBruteForce) {
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> u(-1, 1);
  int hits = 0, misses = 0, grazing = 0, failures = 0;
  double worst = 0;
  const unsigned long long unprovenBefore = SweptMove::unprovenSearches();
  for (int k = 0; k < 90; ++k) {
    const RandomCase rc = randomCase(rng, k);
    const SweptMove move(rc.cutter, PoseCurve::linear({rc.p0, rc.a0}, {rc.p1, rc.a1}));
    ASSERT_TRUE(move.turning());
    const ref::RefCurve curve{rc.p0, rc.p1, [&](double t) { return ref::slerp(rc.a0, rc.a1, t); }};
    // Lines through the footprint: around the tip path, out to the reach of the lean.
    const Box3 box = move.bounds();
    for (int q = 0; q < 4; ++q) {
      const double x = 0.5 * (box.min.x + box.max.x) + 0.5 * (box.max.x - box.min.x) * u(rng);
      const double y = 0.5 * (box.min.y + box.max.y) + 0.5 * (box.max.y - box.min.y) * u(rng);
      const LowestPoint lp = move.lowestPoint(x, y);
      const Reference r = referenceAt(rc.refCutter, curve, x, y);
      if (r.grazing) {
        ++grazing;
        continue;
      }
      if (lp.hit != r.hit.hit) {
        ++failures;
        ADD_FAILURE() << "case " << k << " (" << x << ", " << y << "): kernel hit " << lp.hit
                      << ", reference hit " << r.hit.hit;
        continue;
      }
      if (!lp.hit) {
        ++misses;
        continue;
      }
      ++hits;
      const double err = lp.z - r.hit.z;
      worst = std::max(worst, std::fabs(err));
      if (std::fabs(err) > 1e-6) {
        ++failures;
        ADD_FAILURE() << "case " << k << " type " << toString(rc.cutter.type) << " (" << x << ", "
                      << y << "): kernel " << lp.z << ", reference " << r.hit.z;
        std::fprintf(stderr,
                     "R %.17g r %.17g L %.17g a0 %.17g %.17g %.17g a1 %.17g %.17g %.17g p1 %.17g "
                     "%.17g %.17g x %.17g y %.17g\n",
                     rc.cutter.radius, rc.cutter.cornerRadius, rc.cutter.fluteLength, rc.a0.x,
                     rc.a0.y, rc.a0.z, rc.a1.x, rc.a1.y, rc.a1.z, rc.p1.x, rc.p1.y, rc.p1.z, x, y);
      }
    }
  }
  std::printf(
      "SweptMove turning random: %d hits, %d misses, %d grazing skipped, %d failures; "
      "worst |kernel - reference| = %.3g mm\n",
      hits, misses, grazing, failures, worst);
  EXPECT_GE(hits, 150);
  EXPECT_GE(misses, 5);
  EXPECT_EQ(SweptMove::unprovenSearches(), unprovenBefore);
}

// A 5-axis table-table machine's curve (CONVENTIONS.md "Machines": xyzbc-trt, B and C
// linear in t) goes through the same primitive; the reference writes the axis formula
// itself.
TEST(SweptMove, RotaryMachineCurveAgreesWithBruteForce) {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(-1, 1);
  int hits = 0;
  for (int k = 0; k < 30; ++k) {
    const Cutter cutter = Cutter::make(k % 2 ? CutterType::Bull : CutterType::Ball, 3, 1, 12);
    const ref::RefCutter rc = ref::makeRefCutter(cutter.type, 3, 1, 12);
    const double b0 = 0.6 * u(rng), b1 = b0 + 0.5 * u(rng), c0 = 3 * u(rng), c1 = c0 + 0.8 * u(rng);
    const Vec3 p0{0, 0, 0}, p1{2 * u(rng), 2 * u(rng), 0.3 * u(rng)};
    const bool ac = k % 3 == 0;
    const SweptMove move(
        cutter, PoseCurve::rotary(ac ? RotaryKinematics::TableAC : RotaryKinematics::TableBC, p0,
                                  p1, b0, b1, c0, c1));
    const ref::RefCurve curve{
        p0, p1, [&](double t) {
          const double B = b0 + (b1 - b0) * t, C = c0 + (c1 - c0) * t;
          if (ac) return Vec3{std::sin(C) * std::sin(B), std::cos(C) * std::sin(B), std::cos(B)};
          return Vec3{-std::cos(C) * std::sin(B), std::sin(C) * std::sin(B), std::cos(B)};
        }};
    for (int q = 0; q < 4; ++q) {
      const double x = 1.0 * u(rng) + 0.5 * p1.x, y = 1.0 * u(rng) + 0.5 * p1.y;
      const LowestPoint lp = move.lowestPoint(x, y);
      const Reference r = referenceAt(rc, curve, x, y);
      if (r.grazing) continue;
      ASSERT_EQ(lp.hit, r.hit.hit) << k;
      if (!lp.hit) continue;
      ++hits;
      EXPECT_NEAR(lp.z, r.hit.z, 1e-6) << k;
    }
  }
  EXPECT_GE(hits, 60);
}

// A move whose axis does not turn is the constant-axis kernel itself: today's heights,
// bit for bit.
TEST(SweptMove, ConstantAxisMoveGivesTheSegmentsHeightsBitForBit) {
  const Cutter bull = Cutter::make(CutterType::Bull, 3, 1);
  const Vec3 axis = normalize(Vec3{0.2, -0.1, 1});
  const Vec3 p0{0, 0, 0}, p1{4, 1, -0.3};
  const SweptMove move(bull, PoseCurve::linear({p0, axis}, {p1, axis}));
  // PoseCurve normalises its axes as the path sweep always has.
  const SweptSegment segment(bull, p0, p1, normalize(axis));
  ASSERT_FALSE(move.turning());
  int hits = 0;
  for (double x = -4; x <= 8; x += 0.37) {
    for (double y = -4; y <= 5; y += 0.41) {
      const LowestPoint a = move.lowestPoint(x, y), b = segment.lowestPoint(x, y);
      ASSERT_EQ(a.hit, b.hit);
      if (!a.hit) continue;
      ++hits;
      EXPECT_EQ(a.z, b.z) << x << " " << y;
    }
  }
  EXPECT_GT(hits, 200);
}

// The height of a turning move depends on (x, y) alone: not on the cutoff the caller
// passes (only a miss may be reported at or above it), nor on what was asked before.
TEST(SweptMove, HeightDoesNotDependOnTheCutoff) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  int checked = 0;
  for (int k = 0; k < 40; ++k) {
    const RandomCase rc = randomCase(rng, k);
    const SweptMove move(rc.cutter, PoseCurve::linear({rc.p0, rc.a0}, {rc.p1, rc.a1}));
    for (int q = 0; q < 5; ++q) {
      const double x = 2 * u(rng), y = 2 * u(rng);
      const LowestPoint free = move.lowestPoint(x, y);
      if (!free.hit) continue;
      const LowestPoint above = move.lowestPoint(x, y, nullptr, free.z + 1e-3);
      ASSERT_TRUE(above.hit);
      EXPECT_EQ(above.z, free.z);
      EXPECT_FALSE(move.lowestPoint(x, y, nullptr, free.z - 1e-6).hit);
      ++checked;
    }
  }
  EXPECT_GE(checked, 50);
}

// support() bounds the swept solid's support function from above (the culling planes
// rest on it), within the chord term omega^2 reach / 8 of the true value.
TEST(SweptMove, SupportBoundsTheSweptSolid) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 60; ++k) {
    const RandomCase rc = randomCase(rng, k);
    const PoseCurve curve = PoseCurve::linear({rc.p0, rc.a0}, {rc.p1, rc.a1});
    const SweptMove move(rc.cutter, curve);
    const double reach = std::hypot(rc.cutter.fluteLength, rc.cutter.radius);
    for (int d = 0; d < 6; ++d) {
      const Vec3 dir = normalize(Vec3{u(rng), u(rng), u(rng)});
      double trueMax = -HUGE_VAL;
      for (int i = 0; i <= 2000; ++i) {
        const double t = i / 2000.0;
        const Vec3 a = ref::slerp(rc.a0, rc.a1, t);
        trueMax = std::max(trueMax, dot(dir, rc.p0 + (rc.p1 - rc.p0) * t) +
                                        ref::supportValue(rc.refCutter, a, dir));
      }
      const double bound = move.support(dir);
      EXPECT_GE(bound, trueMax - 1e-9) << k;
      const double omega = curve.turnRate();
      EXPECT_LE(bound, trueMax + omega * omega * reach / 8 + 1e-6) << k;
    }
  }
}

TEST(PoseCurve, SlerpEndsExactlyAndTurnsAtConstantSpeed) {
  const Vec3 a0 = normalize(Vec3{0.1, 0.2, 1}), a1 = normalize(Vec3{-0.5, 0.3, 0.8});
  const PoseCurve c = PoseCurve::linear({{1, 2, 3}, a0}, {{4, 5, 6}, a1});
  EXPECT_EQ(c.axis(0), normalize(a0));
  EXPECT_EQ(c.axis(1), normalize(a1));
  EXPECT_EQ(c.tip(1), (Vec3{4, 5, 6}));
  const double phi = std::acos(dot(a0, a1));
  EXPECT_NEAR(c.turnRate(), phi, 1e-12);
  for (double t : {0.1, 0.33, 0.5, 0.9}) {
    EXPECT_NEAR(std::acos(std::clamp(dot(c.axis(t), a0), -1.0, 1.0)), phi * t, 1e-9);
    EXPECT_NEAR(length(c.axis(t) - ref::slerp(a0, a1, t)), 0, 1e-12);
    // The axis turns with the cutter's angular velocity: axis' = spin x axis.
    const Vec3 fd = (c.axis(t + 1e-6) - c.axis(t - 1e-6)) / 2e-6;
    EXPECT_NEAR(length(cross(c.spin(t), c.axis(t)) - fd), 0, 1e-6);
  }
}

// One curve of each kind: CL slerp, xyzbc-trt and xyzac-trt with TCP on.
std::vector<PoseCurve> threeKinds() {
  return {PoseCurve::linear({{0, 0, 0}, normalize(Vec3{0.3, 0, 1})},
                            {{1, 0, 0}, normalize(Vec3{-0.2, 0.4, 1})}),
          PoseCurve::rotary(RotaryKinematics::TableBC, {}, {1, 0, 0}, 0.2, 0.7, 0.5, -0.4),
          PoseCurve::rotary(RotaryKinematics::TableAC, {}, {1, 0, 0}, -0.3, 0.4, 1.5, 2.4)};
}

// carry() moves a direction fixed to the cutter: the axis itself goes to the axis, and
// for a rotary curve it agrees with the rotation that the axis formula implies.
TEST(PoseCurve, CarryMovesTheAxisWithTheCutter) {
  for (const PoseCurve& curve : threeKinds()) {
    const PoseCurve* c = &curve;
    for (double ta : {0.0, 0.3}) {
      for (double tb : {0.25, 1.0}) {
        EXPECT_NEAR(length(c->carry(c->axis(ta), ta, tb) - c->axis(tb)), 0, 1e-12);
        // A rotation keeps angles: any two carried vectors keep their dot product.
        const Vec3 p{0.3, -0.2, 0.9}, q{-0.5, 0.1, 0.2};
        EXPECT_NEAR(dot(c->carry(p, ta, tb), c->carry(q, ta, tb)), dot(p, q), 1e-12);
      }
    }
  }
}

// spin() is the angular velocity: a direction fixed to the cutter turns as Omega x n,
// and spinRate() is its derivative (finite differences of carry() and spin()).
TEST(PoseCurve, SpinIsTheAngularVelocityOfCarry) {
  const Vec3 n = normalize(Vec3{0.3, -0.5, -0.8});
  for (const PoseCurve& curve : threeKinds()) {
    const PoseCurve* c = &curve;
    for (double t : {0.2, 0.6}) {
      const double e = 1e-6;
      const Vec3 moved = c->carry(n, 0.4, t);
      const Vec3 rate = (c->carry(n, 0.4, t + e) - c->carry(n, 0.4, t - e)) / (2 * e);
      EXPECT_NEAR(length(rate - cross(c->spin(t), moved)), 0, 1e-7);
      const Vec3 spinRate = (c->spin(t + e) - c->spin(t - e)) / (2 * e);
      EXPECT_NEAR(length(spinRate - c->spinRate(t)), 0, 1e-7);
      EXPECT_LE(length(c->spin(t)), c->turnRate() + 1e-12);
    }
  }
}

TEST(PoseCurve, HalfTurnIsAnInputError) {
  try {
    PoseCurve::linear({{0, 0, 0}, {0, 0, 1}}, {{1, 0, 0}, {0, 0, -1}}, "path.cl:7");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("path.cl:7"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("180"), std::string::npos);
  }
}

}  // namespace
}  // namespace scallop
