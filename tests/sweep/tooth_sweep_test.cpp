// The teeth cutting model (sweep/tooth_sweep.h) against the independent brute-force
// reference (tooth_reference.h): random cutters, teeth and moves, through
// sweepToolPath as a job runs it. The spindle angle is computed here from the
// definition (cutting_model.h), not read from the kernel.
#include "sweep/tooth_sweep.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "base/constants.h"
#include "sweep/profile_cases.h"
#include "sweep/tool_path_sweep.h"
#include "sweep/tooth_reference.h"

namespace scallop {
namespace {

struct RandomCase {
  Cutter cutter;
  Vec3 p0, p1, a0, a1;
  double fz = 0.1, phaseDeg = 0;
};

// The unit vector turned from `a` by `angle` about a random direction across it.
Vec3 turnedAxis(std::mt19937_64& rng, const Vec3& a, double angle) {
  std::uniform_real_distribution<double> u(0, 1);
  const Vec3 any = std::fabs(a.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
  const Vec3 p = normalize(cross(a, any)), q = cross(a, p);
  const double az = 2 * kPi * u(rng);
  const Vec3 across = p * std::cos(az) + q * std::sin(az);
  return normalize(a * std::cos(angle) + across * std::sin(angle));
}

// A third of each cutter type's moves turn.
bool turning(int n) {
  return (n / 3) % 3 == 2;
}

// Ball, bull, flat; 1 to 4 flutes; helix 0 to 45 degrees; runout 0 to R / 20 (half of
// the cases) at any phase; the axis from vertical to 45 degrees; a third of the moves
// turn by 10 to 20 degrees about a random direction; feeds, ramps and steep ramps.
RandomCase randomCase(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> u(0, 1);
  RandomCase rc;
  const CutterType type = n % 3 == 0   ? CutterType::Ball
                          : n % 3 == 1 ? CutterType::Bull
                                       : CutterType::Flat;
  const double R = 1 + 2 * u(rng);
  const double L = R * (1.2 + 2 * u(rng));
  rc.cutter = Cutter::make(type, R, R * (0.2 + 0.6 * u(rng)), L);
  rc.cutter.teeth = CutterTeeth::make(1 + int(4 * u(rng)), 45 * u(rng),
                                      n % 2 ? 0.05 * R * u(rng) : 0, 360 * u(rng), R);
  const double polar = 0.25 * kPi * u(rng), azimuth = 2 * kPi * u(rng);
  rc.a0 = {std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
           std::cos(polar)};
  rc.a1 = turning(n) ? turnedAxis(rng, rc.a0, degToRad(10 + 10 * u(rng))) : rc.a0;
  const double len = 0.5 + 2 * u(rng), dir = 2 * kPi * u(rng);
  const double climb = n % 4 == 0 ? 0 : n % 4 == 3 ? len * (u(rng) - 0.5) : 0.2 * (u(rng) - 0.5);
  rc.p0 = {3 * (u(rng) - 0.5), 3 * (u(rng) - 0.5), -1 + u(rng)};
  rc.p1 = rc.p0 + Vec3{len * std::cos(dir), len * std::sin(dir), climb};
  rc.fz = 0.05 + 0.15 * u(rng);
  rc.phaseDeg = 360 * u(rng);
  return rc;
}

ToolPath onePath(const RandomCase& rc) {
  ToolPath path;
  path.moves.push_back(Move{{rc.p0, rc.a0}, {rc.p1, rc.a1}});
  return path;
}

CuttingModel teethModel(double fz, double phaseDeg) {
  CuttingModel model;
  model.kind = CuttingModelKind::Teeth;
  model.feedPerTooth = fz;
  model.phaseDeg = phaseDeg;
  return model;
}

// phi(t) of a single move (cutting_model.h): phi0 at its start, 2 pi |p1 - p0| /
// (flutes fz) over it.
ref::ToothMove refMove(const RandomCase& rc) {
  return {rc.p0,
          rc.p1,
          rc.a0,
          rc.a1,
          degToRad(rc.phaseDeg),
          2 * kPi * length(rc.p1 - rc.p0) / (rc.cutter.teeth.flutes * rc.fz)};
}

// A point within the envelope's footprint: near the tip's path, inside the solid's
// shadow (the envelope hits the line).
// With `nearAxis`, within fz of the bottom's centre's path, where the edges' angle
// about the line turns fastest.
bool footprintPoint(std::mt19937_64& rng, const RandomCase& rc, const SweptMove& move, double& x,
                    double& y, bool nearAxis = false) {
  std::uniform_real_distribution<double> u(0, 1);
  for (int tries = 0; tries < 50; ++tries) {
    const double t = u(rng), ang = 2 * kPi * u(rng);
    const double rho = nearAxis ? rc.fz * u(rng) : rc.cutter.radius * 1.1 * std::sqrt(u(rng));
    const Vec3 tip = rc.p0 + (rc.p1 - rc.p0) * t + rc.a0 * (nearAxis ? 0 : rc.cutter.cornerRadius);
    x = tip.x + rho * std::cos(ang);
    y = tip.y + rho * std::sin(ang);
    if (move.envelopeLowestPoint(x, y).hit) return true;
  }
  return false;
}

void printCase(const RandomCase& rc, double x, double y) {
  const Cutter& c = rc.cutter;
  std::fprintf(stderr,
               "%s R %.17g r %.17g L %.17g flutes %d helix %.17g runout %.17g phase %.17g\n"
               "  p0 %.17g %.17g %.17g p1 %.17g %.17g %.17g\n"
               "  a0 %.17g %.17g %.17g a1 %.17g %.17g %.17g\n"
               "  fz %.17g phaseDeg %.17g x %.17g y %.17g\n",
               toString(c.type), c.radius, c.cornerRadius, c.fluteLength, c.teeth.flutes,
               c.teeth.helixDeg, c.teeth.runout, c.teeth.runoutPhaseDeg, rc.p0.x, rc.p0.y, rc.p0.z,
               rc.p1.x, rc.p1.y, rc.p1.z, rc.a0.x, rc.a0.y, rc.a0.z, rc.a1.x, rc.a1.y, rc.a1.z,
               rc.fz, rc.phaseDeg, x, y);
}

// The kernel's edge points are the header's definition: the frame (e1 from world X, or
// Y near X; carried with the turn), the spindle's sense, the helix and the runout.
TEST(ToothSweep, EdgePointIsTheHeadersDefinition) {
  std::mt19937_64 rng(180);
  std::uniform_real_distribution<double> u(0, 1);
  double worst = 0;
  for (int n = 0; n < 60; ++n) {
    RandomCase rc = randomCase(rng, n);
    if (n % 10 == 9) rc.a0 = rc.a1 = normalize(Vec3{1, 0.3 * u(rng), 0.4});  // near X
    const ref::ToothMove m = refMove(rc);
    const ToothSweep teeth(rc.cutter, PoseCurve::linear({rc.p0, rc.a0}, {rc.p1, rc.a1}),
                           m.phaseStart, m.phaseRate);
    for (int q = 0; q < 5; ++q) {
      const int k = int(rc.cutter.teeth.flutes * u(rng));
      const double s = ref::edgeLength(rc.cutter) * u(rng), t = u(rng);
      const ref::EdgeSpot spot = ref::edgeSpot(rc.cutter, s);
      const Vec3 want = ref::toothEdgePoint(rc.cutter, m, k, s, t);
      const Vec3 got = teeth.edgePoint(k, spot.h, spot.rho, t);
      worst = std::max(worst, length(got - want));
      EXPECT_LE(length(got - want), 1e-12) << n << " " << q;
    }
  }
  std::printf("ToothSweep edge points: worst |kernel - definition| = %.3g mm\n", worst);
}

TEST(ToothSweep, RandomMovesAgreeWithTheReference) {
  std::mt19937_64 rng(2018);
  int hits = 0, misses = 0, failures = 0, kinds[3] = {0, 0, 0}, turns = 0;
  const unsigned long long unprovenBefore = ToothSweep::unprovenSearches();
  double worst = 0, worstAgreeing = 0, closest = HUGE_VAL;
  ref::ToothStats stats;
  for (int n = 0; n < 120; ++n) {
    const RandomCase rc = randomCase(rng, n);
    const std::vector<SweptMove> moves =
        sweepToolPath(rc.cutter, onePath(rc), teethModel(rc.fz, rc.phaseDeg));
    ASSERT_EQ(moves.size(), 1u);
    const SweptMove& move = moves[0];
    ASSERT_NE(move.teeth(), nullptr);
    EXPECT_EQ(move.turning(), turning(n));
    const ref::ToothMove m = refMove(rc);
    for (int q = 0; q < 3; ++q) {
      double x, y;
      if (!footprintPoint(rng, rc, move, x, y, q == 0)) continue;
      const LowestPoint got = move.lowestPoint(x, y);
      const ref::ToothHit want = ref::toothLowest(rc.cutter, m, x, y, &stats);
      if (got.hit != want.hit) {
        ++failures;
        ADD_FAILURE() << "case " << n << ": kernel hit " << got.hit << " (z " << got.z
                      << "), reference hit " << want.hit << " (z " << want.z << ")";
        printCase(rc, x, y);
        continue;
      }
      if (!got.hit) {
        ++misses;
        continue;
      }
      ++hits;
      ++kinds[n % 3];
      turns += turning(n);
      const double err = std::fabs(got.z - want.z);
      worst = std::max(worst, err);
      if (err <= kHeightToleranceMm) worstAgreeing = std::max(worstAgreeing, err);
      if (err > kHeightToleranceMm) {
        ++failures;
        ADD_FAILURE() << "case " << n << ": kernel " << got.z << " (t " << got.t << "), reference "
                      << want.z << " (t " << want.t << ", tooth " << want.tooth << ", u " << want.u
                      << ")";
        printCase(rc, x, y);
      }
      // The teeth cut no deeper than the envelope, their proven lower bound.
      const LowestPoint env = move.envelopeLowestPoint(x, y);
      ASSERT_TRUE(env.hit);
      closest = std::min(closest, got.z - env.z);
      EXPECT_GE(got.z, env.z - 1e-9) << "case " << n;
    }
  }
  std::printf(
      "ToothSweep random: %d hits (ball %d, bull %d, flat %d; %d turning), %d misses, %d "
      "failures; worst |kernel - reference| = %.3g mm (%.3g mm where within 1e-6); least teeth - "
      "envelope %.3g mm; "
      "reference %ld cells, %ld near-crossings\n",
      hits, kinds[0], kinds[1], kinds[2], turns, misses, failures, worst, worstAgreeing, closest,
      stats.cells, stats.nearCrossings);
  EXPECT_GE(hits, 250);
  EXPECT_GE(turns, 70);
  EXPECT_EQ(ToothSweep::unprovenSearches(), unprovenBefore);
  EXPECT_EQ(stats.nearCrossings, 0);
}

// Vertical cutters on lines near the tip's path, where every tooth passes close to the
// line at its slowest and the edges' angle about the line turns faster than the spindle
// (closer than about flutes fz / pi): the kernel's hardest lines in the most common pose.
TEST(ToothSweep, VerticalCuttersNearThePath) {
  const unsigned long long unprovenBefore = ToothSweep::unprovenSearches();
  double worst = 0;
  for (const Cutter& base :
       {Cutter::make(CutterType::Ball, 3), Cutter::make(CutterType::Bull, 3, 1),
        Cutter::make(CutterType::Flat, 3)}) {
    Cutter c = base;
    c.teeth = CutterTeeth::make(2, 0, 0, 0, 3);
    RandomCase rc;
    rc.cutter = c;
    rc.p0 = {-4, 0, -0.1};
    rc.p1 = {5, 0, -0.1};
    rc.a0 = rc.a1 = {0, 0, 1};
    rc.fz = 0.1;
    const SweptMove move = sweepToolPath(c, onePath(rc), teethModel(rc.fz, 0))[0];
    for (double y : {0.0, 0.001, 0.01, 0.03, 0.06, 0.11}) {
      const double x = 0.31 + y;
      const LowestPoint got = move.lowestPoint(x, y);
      const ref::ToothHit want = ref::toothLowest(c, refMove(rc), x, y);
      ASSERT_TRUE(got.hit && want.hit) << toString(c.type) << " " << y;
      EXPECT_NEAR(got.z, want.z, kHeightToleranceMm) << toString(c.type) << " " << y;
      worst = std::max(worst, std::fabs(got.z - want.z));
    }
  }
  std::printf("ToothSweep vertical near the path: worst %.3g mm, %llu unproven searches\n", worst,
              ToothSweep::unprovenSearches() - unprovenBefore);
  EXPECT_EQ(ToothSweep::unprovenSearches(), unprovenBefore);
}

// Outside the envelope's footprint no edge reaches the line: a miss, for the kernel and
// the reference alike.
TEST(ToothSweep, MissOutsideTheFootprint) {
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> u(0, 1);
  int outside = 0;
  for (int n = 0; n < 60; ++n) {
    const RandomCase rc = randomCase(rng, n);
    const SweptMove move = sweepToolPath(rc.cutter, onePath(rc), teethModel(rc.fz, rc.phaseDeg))[0];
    const Box3 box = move.bounds();
    for (int q = 0; q < 6; ++q) {
      // Around the bounds, a margin of a radius on each side.
      const double m = rc.cutter.radius;
      const double x = box.min.x - m + (box.max.x - box.min.x + 2 * m) * u(rng);
      const double y = box.min.y - m + (box.max.y - box.min.y + 2 * m) * u(rng);
      if (move.envelopeLowestPoint(x, y).hit) continue;
      ++outside;
      EXPECT_FALSE(move.lowestPoint(x, y).hit) << n;
      EXPECT_FALSE(ref::toothLowest(rc.cutter, refMove(rc), x, y).hit) << n;
    }
  }
  EXPECT_GE(outside, 60);
}

// The cutoff only turns crossings at or above it into misses (tooth_sweep.h).
TEST(ToothSweep, HeightDoesNotDependOnTheCutoff) {
  std::mt19937_64 rng(5);
  int checked = 0;
  for (int n = 0; n < 30; ++n) {
    const RandomCase rc = randomCase(rng, n);
    const SweptMove move = sweepToolPath(rc.cutter, onePath(rc), teethModel(rc.fz, rc.phaseDeg))[0];
    double x, y;
    if (!footprintPoint(rng, rc, move, x, y)) continue;
    const LowestPoint free = move.lowestPoint(x, y);
    if (!free.hit) continue;
    for (double above : {1e-9, 1e-6, 1e-3, 1.0}) {
      const LowestPoint cut = move.lowestPoint(x, y, nullptr, free.z + above);
      ASSERT_TRUE(cut.hit) << n;
      EXPECT_EQ(cut.z, free.z) << n;
    }
    EXPECT_FALSE(move.lowestPoint(x, y, nullptr, free.z - 1e-9).hit) << n;
    ++checked;
  }
  EXPECT_GE(checked, 20);
}

// The spindle angle runs along the whole path in file order, rapids included, and a
// move's own feed per tooth replaces the job's (cutting_model.h, pose.h): a path of a
// feed, a rapid and a feed at its own fz, each cutting move checked against the
// reference with the angle computed here.
TEST(ToothSweep, SpindleAngleRunsAlongThePathRapidsIncluded) {
  Cutter c = Cutter::make(CutterType::Bull, 2, 0.5, 4);
  c.teeth = CutterTeeth::make(3, 30, 0.04, 70, 2);
  const Vec3 a = normalize(Vec3{0.2, -0.1, 1});
  const Vec3 p0{0, 0, 0}, p1{1.3, 0.4, -0.1}, p2{1.3, 2.2, 2}, p3{1.3, 4.0, 0.1}, p4{2.0, 5.1, 0};
  ToolPath path;
  path.moves.push_back(Move{{p0, a}, {p1, a}});
  path.moves.push_back(Move{{p1, a}, {p2, a}, true});  // rapid
  path.moves.push_back(Move{{p2, a}, {p3, a}, true});  // rapid
  Move own{{p3, a}, {p4, a}};
  own.feedPerTooth = 0.07;
  path.moves.push_back(own);
  const double fz = 0.11, phaseDeg = 25;
  const std::vector<SweptMove> moves = sweepToolPath(c, path, teethModel(fz, phaseDeg));
  ASSERT_EQ(moves.size(), 2u);
  const double rate = 2 * kPi / (3 * fz);  // rad per mm
  const double phiAtP3 =
      degToRad(phaseDeg) + rate * (length(p1 - p0) + length(p2 - p1) + length(p3 - p2));
  const ref::ToothMove m0{p0, p1, a, a, degToRad(phaseDeg), rate * length(p1 - p0)};
  const ref::ToothMove m1{p3, p4, a, a, phiAtP3, 2 * kPi * length(p4 - p3) / (3 * 0.07)};
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  int compared = 0;
  double worst = 0;
  for (int i = 0; i < 2; ++i) {
    const ref::ToothMove& m = i ? m1 : m0;
    for (int q = 0; q < 12; ++q) {
      const Vec3 tip = m.p0 + (m.p1 - m.p0) * u(rng);
      const double x = tip.x + 2 * (u(rng) - 0.5), y = tip.y + 2 * (u(rng) - 0.5);
      const LowestPoint got = moves[size_t(i)].lowestPoint(x, y);
      const ref::ToothHit want = ref::toothLowest(c, m, x, y);
      ASSERT_EQ(got.hit, want.hit) << i << " " << q;
      if (!got.hit) continue;
      EXPECT_NEAR(got.z, want.z, kHeightToleranceMm) << i << " " << q;
      worst = std::max(worst, std::fabs(got.z - want.z));
      ++compared;
    }
  }
  std::printf("ToothSweep path phase: %d compared, worst %.3g mm\n", compared, worst);
  EXPECT_GE(compared, 16);
}

// General cutters (profile_cases.h: tapered balls and bulls, cones, barrels, lenses,
// ovals, free chains) with teeth against the reference walking their chain by arc
// length: constant and turning axes (10 to 20 degrees a move), feeds and ramps, runout,
// and on some straight moves tooth offsets (the chain moved out, the tip lowered).
TEST(ToothSweep, ProfileCuttersAgreeWithTheReference) {
  std::mt19937_64 rng(3301);
  std::uniform_real_distribution<double> u(0, 1);
  const unsigned long long unprovenBefore = ToothSweep::unprovenSearches();
  int hits = 0, turns = 0, offsets = 0;
  double worst = 0;
  ref::ToothStats stats;
  for (int n = 0; n < 18; ++n) {
    RandomCase rc = randomCase(rng, n);  // its move and teeth; the cutter replaced
    const test::ProfileCase shape = test::randomProfileCase(rng, n);
    const CutterTeeth teeth = rc.cutter.teeth;
    rc.cutter = shape.cutter();
    rc.cutter.teeth = CutterTeeth::make(teeth.flutes, teeth.helixDeg,
                                        std::min(teeth.runout, 0.05 * rc.cutter.radius),
                                        teeth.runoutPhaseDeg, rc.cutter.radius);
    if (n % 4 == 1 && !turning(n)) {
      for (int k = 0; k < rc.cutter.teeth.flutes; ++k)
        rc.cutter.teeth.editToothOffsets().push_back(
            {k == 0 ? 0.0 : 0.03 * rc.cutter.radius * u(rng), k == 0 ? 0.0 : 0.02 * u(rng)});
      ++offsets;
    }
    const std::vector<SweptMove> moves =
        sweepToolPath(rc.cutter, onePath(rc), teethModel(rc.fz, rc.phaseDeg));
    ASSERT_EQ(moves.size(), 1u);
    ASSERT_NE(moves[0].teeth(), nullptr);
    const ref::ToothMove m = refMove(rc);
    for (int q = 0; q < 2; ++q) {
      double x, y;
      if (!footprintPoint(rng, rc, moves[0], x, y, q == 0)) continue;
      const LowestPoint got = moves[0].lowestPoint(x, y);
      const ref::ToothHit want = ref::toothLowest(rc.cutter, m, x, y, &stats);
      ASSERT_EQ(got.hit, want.hit)
          << shape.name << " case " << n << " z " << got.z << " / " << want.z;
      if (!got.hit) continue;
      ++hits;
      turns += turning(n);
      const double err = std::fabs(got.z - want.z);
      worst = std::max(worst, err);
      EXPECT_LE(err, kHeightToleranceMm)
          << shape.name << " case " << n << ": kernel " << got.z << ", reference " << want.z;
      if (err > kHeightToleranceMm) printCase(rc, x, y);
      EXPECT_GE(got.z, moves[0].envelopeLowestPoint(x, y).z - 1e-9) << "case " << n;
    }
  }
  std::printf(
      "ToothSweep profiles: %d hits (%d turning, %d cutters with offsets); worst |kernel - "
      "reference| = %.3g mm; reference %ld cells, %ld near-crossings\n",
      hits, turns, offsets, worst, stats.cells, stats.nearCrossings);
  EXPECT_GE(hits, 28);
  EXPECT_GE(turns, 8);
  EXPECT_EQ(ToothSweep::unprovenSearches(), unprovenBefore);
  EXPECT_EQ(stats.nearCrossings, 0);
}

}  // namespace
}  // namespace scallop
