// Per-tooth geometry and the spindle's direction (sweep/tooth_geometry.h, tooth_sweep.h):
// the kernel against the independent reference (tooth_reference.h) with tooth offsets,
// unequal pitch and a counter-clockwise spindle; the closed form of one tooth lower than
// the threshold (docs/teeth.md); a CCW move equal, bit for bit, to the mirrored CW move;
// zero offsets and equal pitch given explicitly equal to the defaults, bit for bit; the
// values refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>

#include "base/constants.h"
#include "base/input_error.h"
#include "sweep/profile_cases.h"
#include "sweep/tool_path_sweep.h"
#include "sweep/tooth_cases.h"
#include "sweep/tooth_reference.h"
#include "sweep/tooth_sweep.h"
#include "tests/support/input_error_message.h"

namespace scallop {
namespace {

std::vector<SweptMove> sweepMoves(const Cutter& c, const Vec3& p0, const Vec3& p1, const Vec3& a0,
                                  const Vec3& a1, const CuttingModel& model) {
  ToolPath path;
  path.moves.push_back(Move{{p0, a0}, {p1, a1}});
  return sweepToolPath(c, path, model);
}

bool sameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(ToothGeometry, BadValuesNameTheirEntry) {
  const std::vector<ToothOffset> none;
  expectRejected(
      [&] {
        checkToothGeometry({0, 90, 180}, none, 2, 3, 0, "tool");
      },
      "tool.tooth_angles_deg");
  expectRejected(
      [&] {
        checkToothGeometry({10, 180}, none, 2, 3, 0, "tool");
      },
      "tool.tooth_angles_deg[0]");
  expectRejected(
      [&] {
        checkToothGeometry({0, 180, 170}, none, 3, 3, 0, "tools.2");
      },
      "tools.2.tooth_angles_deg[2]");
  expectRejected(
      [&] {
        checkToothGeometry({0, 360}, none, 2, 3, 0, "tool");
      },
      "tool.tooth_angles_deg[1]");
  expectRejected([&] { checkToothGeometry({}, {{0, 0}}, 2, 3, 0, "tool"); }, "tool.tooth_offsets");
  expectRejected(
      [&] {
        checkToothGeometry({}, {{0, 0}, {0, 0.31}}, 2, 3, 0, "tool");
      },
      "tool.tooth_offsets[1]");
  expectRejected(
      [&] {
        checkToothGeometry({}, {{0, 0}, {NAN, 0}}, 2, 3, 0, "tool");
      },
      "tool.tooth_offsets[1]");
  // A ball's edge starts on the axis: a radial offset inwards would carry it across.
  expectRejected(
      [&] {
        checkToothGeometry({}, {{-0.001, 0}, {0, 0}}, 2, 3, 0, "tool");
      },
      "tool.tooth_offsets[0][0]");
  checkToothGeometry({0, 170}, {{-0.001, 0.002}, {0.003, -0.004}}, 2, 3, 1, "tool");
}

// Explicit zero offsets and equal pitch as angles are the defaults, bit for bit.
TEST(ToothGeometry, ZeroOffsetsAndEqualAnglesGiveTheDefaultsBits) {
  Cutter plain = Cutter::make(CutterType::Bull, 2, 0.5, 4);
  plain.teeth = CutterTeeth::make(3, 20, 0.01, 40, 2);
  Cutter spelled = plain;
  spelled.teeth.editToothAnglesDeg() = {0, 120, 240};
  spelled.teeth.editToothOffsets() = {{0, 0}, {0, 0}, {0, 0}};
  const Vec3 a = normalize(Vec3{0.2, 0.1, 1});
  const CuttingModel model = teethModel(0.08, 30);
  const auto m0 = sweepMoves(plain, {0, 0, 0}, {1.5, 0.2, -0.1}, a, a, model);
  const auto m1 = sweepMoves(spelled, {0, 0, 0}, {1.5, 0.2, -0.1}, a, a, model);
  int hits = 0;
  for (int i = 0; i < 40; ++i) {
    const double x = -1 + 3.5 * i / 40, y = 0.3 * std::sin(i);
    const LowestPoint p = m0[0].lowestPoint(x, y), q = m1[0].lowestPoint(x, y);
    ASSERT_EQ(p.hit, q.hit);
    if (!p.hit) continue;
    ++hits;
    EXPECT_TRUE(sameBits(p.z, q.z)) << i << ": " << p.z << " " << q.z;
  }
  EXPECT_GE(hits, 25);
}

// Random cutters with offsets, unequal pitch and either spindle direction against the
// reference: constant axes (a tooth may reach below the tip) and turning axes (teeth
// only raised or moved radially).
TEST(ToothGeometry, OffsetsPitchAndDirectionAgreeWithTheReference) {
  std::mt19937_64 rng(3535);
  std::uniform_real_distribution<double> u(0, 1);
  const unsigned long long unprovenBefore = ToothSweep::unprovenSearches();
  int hits = 0, ccw = 0;
  double worst = 0;
  for (int n = 0; n < 24; ++n) {
    const CutterType type = n % 3 == 0   ? CutterType::Ball
                            : n % 3 == 1 ? CutterType::Bull
                                         : CutterType::Flat;
    const double R = 1 + u(rng);
    Cutter c = Cutter::make(type, R, 0.4 * R, 2 * R);
    const int flutes = 2 + n % 3;
    c.teeth = CutterTeeth::make(flutes, n % 2 ? 30 * u(rng) : 0, n % 4 == 1 ? 0.02 * R : 0,
                                360 * u(rng), R);
    const bool turns = n % 4 == 3;
    if (n % 2 == 0) {  // unequal pitch: each tooth up to 20 degrees off its place
      for (int k = 0; k < flutes; ++k)
        c.teeth.editToothAnglesDeg().push_back(k == 0 ? 0
                                                      : 360.0 * k / flutes + 40 * (u(rng) - 0.5));
    }
    for (int k = 0; k < flutes; ++k) {
      const double radial = type == CutterType::Ball ? 0.01 * u(rng) : 0.02 * (u(rng) - 0.5);
      const double axial = turns ? -0.01 * u(rng) : 0.02 * (u(rng) - 0.5);
      c.teeth.editToothOffsets().push_back({radial, axial});
    }
    checkToothGeometry(c.teeth.toothAnglesDeg(), c.teeth.toothOffsets(), flutes, R,
                       c.bottomRadius(), "tool");
    const double tilt = 0.5 * u(rng), az = 2 * kPi * u(rng);
    const Vec3 a0{std::sin(tilt) * std::cos(az), std::sin(tilt) * std::sin(az), std::cos(tilt)};
    const Vec3 a1 = turns ? normalize(a0 + Vec3{0.15, -0.1, 0}) : a0;
    const Vec3 p0{0, 0, 0},
        p1{0.8 * std::cos(az + 1), 0.8 * std::sin(az + 1), 0.1 * (u(rng) - 0.5)};
    const double fz = 0.05 + 0.1 * u(rng), phaseDeg = 360 * u(rng);
    const bool counter = n % 3 != 1;
    ccw += counter;
    const auto moves = sweepMoves(c, p0, p1, a0, a1, teethModel(fz, phaseDeg, counter));
    ASSERT_EQ(moves.size(), 1u);
    const ref::ToothMove m{
        p0, p1, a0, a1, degToRad(phaseDeg), 2 * kPi * length(p1 - p0) / (flutes * fz), counter};
    for (int q = 0; q < 3; ++q) {
      const double t = u(rng), ang = 2 * kPi * u(rng), rho = R * std::sqrt(u(rng));
      const Vec3 at = p0 + (p1 - p0) * t;
      const double x = at.x + rho * std::cos(ang), y = at.y + rho * std::sin(ang);
      const LowestPoint got = moves[0].lowestPoint(x, y);
      const ref::ToothHit want = ref::toothLowest(c, m, x, y);
      ASSERT_EQ(got.hit, want.hit) << n << " " << q << " " << got.z << " " << want.z;
      if (!got.hit) continue;
      ++hits;
      worst = std::max(worst, std::fabs(got.z - want.z));
      EXPECT_NEAR(got.z, want.z, kHeightToleranceMm) << n << " " << q;
      // The envelope (grown and lowered by the offsets) stays a lower bound.
      EXPECT_GE(got.z, moves[0].envelopeLowestPoint(x, y).z - 1e-9) << n;
    }
  }
  std::printf("ToothGeometry random: %d hits (%d CCW cases), worst |kernel - reference| %.3g mm\n",
              hits, ccw, worst);
  EXPECT_GE(hits, 45);
  EXPECT_EQ(ToothSweep::unprovenSearches(), unprovenBefore);
}

// A CCW move computes what the CW move mirrored in y = 0 computes: the heights at
// (x, y) and (x, -y) are the same bits (the envelope alone is not mirror-exact: its
// section frame is not, and the search starts from its lowest point). Vertical, tilted
// and turning axes, runout, helix, offsets, unequal pitch.
TEST(ToothGeometry, CounterClockwiseIsTheMirroredClockwiseBitForBit) {
  std::mt19937_64 rng(44);
  std::uniform_real_distribution<double> u(0, 1);
  int hits = 0, differ = 0;
  for (int n = 0; n < 8; ++n) {
    Cutter c = Cutter::make(n % 2 ? CutterType::Bull : CutterType::Ball, 2, 0.6, 5);
    c.teeth = CutterTeeth::make(2 + n % 2, 25, 0.01, 70, 2);
    if (n % 3)
      c.teeth.editToothAnglesDeg() =
          n % 2 ? std::vector<double>{0, 100, 250} : std::vector<double>{0, 170};
    c.teeth.editToothOffsets().assign(size_t(c.teeth.flutes), ToothOffset{0.003, 0});
    c.teeth.editToothOffsets()[1] = {0.001, n < 6 ? 0.004 : -0.004};
    const Vec3 a = n < 2 ? Vec3{0, 0, 1} : normalize(Vec3{0.3, 0.2 * (n - 3), 1});
    const Vec3 a1 = n < 6 ? a : normalize(a + Vec3{-0.1, 0.2, 0});
    const Vec3 p0{0.1, 0.2, 0}, p1{1.3, -0.4, -0.2};
    const auto mirror = [](const Vec3& v) { return Vec3{v.x, -v.y, v.z}; };
    const auto ccw = sweepMoves(c, p0, p1, a, a1, teethModel(0.1, 17, true));
    const auto cw =
        sweepMoves(c, mirror(p0), mirror(p1), mirror(a), mirror(a1), teethModel(0.1, 17));
    const auto plain = sweepMoves(c, p0, p1, a, a1, teethModel(0.1, 17));
    ASSERT_EQ(ccw[0].turning(), n >= 6);
    for (int i = 0; i < 30; ++i) {
      const Vec3 at = p0 + (p1 - p0) * u(rng);
      const double x = at.x + 2 * (u(rng) - 0.5), y = at.y + 2 * (u(rng) - 0.5);
      const LowestPoint p = ccw[0].lowestPoint(x, y), q = cw[0].lowestPoint(x, -y);
      ASSERT_EQ(p.hit, q.hit);
      if (!p.hit) continue;
      ++hits;
      EXPECT_TRUE(sameBits(p.z, q.z)) << n << " " << i << ": " << p.z << " " << q.z;
      differ += std::fabs(p.z - plain[0].lowestPoint(x, y).z) > 1e-6;
    }
  }
  EXPECT_GE(hits, 100);
  EXPECT_GE(differ, hits / 4);  // and CCW is not CW: the marks differ
}

// Ball R, lead lambda along +X, two flutes, tooth 1 reaching delta further along the
// axis (tooth_offsets [[0, 0], [0, delta]]). As for the runout (docs/teeth.md), on the
// pass centre line each tooth leaves the meridian arcs of its passes, tooth 1's centred
// at tip + (R - delta) a: delta cos(lambda) lower and delta sin(lambda) back along the
// feed. Above the threshold delta* = (sqrt(R^2 cos^2 + fz^2 sin^2) - R cos) / sin^2
// (docs/teeth.md) tooth 0 never cuts there: the height is the least of tooth 1's arcs
// alone, 2 fz apart. Below it tooth 0 cuts too, and the heights are lower somewhere.
// Either spindle direction: at a pass the edge is in the plane of e1 either way.
TEST(ToothGeometry, OneToothLowerThanTheThresholdFinishesAlone) {
  const double R = 3, lambda = degToRad(15), fz = 0.1, phi0 = 0.3;
  const double sl = std::sin(lambda), cl = std::cos(lambda);
  const double threshold = (std::sqrt(R * R * cl * cl + fz * fz * sl * sl) - R * cl) / (sl * sl);
  EXPECT_NEAR(threshold, 1.7254e-3, 1e-6);
  const Vec3 a{sl, 0, cl}, p0{-1, 0, 0}, p1{1, 0, 0};
  const double rate = 2 * kPi * length(p1 - p0) / (2 * fz);
  for (const double delta : {3 * threshold, 0.3 * threshold}) {
    for (const bool ccw : {false, true}) {
      Cutter c = Cutter::make(CutterType::Ball, R, 0, 4 * R);
      c.teeth = CutterTeeth::make(2, 0, 0, 0, R);
      c.teeth.editToothOffsets() = {{0, 0}, {0, delta}};
      const auto moves = sweepMoves(c, p0, p1, a, a, teethModel(fz, radToDeg(phi0), ccw));
      double worst = 0, below = 0;
      for (int i = 0; i <= 40; ++i) {
        const double x = -0.3 + 0.6 * i / 40 + 0.0013;
        double lone = HUGE_VAL;  // tooth 1's arcs alone
        for (int w = -40; w <= 40; ++w) {
          const double t = (kPi + 2 * kPi * w - phi0) / rate;
          if (t < 0 || t > 1) continue;
          const Vec3 centre = p0 + (p1 - p0) * t + a * (R - delta);
          const double dx = x - centre.x;
          if (std::fabs(dx) <= R * cl) lone = std::min(lone, centre.z - std::sqrt(R * R - dx * dx));
        }
        const LowestPoint got = moves[0].lowestPoint(x, 0);
        ASSERT_TRUE(got.hit);
        worst = std::max(worst, std::fabs(got.z - lone));
        below = std::max(below, lone - got.z);
      }
      if (delta > threshold) {
        EXPECT_LE(worst, 1e-9) << ccw;
      } else {
        EXPECT_GT(below, 1e-5) << ccw;  // tooth 0 cuts below tooth 1's arcs
      }
    }
  }
}

TEST(ToothGeometry, ToothReachingBelowTheTipNeedsAConstantAxis) {
  Cutter c = Cutter::make(CutterType::Ball, 2);
  c.teeth.editToothOffsets() = {{0, 0.001}, {0, 0}};
  const CuttingModel model = teethModel(0.1, 0);
  try {
    sweepMoves(c, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}, normalize(Vec3{0.2, 0, 1}), model);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("tooth_offsets"), std::string::npos) << e.what();
  }
  c.teeth.editToothOffsets() = {{0, -0.001}, {0.002, 0}};  // raised, or out: any move
  EXPECT_EQ(
      sweepMoves(c, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}, normalize(Vec3{0.2, 0, 1}), model).size(), 1u);
}

// A tooth moved out by dr > 0 starts dr from the axis: on a plunge (every tooth moved out)
// the lines within dr of the axis meet no edge, a pillar of radius dr stands (before, the
// group's solid, whose widened flat bottom reaches the axis, cut it). Moved in (dr < 0),
// the edge ends at the axis. Flat, bull, ball and a tapered ball (a general chain) on a
// plunge and a steep tilted ramp, against the reference.
TEST(ToothGeometry, AnEdgeMovedOutStartsThatFarFromTheAxis) {
  std::mt19937_64 rng(45);
  std::uniform_real_distribution<double> u(0, 1);
  const Cutter shapes[] = {
      Cutter::make(CutterType::Flat, 1, 0, 3), Cutter::make(CutterType::Bull, 1, 0.3, 3),
      Cutter::make(CutterType::Ball, 1, 1, 3), test::randomProfileCase(rng, 0).cutter()};
  int pillar = 0, hits = 0;
  for (int n = 0; n < 12; ++n) {
    Cutter c = shapes[n % 4];
    // Moved in only where a flat bottom leaves room (the job's rule, tooth_geometry.h).
    const double rb = c.general() ? c.profile->bottomRadius() : c.bottomRadius();
    const double R = c.radius, dr = (n / 4 == 1 && rb > 0 ? -0.04 : 0.04) * R;
    // Three teeth: an edge passing the axis would lie between two others (with two it
    // would lie on the other's place and change nothing).
    c.teeth = CutterTeeth::make(3, 0, 0, 0, R);
    c.teeth.editToothOffsets().assign(3, ToothOffset{dr, 0});
    const bool ramp = n / 4 == 2;
    const Vec3 a = ramp ? normalize(Vec3{0.1, 0.05, 1}) : Vec3{0, 0, 1};
    const Vec3 p0{0, 0, 0.4}, p1{ramp ? 0.05 : 0.0, 0, -0.3};
    const double fz = 0.05, phaseDeg = 30;
    const auto moves = sweepMoves(c, p0, p1, a, a, teethModel(fz, phaseDeg));
    const ref::ToothMove m{p0, p1, a, a, degToRad(phaseDeg), 2 * kPi * length(p1 - p0) / (3 * fz)};
    for (double d : {0.2, 0.6, 0.9, 1.2, 3.0, 8.0}) {
      const double ang = 2 * kPi * u(rng), dist = d * std::abs(dr);
      const double x = p1.x + dist * std::cos(ang), y = p1.y + dist * std::sin(ang);
      const LowestPoint got = moves[0].lowestPoint(x, y);
      const ref::ToothHit want = ref::toothLowest(c, m, x, y);
      ASSERT_EQ(got.hit, want.hit) << n << " d " << d << " z " << got.z << " / " << want.z;
      if (!ramp && dr > 0 && d < 1) {
        EXPECT_FALSE(got.hit) << n << " d " << d;
        ++pillar;
      }
      if (!got.hit) continue;
      ++hits;
      EXPECT_NEAR(got.z, want.z, kHeightToleranceMm) << n << " d " << d;
    }
  }
  EXPECT_EQ(pillar, 18);
  EXPECT_GE(hits, 30);
}

// The envelope model ignores the teeth keys, tooth_offsets included (docs/teeth.md).
TEST(ToothGeometry, EnvelopeModelIgnoresTheOffsets) {
  Cutter c = Cutter::make(CutterType::Ball, 2);
  const auto plain = sweepMoves(c, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0, 0, 1}, {});
  c.teeth.editToothOffsets() = {{0.01, 0.01}, {0, 0}};
  const auto offset = sweepMoves(c, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0, 0, 1}, {});
  for (double x : {-1.0, 0.3, 0.9})
    EXPECT_TRUE(sameBits(plain[0].lowestPoint(x, 0.4).z, offset[0].lowestPoint(x, 0.4).z));
}

}  // namespace
}  // namespace scallop
