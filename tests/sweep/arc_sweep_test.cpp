// G-code arcs as single moves (pose.h ArcMotion, PoseCurve::arc): the tip's closed-form
// derivatives and their bounds, and the swept heights against the brute-force
// reference sweeping the same circle or helix, written here from the definition
// (CONVENTIONS.md "Tool pose": tip(t) on the circle, the axis constant).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "base/constants.h"
#include "sweep/brute_force_reference.h"
#include "sweep/pose_curve.h"
#include "sweep/swept_move.h"
#include "sweep/tool_path_sweep.h"

namespace scallop {
namespace {

// The plane's axes as G-code names them: G17 (x, y), G18 (z, x), G19 (y, z).
void planeAxes(int plane, Vec3& u, Vec3& v) {
  const Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  u = plane == 17 ? x : plane == 18 ? z : y;
  v = plane == 17 ? y : plane == 18 ? x : z;
}

ArcMotion makeArc(int plane, const Vec3& centre, double angle0, double sweep, double radius0,
                  double radius1, double rise) {
  ArcMotion a;
  planeAxes(plane, a.u, a.v);
  a.centre = centre;
  a.angle0 = angle0, a.sweep = sweep;
  a.radius0 = radius0, a.radius1 = radius1;
  a.rise = rise;
  return a;
}

// The tip on the arc from the definition, with the plane's axes spelled out per plane.
Vec3 referenceTip(int plane, const Vec3& c, double angle0, double sweep, double r0, double r1,
                  double rise, double t) {
  const double theta = angle0 + sweep * t, rho = r0 + (r1 - r0) * t;
  const double a = rho * std::cos(theta), b = rho * std::sin(theta), h = rise * t;
  if (plane == 17) return {c.x + a, c.y + b, c.z + h};
  if (plane == 18) return {c.x + b, c.y + h, c.z + a};
  return {c.x + h, c.y + a, c.z + b};
}

TEST(ArcSweep, TipDerivativesAndBoundsAreTheArcsOwn) {
  std::mt19937_64 rng(33);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 30; ++k) {
    const int plane = 17 + k % 3;
    const double r0 = 2 + 3 * std::fabs(u(rng));
    // Every third a spiral within G-code's 0.002 mm; every other a helix.
    const double r1 = k % 3 == 0 ? r0 + 0.002 * u(rng) : r0;
    const double sweep = k % 5 == 0 ? -2 * kPi : 3 * u(rng);
    const double rise = k % 2 ? 1.5 * u(rng) : 0;
    const ArcMotion arc =
        makeArc(plane, {u(rng), u(rng), u(rng)}, kPi * u(rng), sweep, r0, r1, rise);
    const PoseCurve curve = PoseCurve::arc(arc, {0, 0, 1});
    ASSERT_TRUE(curve.constantAxis());
    ASSERT_FALSE(curve.linearTip());
    ASSERT_TRUE(curve.arcTip());
    double maxAccel = 0, maxJerk = 0, maxSpeed = 0;
    for (int i = 0; i <= 200; ++i) {
      const double t = i / 200.0, h = 1e-5;
      const Vec3 ref = referenceTip(plane, arc.centre, arc.angle0, sweep, r0, r1, rise, t);
      EXPECT_LT(length(curve.tip(t) - ref), 1e-12);
      // Central differences of the reference: O(h^2) against the closed forms.
      auto tipAt = [&](double s) {
        return referenceTip(plane, arc.centre, arc.angle0, sweep, r0, r1, rise, s);
      };
      const Vec3 dv = (tipAt(t + h) - tipAt(t - h)) / (2 * h);
      const Vec3 da = (tipAt(t + h) - tipAt(t) * 2 + tipAt(t - h)) / (h * h);
      EXPECT_LT(length(curve.tipVelocity(t) - dv), 1e-7 * (1 + length(dv)));
      EXPECT_LT(length(curve.tipAcceleration(t) - da), 1e-3 * (1 + length(da)));
      const Vec3 jerk = (curve.tipAcceleration(t + h) - curve.tipAcceleration(t - h)) / (2 * h);
      maxSpeed = std::max(maxSpeed, length(curve.tipVelocity(t)));
      maxAccel = std::max(maxAccel, length(curve.tipAcceleration(t)));
      maxJerk = std::max(maxJerk, length(jerk));
    }
    EXPECT_LE(maxSpeed, curve.tipSpeedBound());
    EXPECT_LE(maxAccel, curve.tipAccelBound());
    EXPECT_LE(maxJerk, curve.tipJerkBound() * (1 + 1e-6));
    if (r1 == r0) {
      // On a circle the bounds are attained: r s^2 and r |s|^3, and the speed.
      EXPECT_NEAR(curve.tipAccelBound(), r0 * sweep * sweep, 1e-9 * r0 * sweep * sweep);
      EXPECT_NEAR(curve.tipJerkBound(), r0 * std::pow(std::fabs(sweep), 3),
                  1e-9 * (1 + r0 * std::pow(std::fabs(sweep), 3)));
      EXPECT_NEAR(maxAccel, curve.tipAccelBound(), 1e-9 * (1 + maxAccel));
      EXPECT_NEAR(curve.pathLength(), std::hypot(r0 * sweep, rise), 1e-12 * (1 + r0));
    } else {
      // A spiral's length by Simpson's rule against the trapezoid on a fine grid.
      double trapezoid = 0;
      for (int i = 0; i < 20000; ++i)
        trapezoid +=
            0.5 / 20000 *
            (length(curve.tipVelocity(i / 20000.0)) + length(curve.tipVelocity((i + 1) / 20000.0)));
      EXPECT_NEAR(curve.pathLength(), trapezoid, 1e-8 * (1 + trapezoid));
    }
  }
}

struct ArcCase {
  int plane;
  CutterType type;
  double sweep, rise;
  Vec3 axis;
};

// Heights of one arc move against the reference on lines over its path, within 1e-6 mm;
// returns the worst difference and counts the lines.
double checkArc(const ArcCase& c, std::mt19937_64& rng, int lines, int& hits, int& misses,
                int& grazing) {
  std::uniform_real_distribution<double> u(-1, 1);
  const double r = 4, R = 1.5;
  const Vec3 centre{0.3, -0.2, 0.1};
  const double angle0 = kPi * u(rng);
  const ArcMotion arc = makeArc(c.plane, centre, angle0, c.sweep, r, r, c.rise);
  const Cutter cutter = Cutter::make(c.type, R, 0.5, 8);
  const ref::RefCutter refCutter = ref::makeRefCutter(c.type, R, 0.5, 8);
  const SweptMove move(cutter, PoseCurve::arc(arc, c.axis));
  EXPECT_TRUE(move.turning());
  ref::RefCurve refCurve;
  const Vec3 axis = normalize(c.axis);
  refCurve.axis = [axis](double) { return axis; };
  refCurve.tip = [&](double t) {
    return referenceTip(c.plane, centre, angle0, c.sweep, r, r, c.rise, t);
  };
  refCurve.p0 = refCurve.tip(0), refCurve.p1 = refCurve.tip(1);
  const Box3 box = arc.bounds();
  double worst = 0;
  for (int q = 0; q < lines; ++q) {
    const double x = box.min.x - R + (box.max.x - box.min.x + 2 * R) * 0.5 * (1 + u(rng));
    const double y = box.min.y - R + (box.max.y - box.min.y + 2 * R) * 0.5 * (1 + u(rng));
    double depth = 0;
    const ref::RefHit want = ref::turningLowest(refCutter, refCurve, x, y, 2001, &depth);
    const LowestPoint got = move.lowestPoint(x, y);
    if (std::fabs(depth) < 1e-5) {
      ++grazing;
      continue;
    }
    EXPECT_EQ(got.hit, want.hit) << "G" << c.plane << " " << toString(c.type) << " (" << x << ", "
                                 << y << ")";
    if (!want.hit || !got.hit) {
      ++misses;
      continue;
    }
    ++hits;
    worst = std::max(worst, std::fabs(got.z - want.z));
    EXPECT_NEAR(got.z, want.z, 1e-6)
        << "G" << c.plane << " " << toString(c.type) << " sweep " << c.sweep << " rise " << c.rise
        << " (" << x << ", " << y << ")";
  }
  return worst;
}

TEST(ArcSweep, ArcMovesAgreeWithBruteForce) {
  std::mt19937_64 rng(3317);
  const unsigned long long unprovenBefore = SweptMove::unprovenSearches();
  std::vector<ArcCase> cases;
  for (int plane : {17, 18, 19})
    for (CutterType type : {CutterType::Ball, CutterType::Flat, CutterType::Bull}) {
      cases.push_back({plane, type, 1.3, 0, {0, 0, 1}});      // a plain arc, G3
      cases.push_back({plane, type, -2.2, 0.8, {0, 0, 1}});   // a helical G2
      cases.push_back({plane, type, 2 * kPi, 0, {0, 0, 1}});  // a full circle
      // A tilted axis (TCP on), ball and bull: a flat one meets the certified search's
      // known defect near its rim (DISABLED_FlatCutterTiltedHelixNearItsRim below).
      cases.push_back({plane, type, -0.9, 0.3, {0.2, -0.1, 1}});
    }
  int hits = 0, misses = 0, grazing = 0;
  double worst = 0;
  for (const ArcCase& c : cases)
    worst = std::max(worst, checkArc(c, rng, 16, hits, misses, grazing));
  std::printf(
      "arcs: %d hits, %d misses, %d grazing skipped; worst |kernel - reference| = %.3g mm\n", hits,
      misses, grazing, worst);
  EXPECT_GE(hits, 250);
  EXPECT_EQ(SweptMove::unprovenSearches(), unprovenBefore);
}

// The defect of certified_search_test's DISABLED_FlatCutterLineNearItsRimClosesItsProof
// on an arc: a line near a tilted flat cutter's rim, where the search spends its samples
// and returns a height 4.3 um too high (0.0956381 against 0.0913066).
TEST(ArcSweep, FlatCutterTiltedHelixNearItsRim) {
  const double angle0 = -2.8832343886328231, x = -2.2957763577236596, y = 1.564426403122269;
  const Vec3 centre{0.3, -0.2, 0.1}, axis{0.2, -0.1, 1};
  const ArcMotion arc = makeArc(17, centre, angle0, -0.9, 4, 4, 0.3);
  const SweptMove move(Cutter::make(CutterType::Flat, 1.5, 0.5, 8), PoseCurve::arc(arc, axis));
  ref::RefCurve curve;
  curve.axis = [&](double) { return normalize(axis); };
  curve.tip = [&](double t) { return referenceTip(17, centre, angle0, -0.9, 4, 4, 0.3, t); };
  curve.p0 = curve.tip(0), curve.p1 = curve.tip(1);
  const unsigned long long unprovenBefore = SweptMove::unprovenSearches();
  const LowestPoint got = move.lowestPoint(x, y);
  const ref::RefHit want =
      ref::turningLowest(ref::makeRefCutter(CutterType::Flat, 1.5, 0.5, 8), curve, x, y, 2001);
  ASSERT_TRUE(got.hit && want.hit);
  EXPECT_NEAR(got.z, want.z, 1e-6);
  EXPECT_EQ(SweptMove::unprovenSearches(), unprovenBefore);
}

TEST(ArcSweep, ArcsAreNeverMergedAndTheirSupportHoldsTheSolid) {
  // Two arcs of one circle in a row, and a line after them: three moves, none merged.
  ToolPath path;
  path.arcs.push_back(makeArc(17, {0, 0, 0}, 0, 1, 3, 3, 0));
  path.arcs.push_back(makeArc(17, {0, 0, 0}, 1, 1, 3, 3, 0));
  const Vec3 up{0, 0, 1};
  auto at = [&](int k, double t) { return path.arcs[size_t(k)].at(t); };
  path.moves.push_back({{at(0, 0), up}, {at(0, 1), up}});
  path.moves.back().arc = 1;
  path.moves.push_back({{at(1, 0), up}, {at(1, 1), up}});
  path.moves.back().arc = 2;
  path.moves.push_back({{at(1, 1), up}, {at(1, 1) + Vec3{1, 0, 0}, up}});
  const Cutter cutter = Cutter::make(CutterType::Ball, 1, 0, 4);
  const std::vector<SweptMove> moves = sweepToolPath(cutter, path);
  ASSERT_EQ(moves.size(), 3u);
  EXPECT_TRUE(moves[0].turning() && moves[1].turning());
  // support() bounds every point of the solid: the cutter's support at dense t.
  for (const Vec3& dir :
       {Vec3{1, 0, 0}, Vec3{0, -1, 0}, Vec3{0.6, 0.8, 0}, Vec3{0.3, 0.4, -0.866}}) {
    for (int k = 0; k < 2; ++k) {
      double most = -HUGE_VAL;
      for (int i = 0; i <= 4000; ++i) {
        const double t = i / 4000.0;
        most = std::max(most, dot(dir, at(k, t) + cutterSupport(cutter, up, dir)));
      }
      EXPECT_GE(moves[size_t(k)].support(dir), most);
      EXPECT_LE(moves[size_t(k)].support(dir), most + 0.5);  // the chord bound's slack
    }
  }
}

}  // namespace
}  // namespace scallop
