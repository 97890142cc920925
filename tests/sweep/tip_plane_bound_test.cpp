// Independent checks of the tip-plane bound (sweep/tip_plane_bound.h):
//   * it is a lower bound: on a grid of lines over the rectangle it was made for, no
//     cutter of the move, at any of 1001 instants, has its lowest point (the brute-force
//     reference's stationaryLowest, written from the cutter's definition, sharing no
//     code with sweep/) below it; for ball, bull and flat cutters, slerp turns up to
//     90 degrees, rotary (TCP on) and joint-linear (TCP off) machine curves, with the
//     poses written here from the conventions' formulas;
//   * it is tight where it is meant to be: under the flat bottom of a bull cutter on a
//     B3-like move (5-axis finishing, the axis turning 0.6 degrees a move) it lies
//     within 0.5 um of the reference's height of the swept solid;
//   * it gives up (-inf) on an axis leaning to the horizontal, where its argument fails.
#include "sweep/tip_plane_bound.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "base/constants.h"
#include "sweep/brute_force_reference.h"
#include "sweep/cutter.h"
#include "sweep/pose_curve.h"
#include "tests/support/random_cases.h"

namespace scallop {
namespace {

using Move = test::CheckedCurve;

std::vector<Move> randomMoves(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Move> out;
  for (int k = 0; k < 12; ++k) {  // slerp: turns from none to 90 degrees, plunges too
    const Vec3 p0{u(rng), u(rng), u(rng)};
    const Vec3 p1 = k % 4 == 3 ? p0 + Vec3{0, 0, -0.5} : Vec3{3 * u(rng), 3 * u(rng), u(rng)};
    const Vec3 a0 = ref::unitFromAngles(0.6 * (1 + u(rng)) * 0.5, kPi * u(rng));
    const double turn = (k % 3) * 0.25 * kPi;  // 0, 45 and 90 degrees
    const Vec3 w = normalize(cross(a0, Vec3{u(rng), u(rng), u(rng)}));
    Vec3 a1 = a0 * std::cos(turn) + cross(w, a0) * std::sin(turn);
    if (a1.z < 0.05) a1 = normalize(Vec3{a1.x, a1.y, 0.05});  // never below the horizontal
    out.push_back({"slerp " + std::to_string(k), PoseCurve::linear({p0, a0}, {p1, a1}),
                   [=](double t) { return p0 + (p1 - p0) * t; },
                   [=](double t) { return ref::slerp(a0, a1, t); }});
  }
  for (int k = 0; k < 4; ++k) {  // rotary, TCP on
    const RotaryKinematics kin = k % 2 ? RotaryKinematics::TableAC : RotaryKinematics::TableBC;
    out.push_back(
        test::randomRotaryCurve("rotary " + std::to_string(k), rng, kin, {0.6, 0.3, 3, 1.0}));
  }
  for (int k = 0; k < 4; ++k) {  // joint-linear, TCP off: the tip on a curve
    const RotaryKinematics kin = k % 2 ? RotaryKinematics::TableAC : RotaryKinematics::TableBC;
    const test::MachineMove move =
        test::randomMachineMove(rng, kin, {5, 2, 20, 5, 0.5, 0.05, 3, 0.1, 5, 1});
    out.push_back(test::jointLinearCurve("joint-linear " + std::to_string(k), move));
  }
  return out;
}

TEST(TipPlaneBound, NoCutterPointBelowIt) {
  std::mt19937_64 rng(1701);
  std::uniform_real_distribution<double> u(-1, 1);
  const ref::RefCutter cutters[] = {ref::makeRefCutter(CutterType::Ball, 2),
                                    ref::makeRefCutter(CutterType::Bull, 3, 1),
                                    ref::makeRefCutter(CutterType::Flat, 1.5)};
  int finite = 0, checked = 0;
  for (const Move& mv : randomMoves(rng)) {
    for (const ref::RefCutter& c : cutters) {
      // A rectangle round the move's start, up to a cutter radius across.
      const Vec3 centre = mv.tip(0);
      const double x0 = centre.x + c.R * u(rng), y0 = centre.y + c.R * u(rng);
      const double x1 = x0 + c.R * (1 + u(rng)), y1 = y0 + c.R * (1 + u(rng));
      const TipPlaneBound bound = tipPlaneBound(mv.curve, x0, y0, x1, y1);
      for (int i = 0; i <= 4; ++i) {
        for (int j = 0; j <= 4; ++j) {
          const double x = x0 + (x1 - x0) * i / 4, y = y0 + (y1 - y0) * j / 4;
          const double b = bound.at(x, y);
          if (!std::isfinite(b)) continue;
          ++finite;
          double lowest = HUGE_VAL;
          for (int s = 0; s <= 1000; ++s) {
            const double t = s / 1000.0;
            const ref::RefHit hit = ref::stationaryLowest(c, mv.tip(t), mv.axis(t), x, y);
            if (hit.hit) lowest = std::fmin(lowest, hit.z);
          }
          if (lowest < HUGE_VAL) ++checked;
          EXPECT_LE(b, lowest) << mv.name << " R " << c.R << " r " << c.r << " at (" << x << ", "
                               << y << ")";
        }
      }
    }
  }
  // The argument applies to every move but those turning by more than a_z(0) + a_z(1)
  // radians (here the 90-degree slerps), and many lines meet the cutters.
  EXPECT_GT(finite, 600);
  EXPECT_GT(checked, 300) << finite;
}

// B3's moves: bull R3 r1, the tip 0.05 mm along X on the surface's slope, the axis the
// surface normal leaned 5 degrees along the feed, turning about 0.01 rad in the move.
TEST(TipPlaneBound, MeetsTheHeightUnderABottomFace) {
  const ref::RefCutter c = ref::makeRefCutter(CutterType::Bull, 3, 1);
  const Vec3 p0{0, 0, 0}, p1{0.05, 0, 0.004};
  const Vec3 a0 = ref::unitFromAngles(0.15, 0.1), a1 = ref::unitFromAngles(0.16, 0.1);
  const PoseCurve curve = PoseCurve::linear({p0, a0}, {p1, a1});
  const ref::RefCurve refCurve{p0, p1, [&](double t) { return ref::slerp(a0, a1, t); }};
  const TipPlaneBound bound = tipPlaneBound(curve, -1.5, -1.5, 1.5, 1.5);
  double worst = 0;
  int lines = 0;
  for (double x = -1.5; x <= 1.5; x += 0.25) {
    for (double y = -1.5; y <= 1.5; y += 0.25) {
      const ref::RefHit h = ref::turningLowest(c, refCurve, x, y);
      ASSERT_TRUE(h.hit);
      // Only lines that meet the bottom face: the reference's lowest point lies in the
      // tip plane of some pose (within the face's radius Rb of the tip).
      bool onFace = false;
      for (int s = 0; s <= 100 && !onFace; ++s) {
        const double t = s / 100.0;
        const Vec3 tip = p0 + (p1 - p0) * t, a = ref::slerp(a0, a1, t);
        const Vec3 q = Vec3{x, y, h.z} - tip;
        onFace = std::fabs(dot(q, a)) < 1e-6 && length(q) < c.Rb() - 0.1;
      }
      if (!onFace) continue;
      ++lines;
      const double b = bound.at(x, y);
      EXPECT_LE(b, h.z) << "(" << x << ", " << y << ")";
      worst = std::fmax(worst, h.z - b);
    }
  }
  EXPECT_GT(lines, 50);
  EXPECT_LT(worst, 5e-4) << "mm: the bound should follow the turning face";
}

TEST(TipPlaneBound, GivesUpOnAnAxisLeaningToTheHorizontal) {
  const Vec3 a0 = normalize(Vec3{1, 0, 0.01}), a1 = normalize(Vec3{0, 1, 0.01});
  const PoseCurve curve = PoseCurve::linear({{0, 0, 0}, a0}, {{1, 0, 0}, a1});
  const TipPlaneBound bound = tipPlaneBound(curve, -1, -1, 1, 1);
  EXPECT_EQ(bound.at(0, 0), -HUGE_VAL);
  EXPECT_EQ(bound.minOver(-1, -1, 1, 1), -HUGE_VAL);
}

}  // namespace
}  // namespace scallop
