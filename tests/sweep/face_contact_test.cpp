// Independent checks of the flat bottom face's contact (sweep/face_contact.h):
//   * every contact it returns is a real point of the cutter at its t (membership from
//     the cutter's definition, brute_force_reference.h) and the brute-force lowest point
//     of the swept solid to 1e-9 mm (dense t, then golden-section refinement: the
//     reference errs only upwards, so a false proof, a lower point elsewhere in t,
//     shows as a contact above the reference);
//   * it is found on most lines under the face of CAM-like moves (it is the kernel's
//     path there, in place of the certified search), for slerp and rotary (TCP on)
//     curves, bull and flat cutters;
//   * on moves with large turns (up to 90 degrees) and steep axes, where z_face may have
//     several minima or the proof cannot close, it may decline, but never errs;
//   * SweptMove::lowestPoint on the same lines agrees with the reference.
#include "sweep/face_contact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "base/constants.h"
#include "sweep/brute_force_reference.h"
#include "sweep/machine_reference.h"
#include "sweep/swept_move.h"

namespace scallop {
namespace {

struct FaceCase {
  Cutter cutter;
  ref::RefCutter refCutter;
  PoseCurve curve;
  ref::RefCurve refCurve;
};

// A move whose axis leans by up to `maxLeanDeg` from the vertical and turns by up to
// `maxTurn` rad (slerp), or a rotary table move (TCP on) whose tilt and spin change by up
// to `maxTurn` each; the tip feeds 0.05 to 3 mm, level or on a ramp.
FaceCase randomFaceCase(std::mt19937_64& rng, int k, double maxLeanDeg, double maxTurn) {
  std::uniform_real_distribution<double> u(0, 1);
  FaceCase c;
  const bool flat = k % 3 == 2;
  const double R = 1 + 4 * u(rng);
  const double r = flat ? 0 : R * (0.1 + 0.5 * u(rng));
  const double L = R * (2 + 2 * u(rng));
  const CutterType type = flat ? CutterType::Flat : CutterType::Bull;
  c.cutter = Cutter::make(type, R, r, L);
  c.refCutter = ref::makeRefCutter(type, R, r, L);
  const double heading = 2 * kPi * u(rng), feed = 0.05 + 2.95 * u(rng) * u(rng);
  const Vec3 p0{2 * (u(rng) - 0.5), 2 * (u(rng) - 0.5), u(rng) - 0.5};
  const Vec3 p1 = p0 + Vec3{feed * std::cos(heading), feed * std::sin(heading),
                            k % 4 == 1 ? 0.3 * feed * (u(rng) - 0.5) : 0};
  const double lean = degToRad(maxLeanDeg) * u(rng);
  if (k % 5 == 4) {
    const RotaryKinematics kin = k % 2 ? RotaryKinematics::TableAC : RotaryKinematics::TableBC;
    const double tilt0 = lean * (u(rng) < 0.5 ? -1 : 1), spin0 = 2 * kPi * u(rng);
    const double tilt1 = tilt0 + maxTurn * (u(rng) - 0.5), spin1 = spin0 + maxTurn * (u(rng) - 0.5);
    c.curve = PoseCurve::rotary(kin, p0, p1, tilt0, tilt1, spin0, spin1);
    c.refCurve = {p0, p1, [=](double t) {
                    return conventionAxis(kin, tilt0 + (tilt1 - tilt0) * t,
                                          spin0 + (spin1 - spin0) * t);
                  }};
    return c;
  }
  const Vec3 a0 = ref::unitFromAngles(lean, 2 * kPi * u(rng));
  const double turn = maxTurn * u(rng) + 1e-6;
  const Vec3 w = normalize(cross(a0, Vec3{u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5}));
  const Vec3 a1 = a0 * std::cos(turn) + cross(w, a0) * std::sin(turn);
  c.curve = PoseCurve::linear({p0, a0}, {p1, a1});
  c.refCurve = {p0, p1, [=](double t) { return ref::slerp(a0, a1, t); }};
  return c;
}

// A line through a point of the bottom disc of the cutter at a random pose of the move
// (up to `reach` Rb from the tip): most such lines meet the swept solid lowest on a face.
void faceLine(const FaceCase& c, std::mt19937_64& rng, double reach, double& x, double& y) {
  std::uniform_real_distribution<double> u(0, 1);
  const double t = u(rng);
  const Vec3 tip = c.refCurve.p0 + (c.refCurve.p1 - c.refCurve.p0) * t, a = c.refCurve.axis(t);
  const Vec3 e1 = normalize(cross(a, std::fabs(a.x) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
  const Vec3 e2 = cross(a, e1);
  const double rho = reach * c.cutter.bottomRadius() * std::sqrt(u(rng)), phi = 2 * kPi * u(rng);
  const Vec3 p = tip + (e1 * std::cos(phi) + e2 * std::sin(phi)) * rho;
  x = p.x, y = p.y;
}

struct Tally {
  int lines = 0, found = 0, kernelHits = 0;
  double worst = 0, worstKernel = 0;
};

// One line: the contact (where found) and SweptMove against the reference.
void check(const FaceCase& c, const SweptMove& move, double x, double y, Tally& st,
           const std::string& what) {
  double depth = 0;
  const ref::RefHit rh = ref::turningLowest(c.refCutter, c.refCurve, x, y, 801, &depth);
  if (!rh.hit || depth < 1e-6) return;  // a miss, or a grazing line
  ++st.lines;
  char where[96];
  std::snprintf(where, sizeof where, " line (%.17g, %.17g)", x, y);
  const FaceContact face = locateFaceContact(c.cutter, c.curve, x, y);
  if (face.found) {
    ++st.found;
    const Vec3 tip = c.refCurve.p0 + (c.refCurve.p1 - c.refCurve.p0) * face.t;
    EXPECT_TRUE(ref::inside(c.refCutter, tip, c.refCurve.axis(face.t), {x, y, face.z}, 1e-9))
        << what << where << ": the contact is no point of the cutter";
    EXPECT_NEAR(face.z, rh.z, 1e-9) << what << where;
    EXPECT_LT(face.normal.z, 0) << what << where;
    st.worst = std::max(st.worst, std::fabs(face.z - rh.z));
  }
  const LowestPoint lp = move.lowestPoint(x, y);
  ASSERT_TRUE(lp.hit) << what << where;
  ++st.kernelHits;
  EXPECT_NEAR(lp.z, rh.z, 1e-9) << what << where;
  st.worstKernel = std::max(st.worstKernel, std::fabs(lp.z - rh.z));
}

// `cases` random moves (randomFaceCase) with `lines` face lines each (faceLine), checked
// and summed up under `name`.
Tally checkCases(uint64_t seed, int cases, int lines, double maxLeanDeg, double maxTurn,
                 double reach, const char* name) {
  std::mt19937_64 rng(seed);
  Tally st;
  for (int k = 0; k < cases; ++k) {
    const FaceCase c = randomFaceCase(rng, k, maxLeanDeg, maxTurn);
    const SweptMove move(c.cutter, c.curve);
    for (int q = 0; q < lines; ++q) {
      double x, y;
      faceLine(c, rng, reach, x, y);
      check(c, move, x, y, st, "case " + std::to_string(k));
    }
  }
  std::printf("FaceContact %s: %d lines, found on %d (worst %.3g mm); SweptMove worst %.3g mm\n",
              name, st.lines, st.found, st.worst, st.worstKernel);
  return st;
}

TEST(FaceContact, CamLikeMovesAreFoundAndExact) {
  const Tally st = checkCases(2026, 40, 6, 20, 0.02, 0.8, "CAM-like");
  ASSERT_GE(st.lines, 150);
  // Lines through the inner 80 % of the disc at a pose of the move. Measured, this seed:
  // found on 219 of 240; of the 21 others, 18 meet the solid lowest on a corner (no face
  // contact) and 3 on a face where the proof did not close.
  EXPECT_GE(st.found, 0.85 * st.lines);
}

TEST(FaceContact, LargeTurnsAndSteepAxesNeverErr) {
  const Tally st = checkCases(77, 60, 5, 70, 0.5 * kPi, 1.0, "large turns");
  ASSERT_GE(st.lines, 150);
  EXPECT_GT(st.found, 0);
  EXPECT_LT(st.found, st.lines);  // some lines are left to the certified search
}

TEST(FaceContact, BallCuttersHaveNoFace) {
  const Cutter ball = Cutter::make(CutterType::Ball, 3, 3, 10);
  const PoseCurve curve = PoseCurve::linear({{0, 0, 0}, {0, 0, 1}}, {{1, 0, 0}, {0.1, 0, 1}});
  EXPECT_FALSE(locateFaceContact(ball, curve, 0.5, 0).found);
}

}  // namespace
}  // namespace scallop
