// The general kernel (cutters of any convex profile: profile_lowest_point.cpp and
// SweptMove's certified search for every move of such a cutter):
//   * on CutterProfile::of(ball / flat / bull) it agrees with the ball, flat and bull
//     kernel within 1e-9 mm, stationary and on random constant-axis and turning moves;
//   * on random tapered balls and bulls, cones, barrels, lenses, ovals and free chains
//     (tests/sweep/profile_cases.h) it agrees with the independent brute-force reference
//     (brute_force_reference.h with the case's own w(s)) within 1e-6 mm, on constant and
//     turning axes (up to 90 degrees a move), level feeds, ramps, plunges;
//   * no search runs out of samples before its proof closes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

#include "base/constants.h"
#include "base/input_error.h"
#include "sweep/brute_force_reference.h"
#include "sweep/cutter_profile.h"
#include "sweep/pose.h"
#include "sweep/pose_curve.h"
#include "sweep/profile_cases.h"
#include "sweep/swept_move.h"
#include "sweep/swept_segment.h"
#include "sweep/tool_path_sweep.h"
#include "tests/support/random_cases.h"

namespace scallop {
namespace {

using ref::unitFromAngles;

// The same solid as `c`, swept by the general kernel.
Cutter generalOf(const Cutter& c) {
  Cutter g;
  g.type = CutterType::Profile;
  g.profile = std::make_shared<const CutterProfile>(CutterProfile::of(c));
  g.radius = g.profile->maxRadius();
  g.fluteLength = g.profile->fluteLength();
  return g;
}

struct Axes {
  Vec3 a0, a1;
};
// Polar angles in [0, 90] degrees; `turning`: a turn of at most 90 degrees, else a1 = a0.
Axes randomAxes(std::mt19937_64& rng, bool turning) {
  std::uniform_real_distribution<double> u(0, 1);
  for (;;) {
    Axes ax{unitFromAngles(0.5 * kPi * u(rng), 2 * kPi * u(rng)),
            unitFromAngles(0.5 * kPi * u(rng), 2 * kPi * u(rng))};
    if (!turning) ax.a1 = ax.a0;
    if (!turning || (dot(ax.a0, ax.a1) >= 1e-3 && dot(ax.a0, ax.a1) < 1 - 1e-6)) return ax;
  }
}

TEST(GeneralCutter, StationaryAgreesWithBallFlatBullKernel) {
  std::mt19937_64 rng(3301);
  std::uniform_real_distribution<double> u(-1, 1);
  double worst = 0;
  int hits = 0;
  for (int k = 0; k < 60; ++k) {
    const test::CutterShape s = test::randomCutterShape(rng, k);
    const Cutter c = Cutter::make(s.type, s.radius, s.cornerRadius, s.fluteLength);
    const Cutter g = generalOf(c);
    const Vec3 a = randomAxes(rng, false).a0;
    for (int q = 0; q < 20; ++q) {
      const double x = 1.2 * c.radius * u(rng) + a.x * c.fluteLength * 0.5 * (1 + u(rng));
      const double y = 1.2 * c.radius * u(rng) + a.y * c.fluteLength * 0.5 * (1 + u(rng));
      const LowestPoint want = cutterLowestPoint(c, a, x, y);
      const LowestPoint got = cutterLowestPoint(g, a, x, y);
      if (want.hit && got.hit) {
        ++hits;
        worst = std::max(worst, std::fabs(got.z - want.z));
        EXPECT_NEAR(got.z, want.z, 1e-9) << toString(c.type) << " k " << k;
      } else if (want.hit != got.hit) {
        // Only a line that grazes the solid may differ in hit or miss.
        const LowestPoint grazing = want.hit ? want : got;
        EXPECT_GT(grazing.normal.z, -1e-3) << toString(c.type) << " k " << k;
      }
      // Support points: the same support value.
      const Vec3 dir = normalize(Vec3{u(rng), u(rng), u(rng)});
      EXPECT_NEAR(dot(dir, cutterSupport(g, a, dir)), dot(dir, cutterSupport(c, a, dir)), 1e-12);
    }
  }
  std::printf("stationary general vs ball/flat/bull: %d hits, worst %.2e mm\n", hits, worst);
}

TEST(GeneralCutter, MovesAgreeWithBallFlatBullKernel) {
  std::mt19937_64 rng(3302);
  std::uniform_real_distribution<double> u(-1, 1);
  const unsigned long long unprovenBefore = SweptMove::unprovenSearches();
  double worst = 0;
  int hits = 0, mismatches = 0;
  for (int k = 0; k < 48; ++k) {
    const test::CutterShape s = test::randomCutterShape(rng, k);
    const Cutter c = Cutter::make(s.type, s.radius, s.cornerRadius, s.fluteLength);
    const Axes ax = randomAxes(rng, k % 2 == 1);
    const Vec3 p1 = test::randomMoveEnd(rng, k / 2);
    const PoseCurve curve = PoseCurve::linear({{0, 0, 0}, ax.a0}, {p1, ax.a1});
    const SweptMove want(c, curve), got(generalOf(c), curve);
    ASSERT_TRUE(got.turning());  // every move of a general cutter: the certified search
    const Box3 box = want.bounds();
    for (int q = 0; q < 12; ++q) {
      const double x = 0.5 * (box.min.x + box.max.x) + 0.5 * (box.max.x - box.min.x) * u(rng);
      const double y = 0.5 * (box.min.y + box.max.y) + 0.5 * (box.max.y - box.min.y) * u(rng);
      const LowestPoint a = want.lowestPoint(x, y), b = got.lowestPoint(x, y);
      if (a.hit != b.hit) {
        // A grazing line: the hit one has its normal near horizontal.
        const LowestPoint& h = a.hit ? a : b;
        if (!(h.normal.z > -1e-2)) ++mismatches;
        continue;
      }
      if (!a.hit) continue;
      ++hits;
      worst = std::max(worst, std::fabs(a.z - b.z));
      EXPECT_NEAR(b.z, a.z, 1e-9) << toString(c.type) << " k " << k << " (" << x << ", " << y
                                  << ")";
    }
    // Support (the culling planes): an upper bound of the true one, tight for a constant
    // axis.
    for (int q = 0; q < 4; ++q) {
      const Vec3 dir = normalize(Vec3{u(rng), u(rng), -1});
      EXPECT_GE(got.support(dir), want.support(dir) - 1e-9);
      if (k % 2 == 0) {
        EXPECT_NEAR(got.support(dir), want.support(dir), 1e-9);
      }
    }
  }
  std::printf("moves general vs ball/flat/bull: %d hits, worst %.2e mm\n", hits, worst);
  EXPECT_EQ(mismatches, 0);
  EXPECT_EQ(SweptMove::unprovenSearches(), unprovenBefore);
}

ref::RefCutter refCutterOf(const test::ProfileCase& pc) {
  ref::RefCutter r;
  r.R = pc.maxWidth();
  r.L = pc.fluteLength();
  r.width = [pc](double s) { return pc.width(s); };
  return r;
}

TEST(GeneralCutter, RandomProfilesAgreeWithBruteForce) {
  std::mt19937_64 rng(3303);
  std::uniform_real_distribution<double> u(-1, 1);
  const unsigned long long unprovenBefore = SweptMove::unprovenSearches();
  int hits = 0, misses = 0, grazing = 0;
  double worst = 0, worstConstant = 0, worstTurning = 0;
  for (int k = 0; k < 56; ++k) {
    const test::ProfileCase pc = test::randomProfileCase(rng, k);
    const Cutter c = pc.cutter();
    const ref::RefCutter rc = refCutterOf(pc);
    const bool turning = (k / 7) % 2 == 1;
    const Axes ax = randomAxes(rng, turning);
    const Vec3 p1 = test::randomMoveEnd(rng, k / 14 + k);
    const PoseCurve curve = PoseCurve::linear({{0, 0, 0}, ax.a0}, {p1, ax.a1});
    const SweptMove move(c, curve);
    const ref::RefCurve refCurve{
        {0, 0, 0}, p1, [&](double t) { return ref::slerp(ax.a0, ax.a1, t); }};
    const Box3 box = move.bounds();
    for (int q = 0; q < 6; ++q) {
      const double x = 0.5 * (box.min.x + box.max.x) + 0.4 * (box.max.x - box.min.x) * u(rng);
      const double y = 0.5 * (box.min.y + box.max.y) + 0.4 * (box.max.y - box.min.y) * u(rng);
      const LowestPoint lp = move.lowestPoint(x, y);
      double depth = 0;
      const ref::RefHit want = turning ? ref::turningLowest(rc, refCurve, x, y, 401, &depth)
                                       : ref::sweptLowest(rc, {0, 0, 0}, p1, ax.a0, x, y);
      if (!turning) depth = 1;  // the constant-axis reference is exact in hit or miss
      if (std::fabs(depth) < 1e-5) {
        ++grazing;
        continue;
      }
      ASSERT_EQ(lp.hit, want.hit) << pc.name << " k " << k << " (" << x << ", " << y << ")";
      if (!lp.hit) {
        ++misses;
        continue;
      }
      ++hits;
      const double err = std::fabs(lp.z - want.z);
      worst = std::max(worst, err);
      (turning ? worstTurning : worstConstant) =
          std::max(turning ? worstTurning : worstConstant, err);
      EXPECT_LT(err, 1e-6) << pc.name << " k " << k << " (" << x << ", " << y << "): kernel "
                           << lp.z << ", reference " << want.z;
    }
  }
  std::printf(
      "profiles vs brute force: %d hits, %d misses, %d grazing; worst %.2e mm (constant axis "
      "%.2e, turning %.2e)\n",
      hits, misses, grazing, worst, worstConstant, worstTurning);
  EXPECT_GT(hits, 150);
  EXPECT_EQ(SweptMove::unprovenSearches(), unprovenBefore);
}

// The teeth model takes a general cutter (tooth_sweep_test.cpp checks its heights
// against the brute-force reference): its edges cut, never below the envelope.
TEST(GeneralCutter, TeethModelSweepsAGeneralCutter) {
  std::mt19937_64 rng(3304);
  const Cutter c = test::randomProfileCase(rng, 0).cutter();
  ToolPath path;
  Move mv;
  mv.from = {{0, 0, 0}, {0, 0, 1}};
  mv.to = {{1, 0, 0}, {0, 0, 1}};
  path.moves.push_back(mv);
  CuttingModel teeth;
  teeth.kind = CuttingModelKind::Teeth;
  teeth.feedPerTooth = 0.05;
  const std::vector<SweptMove> moves = sweepToolPath(c, path, teeth);
  ASSERT_EQ(moves.size(), 1u);
  ASSERT_NE(moves[0].teeth(), nullptr);
  const LowestPoint got = moves[0].lowestPoint(0.5, 0.01);
  ASSERT_TRUE(got.hit);
  EXPECT_GE(got.z, moves[0].envelopeLowestPoint(0.5, 0.01).z - 1e-9);
}

}  // namespace
}  // namespace scallop
