// Independent checks of the turning moves' rim contact (sweep/rim_contact.h) and of the
// pose frame it runs on (PoseCurve::frame, sweep/pose_curve.h):
//   * PoseFrame: the frame's fields are the curve's accessors, (e1, e2, axis) is a
//     right-handed orthonormal frame, and e1 turns with the cutter (d e1/dt = spin x e1
//     by central differences), for slerp, rotary (TCP on) and joint-linear curves;
//   * RimContact: every contact located is a real point of the cutter K(t) at its t
//     (membership written here from the cutter's definition in cutter.h, sharing no code
//     with sweep/), so never below the brute-force reference's lowest point
//     (brute_force_reference.h); its normal is unit and points down; on CAM-like moves
//     it is found on most lines and is the reference's lowest point; a ball turning about
//     its tip against a closed form;
//   * SweptMove::lowestPoint (whose fast path is the rim contact) against the reference
//     on CAM-like bull and ball moves, near their footprints' edges, and on cutters whose
//     flutes are shorter than twice the corner radius (there a rim sphere's lowest point
//     can lie above the flute top).
#include "sweep/rim_contact.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "base/constants.h"
#include "sweep/brute_force_reference.h"
#include "sweep/contact_knots.h"
#include "sweep/pose_curve.h"
#include "sweep/swept_move.h"
#include "tests/support/random_cases.h"

namespace scallop {
namespace {

using ref::unitFromAngles;

// ---------------------------------------------------------------------------------------
// PoseFrame

using NamedCurve = test::CheckedCurve;

std::vector<NamedCurve> frameCurves() {
  std::vector<NamedCurve> out;
  std::mt19937_64 rng(404);
  std::uniform_real_distribution<double> u(-1, 1);
  // Slerp: small, medium and 90-degree turns, a moving and a standing tip, and a move
  // whose axis does not turn at all.
  for (int k = 0; k < 5; ++k) {
    const Vec3 p0{u(rng), u(rng), u(rng)}, p1 = k == 3 ? p0 : Vec3{3 * u(rng), 3 * u(rng), u(rng)};
    const Vec3 a0 = unitFromAngles(0.4 * (1 + u(rng)), kPi * u(rng));
    Vec3 a1;
    if (k == 4) {
      a1 = a0;
    } else {
      const double turn = k == 0 ? 0.02 : (k == 1 ? 0.5 : 0.5 * kPi);
      const Vec3 w = normalize(cross(a0, Vec3{u(rng), u(rng), u(rng)}));  // across a0
      a1 = a0 * std::cos(turn) + cross(w, a0) * std::sin(turn);
    }
    out.push_back({"slerp " + std::to_string(k), PoseCurve::linear({p0, a0}, {p1, a1}),
                   [=](double t) { return p0 + (p1 - p0) * t; },
                   [=](double t) { return ref::slerp(a0, a1, t); }});
  }
  // Rotary, TCP on: both kinematics, tilt and spin both moving, or one of them alone.
  for (int k = 0; k < 6; ++k) {
    const RotaryKinematics kin = k % 2 ? RotaryKinematics::TableAC : RotaryKinematics::TableBC;
    test::RotaryRanges ranges{0.7, 0.4, 3, 1.2};
    ranges.tiltStands = k / 2 == 2, ranges.spinStands = k / 2 == 1;
    out.push_back(test::randomRotaryCurve(
        std::string("rotary ") + (k % 2 ? "AC " : "BC ") + std::to_string(k), rng, kin, ranges));
  }
  // Joint-linear (TCP off): the tip follows trtfuncs' forward kinematics.
  for (int k = 0; k < 4; ++k) {
    const RotaryKinematics kin = k % 2 ? RotaryKinematics::TableAC : RotaryKinematics::TableBC;
    const test::MachineMove move =
        test::randomMachineMove(rng, kin, {10, 3, 40, 10, 0.7, 0.3, 3, 0.8, 20, 5});
    out.push_back(test::jointLinearCurve(
        std::string("joint-linear ") + (k % 2 ? "AC " : "BC ") + std::to_string(k), move));
  }
  return out;
}

double diff(const Vec3& a, const Vec3& b) {
  return length(a - b);
}

// frame(t) holds what the curve's accessors give at t.
TEST(PoseFrame, FieldsAreTheCurvesAccessors) {
  double worstField = 0, worstConvention = 0;
  int frames = 0;
  for (const NamedCurve& nc : frameCurves()) {
    const PoseCurve& c = nc.curve;
    for (double t : {0.0, 0.125, 0.37, 0.5, 0.81, 1.0}) {
      const PoseFrame f = c.frame(t);
      ++frames;
      EXPECT_EQ(f.t, t);
      // Each field against its accessor, to a few units in the last place of its size.
      const std::pair<Vec3, Vec3> fields[] = {{f.tip, c.tip(t)},
                                              {f.velocity, c.tipVelocity(t)},
                                              {f.acceleration, c.tipAcceleration(t)},
                                              {f.axis, c.axis(t)},
                                              {f.spin, c.spin(t)},
                                              {f.spinRate, c.spinRate(t)}};
      const char* names[] = {"tip", "velocity", "acceleration", "axis", "spin", "spinRate"};
      for (int i = 0; i < 6; ++i) {
        const double d = diff(fields[i].first, fields[i].second);
        worstField = std::max(worstField, d / (1 + length(fields[i].second)));
        EXPECT_LE(d, 1e-15 * (1 + length(fields[i].second)))
            << nc.name << " t " << t << " field " << names[i];
      }
      // And the accessors against the conventions written out here.
      const double dTip = diff(f.tip, nc.tip(t)), dAxis = diff(f.axis, nc.axis(t));
      worstConvention = std::max({worstConvention, dTip / (1 + length(f.tip)), dAxis});
      EXPECT_LE(dTip, 1e-12 * (1 + length(f.tip))) << nc.name << " t " << t;
      EXPECT_LE(dAxis, 1e-12) << nc.name << " t " << t;
    }
  }
  std::printf(
      "PoseFrame fields: %d frames; worst |field - accessor| = %.3g (relative), "
      "worst |pose - convention| = %.3g\n",
      frames, worstField, worstConvention);
}

// (e1, e2, axis) is right-handed and orthonormal, turns with the cutter (d e1/dt =
// spin x e1, by central differences of frame() itself), and the curve's rates are
// those of its own axis (d axis/dt = spin x axis, d spin/dt = spinRate, d tip/dt =
// velocity, d velocity/dt = acceleration), all by central differences.
TEST(PoseFrame, IsOrthonormalRightHandedAndCarriedWithTheCutter) {
  double worstOrtho = 0, worstCarry = 0, worstRates = 0;
  int frames = 0;
  for (const NamedCurve& nc : frameCurves()) {
    const PoseCurve& c = nc.curve;
    const double omega = c.turnRate();
    for (double t : {0.0, 0.125, 0.37, 0.5, 0.81, 1.0}) {
      const PoseFrame f = c.frame(t);
      ++frames;
      const double ortho = std::max(
          {std::fabs(length(f.e1) - 1), std::fabs(length(f.e2) - 1), std::fabs(length(f.axis) - 1),
           std::fabs(dot(f.e1, f.e2)), std::fabs(dot(f.e1, f.axis)), std::fabs(dot(f.e2, f.axis)),
           diff(cross(f.e1, f.e2), f.axis)});  // right-handed: e1 x e2 = axis
      worstOrtho = std::max(worstOrtho, ortho);
      EXPECT_LE(ortho, 1e-14) << nc.name << " t " << t;
      if (t <= 0 || t >= 1) continue;  // central differences need both sides
      const double h = 1e-5;
      const PoseFrame fa = c.frame(t - h), fb = c.frame(t + h);
      // e1 and e2 carried rigidly: relative to the turn rate.
      const double de1 = diff((fb.e1 - fa.e1) / (2 * h), cross(f.spin, f.e1));
      const double de2 = diff((fb.e2 - fa.e2) / (2 * h), cross(f.spin, f.e2));
      const double carry = std::max(de1, de2) / std::max(omega, 1e-3);
      worstCarry = std::max(worstCarry, carry);
      EXPECT_LE(carry, 1e-6) << nc.name << " t " << t << " omega " << omega;
      // The curve's rates against its own poses (and the convention's axis).
      const double dAxis =
          diff((nc.axis(t + h) - nc.axis(t - h)) / (2 * h), cross(f.spin, f.axis)) /
          std::max(omega, 1e-3);
      const double dSpin =
          diff((fb.spin - fa.spin) / (2 * h), f.spinRate) / std::max(omega * omega, 1e-3);
      const double speed = std::max(length(f.velocity), 1e-3);
      const double dTip = diff((nc.tip(t + h) - nc.tip(t - h)) / (2 * h), f.velocity) / speed;
      const double dVel = diff((fb.velocity - fa.velocity) / (2 * h), f.acceleration) /
                          std::max(length(f.acceleration) + omega * speed, 1e-3);
      const double rates = std::max({dAxis, dSpin, dTip, dVel});
      worstRates = std::max(worstRates, rates);
      EXPECT_LE(rates, 1e-6) << nc.name << " t " << t << ": axis " << dAxis << " spin " << dSpin
                             << " tip " << dTip << " velocity " << dVel;
    }
  }
  std::printf(
      "PoseFrame: %d frames; worst orthonormality %.3g, worst |de/dt - spin x e| / omega %.3g, "
      "worst rate %.3g (relative)\n",
      frames, worstOrtho, worstCarry, worstRates);
}

// ---------------------------------------------------------------------------------------
// Independent geometry of the cutter, from cutter.h's definition
//     K = (Cyl(Rb; s in [r, L]) (+) Ball(r)) n {s <= L}
// for the cutter standing at (tip, unit axis).

struct CoreDistance {
  double dist = 0;  // distance from p to the core cylinder C (radius Rb, s in [r, L])
  Vec3 nearest;     // C's nearest point to p
  double s = 0;     // p's height along the axis above the tip
};

CoreDistance toCore(const Cutter& c, const Vec3& tip, const Vec3& axis, const Vec3& p) {
  const double r = c.cornerRadius, rb = c.radius - c.cornerRadius, L = c.fluteLength;
  const Vec3 q = p - tip;
  CoreDistance out;
  out.s = dot(q, axis);
  const Vec3 across = q - axis * out.s;
  const double rho = length(across);
  const double sc = std::min(std::max(out.s, r), L), rc = std::min(rho, rb);
  out.nearest = tip + axis * sc + (rho > 0 ? across * (rc / rho) : Vec3{});
  out.dist = length(p - out.nearest);
  return out;
}

// A turning move (slerp), with its pose written from the conventions for the checks.
struct TurnCase {
  Cutter cutter;
  ref::RefCutter refCutter;
  Vec3 p0, p1, a0, a1;
  PoseCurve curve() const { return PoseCurve::linear({p0, a0}, {p1, a1}); }
  ref::RefCurve refCurve() const {
    const Vec3 b0 = a0, b1 = a1;
    return {p0, p1, [=](double t) { return ref::slerp(b0, b1, t); }};
  }
  // The cutter's pose at t, from the conventions (not PoseCurve).
  Vec3 tip(double t) const { return p0 + (p1 - p0) * t; }
  Vec3 axis(double t) const { return ref::slerp(a0, a1, t); }
  std::string describe() const {
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "%s R %.17g r %.17g L %.17g p0 (%.17g, %.17g, %.17g) p1 (%.17g, %.17g, %.17g) "
                  "a0 (%.17g, %.17g, %.17g) a1 (%.17g, %.17g, %.17g)",
                  toString(cutter.type), cutter.radius, cutter.cornerRadius, cutter.fluteLength,
                  p0.x, p0.y, p0.z, p1.x, p1.y, p1.z, a0.x, a0.y, a0.z, a1.x, a1.y, a1.z);
    return buf;
  }
};

TurnCase makeCase(CutterType type, double R, double r, double L, const Vec3& p0, const Vec3& p1,
                  const Vec3& a0, const Vec3& a1) {
  TurnCase c;
  c.cutter = Cutter::make(type, R, r, L);
  c.refCutter = ref::makeRefCutter(type, R, r, L);
  c.p0 = p0, c.p1 = p1, c.a0 = normalize(a0), c.a1 = normalize(a1);
  return c;
}

// A random turning move: ball or bull, axes from `minPolarDeg` (default: vertical) to 80
// degrees from the vertical, turns up to 90 degrees, level feeds, ramps, plunges and pure
// turns. `shortFlute`: the flute length is drawn from [r, 2r) (legal: Cutter::make asks
// L >= r), otherwise from [2R, 5R].
TurnCase randomTurningCase(std::mt19937_64& rng, int k, bool shortFlute, double minPolarDeg = 0) {
  std::uniform_real_distribution<double> u(0, 1);
  const CutterType type = k % 2 ? CutterType::Bull : CutterType::Ball;
  const double R = 1 + 4 * u(rng);
  const double r = type == CutterType::Bull ? R * (0.15 + 0.7 * u(rng)) : R;
  const double L = shortFlute ? r * (1 + 0.999 * u(rng)) : R * (2 + 3 * u(rng));
  Vec3 a0, a1;
  const double minPolar = degToRad(minPolarDeg), maxPolar = degToRad(80);
  for (;;) {
    a0 = unitFromAngles(minPolar + (maxPolar - minPolar) * u(rng), 2 * kPi * u(rng));
    a1 = unitFromAngles(minPolar + (maxPolar - minPolar) * u(rng), 2 * kPi * u(rng));
    if (dot(a0, a1) >= 0 && dot(a0, a1) < 1 - 1e-6) break;  // 0.08 to 90 degrees
  }
  const Vec3 p0{4 * (u(rng) - 0.5), 4 * (u(rng) - 0.5), u(rng) - 0.5};
  Vec3 p1 = p0;
  switch (k / 2 % 4) {
    case 0:  // level feed
      p1 = p0 + Vec3{3 * (u(rng) - 0.5), 3 * (u(rng) - 0.5), 0};
      break;
    case 1:  // ramp
      p1 = p0 + Vec3{3 * (u(rng) - 0.5), 3 * (u(rng) - 0.5), 2 * (u(rng) - 0.5)};
      break;
    case 2:  // plunge or retract
      p1 = p0 + Vec3{0, 0, 2 * (u(rng) - 0.5)};
      break;
    default:  // the axis turns about a standing tip
      break;
  }
  return makeCase(type, R, r, L, p0, p1, a0, a1);
}

// A CAM-like move: a leaned bull (or a ball), lead 2 to 20 degrees and a little tilt,
// a feed level or on a gentle ramp, the axis turning by at most 0.02 rad. The feed is
// 0.05 to 0.5 mm for Segment::Short (5-axis CL output, a new axis every few tenths of a
// mm), 0.5 to 4 mm for Segment::Long, and either by default.
enum class Segment { Any, Short, Long };
TurnCase camLikeCase(std::mt19937_64& rng, int k, Segment segment = Segment::Any) {
  std::uniform_real_distribution<double> u(0, 1);
  const CutterType type = k % 4 == 3 ? CutterType::Ball : CutterType::Bull;
  const double R = 1 + 5 * u(rng);
  const double r = type == CutterType::Bull ? R * (0.1 + 0.5 * u(rng)) : R;
  const double L = R * (2 + 2 * u(rng));
  const double heading = 2 * kPi * u(rng);
  const Vec3 feed{std::cos(heading), std::sin(heading), 0}, side{-feed.y, feed.x, 0};
  const double lead = degToRad(2 + 18 * u(rng)), tilt = degToRad((u(rng) - 0.5) * 10);
  const Vec3 a0 = normalize(feed * std::tan(lead) + side * std::tan(tilt) + Vec3{0, 0, 1});
  const double turn = 0.02 * u(rng) + 1e-6;
  const Vec3 w = normalize(cross(a0, Vec3{u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5}));
  const Vec3 a1 = a0 * std::cos(turn) + cross(w, a0) * std::sin(turn);
  const double v = u(rng);
  const double length = segment == Segment::Short  ? 0.05 + 0.45 * v
                        : segment == Segment::Long ? 0.5 + 3.5 * v
                                                   : 0.05 + 3.95 * v;
  const double slope = k % 3 == 0 ? 0.3 * (u(rng) - 0.5) : 0;
  const Vec3 p0{10 * (u(rng) - 0.5), 10 * (u(rng) - 0.5), u(rng) - 0.5};
  const Vec3 p1 = p0 + feed * length + Vec3{0, 0, slope * length};
  return makeCase(type, R, r, L, p0, p1, a0, a1);
}

// Lines inside a CAM-like move's footprint, across the feed by up to 0.9 R: over the
// tip's path, or (`toe`) over the trace of the cutter's toe, the point of its bottom rim
// where the leaning bottom face dips lowest, Rb from the tip (for a lead the toe is
// ahead: a cutter leaning forward cuts with the front of its bottom), where most lowest
// points lie on the corner.
void camLine(const TurnCase& c, std::mt19937_64& rng, bool toe, double& x, double& y) {
  std::uniform_real_distribution<double> u(0, 1);
  const Vec3 d = c.p1 - c.p0;
  const double len = std::hypot(d.x, d.y);
  const Vec3 feed{d.x / len, d.y / len, 0}, side{-feed.y, feed.x, 0};
  // The toe: the bottom rim's lowest direction, -(z less its part along the axis).
  const Vec3 a = c.axis(0), z{0, 0, 1};
  const Vec3 down = (z - a * dot(z, a)) * -1.0;
  const double dh = std::hypot(down.x, down.y);
  const Vec3 toeDir = dh > 1e-12 ? Vec3{down.x / dh, down.y / dh, 0} : feed;
  const double reach = toe ? c.cutter.radius - c.cutter.cornerRadius : 0;
  const Vec3 at =
      c.tip(u(rng)) + toeDir * reach + side * (0.9 * c.cutter.radius * (2 * u(rng) - 1));
  x = at.x, y = at.y;
}

// Where on the cutter the swept solid's lowest point on a line lies: on the corner
// (below the rim's plane and outside the bottom face's radius), on the flat bottom face,
// or on the flank, for the point (x, y, z) of K(t) (t and z from SweptMove, checked
// against the reference by the caller; the pose from the conventions).
enum class Part { Corner, Face, Flank };
Part partOf(const TurnCase& c, double t, const Vec3& p) {
  const Vec3 tip = c.tip(t), a = c.axis(t), q = p - tip;
  const double s = dot(q, a), rho = length(q - a * s);
  const double rb = c.cutter.radius - c.cutter.cornerRadius;
  if (s >= c.cutter.cornerRadius) return Part::Flank;
  if (rho <= rb + 1e-9) return Part::Face;
  return Part::Corner;
}

// How deep the vertical line (x, y) reaches into the swept solid, from the reference:
// the deepest penetration into K(t) (ref::deepestDepth; >= 0: the line meets K(t)) on 33
// poses, refined by golden section beside the deepest. Only chooses lines near edges.
double sweptDepth(const TurnCase& c, double x, double y) {
  auto depth = [&](double t) { return ref::deepestDepth(c.refCutter, c.tip(t), c.axis(t), x, y); };
  int best = 0;
  double bestDepth = -HUGE_VAL;
  for (int i = 0; i <= 32; ++i) {
    const double d = depth(i / 32.0);
    if (d > bestDepth) bestDepth = d, best = i;
  }
  const double lo = std::max(0, best - 1) / 32.0, hi = std::min(32, best + 1) / 32.0;
  return std::max(bestDepth, ref::goldenMax(depth, lo, hi).second);
}

// A line `inset` inside the footprint's edge: from the tip's middle (a point of the
// solid) out in direction `angle` to where the line stops meeting the solid (bisection on
// sweptDepth), then back by `inset`.
void edgeLine(const TurnCase& c, double angle, double inset, double& x, double& y) {
  const Vec3 mid = c.tip(0.5), dir{std::cos(angle), std::sin(angle), 0};
  double in = 0,
         out = 2 * (length(c.p1 - c.p0) + std::hypot(c.cutter.fluteLength, c.cutter.radius));
  for (int i = 0; i < 40; ++i) {
    const double m = 0.5 * (in + out);
    (sweptDepth(c, mid.x + m * dir.x, mid.y + m * dir.y) >= 0 ? in : out) = m;
  }
  const double at = std::max(0.0, in - inset);
  x = mid.x + at * dir.x, y = mid.y + at * dir.y;
}

struct RefLine {
  ref::RefHit hit;
  bool grazing = false;
};
RefLine reference(const TurnCase& c, double x, double y) {
  RefLine out;
  double depth = 0;
  out.hit = ref::turningLowest(c.refCutter, c.refCurve(), x, y, 401, &depth);
  out.grazing = std::fabs(depth) < 1e-5;
  return out;
}

// The checks of one located contact, whatever the start it came from (each failure is
// reported and counted, with the worst values seen).
struct ContactStats {
  int found = 0, onBoundary = 0, failures = 0;
  double worstMembership = -HUGE_VAL;      // max of dist(p, C) - r and s - L (<= 0: in K)
  double worstBelowReference = -HUGE_VAL;  // max of reference - z
  double worstNormal = 0;                  // max | |normal| - 1 |
  double worstNormalBoundary = 0;          // max |normal - K's outward normal| on K's boundary
};

void checkContact(const TurnCase& c, double x, double y, const RimContact& rim,
                  const RefLine* refLine, ContactStats& st, const char* what) {
  if (!rim.found) return;
  ++st.found;
  const Vec3 p{x, y, rim.z};
  std::string where = std::string(what) + " " + c.describe();
  char buf[160];
  std::snprintf(buf, sizeof buf, " (%.17g, %.17g): t %.17g z %.17g", x, y, rim.t, rim.z);
  where += buf;
  // t in [0, 1] and the pose returned is the pose at t.
  if (!(rim.t >= 0 && rim.t <= 1)) {
    ++st.failures;
    ADD_FAILURE() << "t out of [0, 1]: " << where;
    return;
  }
  const Vec3 tip = c.tip(rim.t), axis = c.axis(rim.t);
  EXPECT_EQ(rim.pose.t, rim.t) << where;
  EXPECT_LE(diff(rim.pose.tip, tip), 1e-12) << where;
  EXPECT_LE(diff(rim.pose.axis, axis), 1e-12) << where;
  // (a) p lies in K(t).
  const CoreDistance d = toCore(c.cutter, tip, axis, p);
  const double r = c.cutter.cornerRadius, L = c.cutter.fluteLength;
  const double membership = std::max(d.dist - r, d.s - L);
  st.worstMembership = std::max(st.worstMembership, membership);
  if (!(membership <= 1e-12)) {
    ++st.failures;
    ADD_FAILURE() << "the point is not in K(t): dist to the core - r = " << d.dist - r
                  << ", s - L = " << d.s - L << "; " << where;
    return;  // the checks below assume it
  }
  // The same through the reference's own membership (its profile), and the point is
  // at or above the reference's lowest point of that one cutter.
  EXPECT_TRUE(ref::inside(c.refCutter, tip, axis, p, 1e-9)) << where;
  const ref::RefHit standing = ref::stationaryLowest(c.refCutter, tip, axis, x, y);
  EXPECT_TRUE(standing.hit) << where;
  if (standing.hit) {
    EXPECT_GE(rim.z, standing.z - 1e-9) << where;
  }
  // (b) at or above the swept solid's lowest point.
  if (refLine) {
    if (!refLine->hit.hit) {
      if (!refLine->grazing) {
        ++st.failures;
        ADD_FAILURE() << "contact on a line the reference misses: " << where;
      }
    } else {
      const double below = refLine->hit.z - rim.z;
      st.worstBelowReference = std::max(st.worstBelowReference, below);
      if (!(below <= 1e-9)) {
        ++st.failures;
        ADD_FAILURE() << "below the reference's lowest point " << refLine->hit.z << " by " << below
                      << ": " << where;
      }
    }
  }
  // (c) a unit normal pointing down; where p is on K'(t)'s boundary (distance r from the
  // core), the outward normal there, (p - nearest) / dist, to within what the distance's
  // shortfall allows: the rim point c is at distance r from p, so |c - nearest|^2 <=
  // r^2 - dist^2 (C convex), and the normals differ by at most (|c - nearest| + r - dist)
  // / r. The shortfall counts the distance's round-off (1e-14 of the coordinates), which
  // the square root magnifies to ~1e-7.
  const double unit = std::fabs(length(rim.normal) - 1);
  st.worstNormal = std::max(st.worstNormal, unit);
  if (!(unit <= 1e-12 && rim.normal.z < 0)) {
    ++st.failures;
    ADD_FAILURE() << "normal (" << rim.normal.x << ", " << rim.normal.y << ", " << rim.normal.z
                  << ") not a unit downward vector: " << where;
  }
  if (d.dist >= r - 1e-12 && d.dist > 0) {
    ++st.onBoundary;
    const double shortfall = std::max(0.0, r - d.dist) + 1e-14 * (1 + length(p));
    const double allowed = (std::sqrt(2 * r * shortfall) + shortfall) / r;
    const double off = diff(rim.normal, (p - d.nearest) / d.dist);
    st.worstNormalBoundary = std::max(st.worstNormalBoundary, off);
    EXPECT_LE(off, allowed) << "normal is not K's outward normal: " << where;
  }
}

// Claims (a) to (c) on random turning moves, from the default start and from random
// starts, on lines through the footprint and just inside its edges.
TEST(RimContact, RandomTurningMovesGiveRealPointsOfTheCutter) {
  std::mt19937_64 rng(5150);
  std::uniform_real_distribution<double> u(0, 1);
  ContactStats st;
  int lines = 0, refHits = 0, grazing = 0, foundDefault = 0;
  for (int k = 0; k < 56; ++k) {
    const TurnCase c = randomTurningCase(rng, k, false);
    const PoseCurve curve = c.curve();
    const SweptMove move(c.cutter, curve);
    ASSERT_TRUE(move.turning());
    const Box3 box = move.bounds();
    for (int q = 0; q < 12; ++q) {
      double x, y;
      if (q < 10) {  // through the footprint's box, mostly its middle
        x = box.min.x + (box.max.x - box.min.x) * (0.15 + 0.7 * u(rng));
        y = box.min.y + (box.max.y - box.min.y) * (0.15 + 0.7 * u(rng));
      } else {
        edgeLine(c, 2 * kPi * u(rng), c.cutter.radius * (q == 10 ? 1e-3 : 1e-6), x, y);
      }
      ++lines;
      const RimContact fromMiddle = locateRimContact(c.cutter, curve, x, y);
      RimStart start;
      start.t = u(rng), start.hasDirection = true;
      const double phi = 2 * kPi * u(rng);
      start.cosPhi = std::cos(phi), start.sinPhi = std::sin(phi);
      const RimContact fromAnywhere = locateRimContact(c.cutter, curve, x, y, start);
      if (!fromMiddle.found && !fromAnywhere.found) continue;
      foundDefault += fromMiddle.found;
      const RefLine rl = reference(c, x, y);
      refHits += rl.hit.hit, grazing += rl.grazing;
      checkContact(c, x, y, fromMiddle, &rl, st, "default start");
      checkContact(c, x, y, fromAnywhere, &rl, st, "random start");
    }
  }
  std::printf(
      "RimContact random: %d lines, %d contacts (%d from the middle), %d reference hits, %d "
      "grazing; worst max(dist - r, s - L) = %.3g mm, worst reference - z = %.3g mm, "
      "worst | |n| - 1 | = %.3g, %d on K's boundary with worst normal error %.3g; %d failures\n",
      lines, st.found, foundDefault, refHits, grazing, st.worstMembership, st.worstBelowReference,
      st.worstNormal, st.onBoundary, st.worstNormalBoundary, st.failures);
  EXPECT_EQ(st.failures, 0);
  // The checks saw enough contacts to mean something: measured 244 on 672 lines (Newton
  // leaves its safe region on most lines of such turns, which the design allows, and many
  // lines of the box miss the solid); required just below.
  EXPECT_GE(st.found, 220);
}

// The same claim (a) where the flutes are shorter than twice the corner radius (L in
// [r, 2r), which Cutter::make accepts): a rim sphere's lowest point can then lie above
// the flute top, s > L, outside K(t). Axes leaning 50 to 80 degrees and lines towards
// the shank's side, where such points are lowest.
void shortFluteLine(const TurnCase& c, std::mt19937_64& rng, double& x, double& y) {
  std::uniform_real_distribution<double> u(0, 1);
  const Vec3 mid = c.tip(0.5), a = c.axis(0.5);
  const double ah = std::hypot(a.x, a.y);
  const Vec3 dir = ah > 1e-6 ? Vec3{a.x / ah, a.y / ah, 0} : Vec3{1, 0, 0};
  const double along = (c.cutter.fluteLength + c.cutter.radius) * u(rng);
  const double across = c.cutter.radius * (2 * u(rng) - 1);
  x = mid.x + dir.x * along - dir.y * across;
  y = mid.y + dir.y * along + dir.x * across;
}

TEST(RimContact, ShortFluteContactsAreRealPointsOfTheCutter) {
  std::mt19937_64 rng(777);
  ContactStats st;
  int lines = 0;
  for (int k = 0; k < 24; ++k) {
    const TurnCase c = randomTurningCase(rng, k, true, 50);
    const PoseCurve curve = c.curve();
    for (int q = 0; q < 6; ++q) {
      double x, y;
      shortFluteLine(c, rng, x, y);
      ++lines;
      checkContact(c, x, y, locateRimContact(c.cutter, curve, x, y), nullptr, st, "short flute");
    }
  }
  std::printf(
      "RimContact short flutes: %d lines, %d contacts; worst max(dist - r, s - L) = %.3g mm; "
      "%d failures\n",
      lines, st.found, st.worstMembership, st.failures);
  EXPECT_EQ(st.failures, 0);
  EXPECT_GE(st.found, 40);
}

// Claim (d): on CAM-like moves the contact is found on most lines inside the footprint
// and is the reference's lowest point to 1e-9 mm, from the default start and from the
// start the kernel uses (contact_knots.h). Short and long segments apart; lines whose
// lowest point lies on the corner (where the method applies) apart from the others (on
// a flat face: under the bottom of the cutter at the move's start or end; on a flank).
// A contact found elsewhere (a local minimum above the lowest point) is allowed by the
// design (the proof then fails and the certified search decides) and is counted.
TEST(RimContact, CamLikeMovesLocateTheLowestPoint) {
  std::mt19937_64 rng(31337);
  ContactStats st;
  struct Tally {
    int lines = 0, found = 0, exact = 0;
    double worst = 0;       // over the lines found at the lowest point (within 1e-9 mm)
    double worstFound = 0;  // over all found: a local minimum elsewhere is allowed
    void add(const RimContact& rim, double reference) {
      if (!rim.found) return;
      ++found;
      const double e = std::fabs(rim.z - reference);
      worstFound = std::max(worstFound, e);
      if (e <= 1e-9) ++exact, worst = std::max(worst, e);
    }
  };
  // [segment: short, long][lowest point: on the corner, elsewhere][start: middle, knots]
  Tally tally[2][2][2];
  int faces = 0, flanks = 0;
  for (int k = 0; k < 60; ++k) {
    const int seg = k % 2;
    const TurnCase c = camLikeCase(rng, k / 2, seg == 0 ? Segment::Short : Segment::Long);
    const PoseCurve curve = c.curve();
    const SweptMove move(c.cutter, curve);
    const uint64_t id = newContactKnotsId();
    for (int q = 0; q < 6; ++q) {
      double x, y;
      camLine(c, rng, q % 2 == 0, x, y);
      const RefLine rl = reference(c, x, y);
      if (!rl.hit.hit || rl.grazing) continue;
      const LowestPoint lp = move.lowestPoint(x, y);
      // Which part: from SweptMove's contact (its height checked against the reference).
      ASSERT_TRUE(lp.hit && std::fabs(lp.z - rl.hit.z) <= 1e-9)
          << c.describe() << " (" << x << ", " << y << ")";
      const Part part = partOf(c, lp.t, {x, y, lp.z});
      faces += part == Part::Face, flanks += part == Part::Flank;
      const int cls = part == Part::Corner ? 0 : 1;
      const RimContact a = locateRimContact(c.cutter, curve, x, y);
      const RimContact b = locateRimContact(
          c.cutter, curve, x, y, contactStart(id, kContactKnotSpacing, c.cutter, curve, x, y));
      checkContact(c, x, y, a, &rl, st, "CAM-like, default start");
      checkContact(c, x, y, b, &rl, st, "CAM-like, knots' start");
      ++tally[seg][cls][0].lines, ++tally[seg][cls][1].lines;
      tally[seg][cls][0].add(a, rl.hit.z);
      tally[seg][cls][1].add(b, rl.hit.z);
    }
  }
  const char* segments[] = {"short segments", "long segments"};
  const char* classes[] = {"lowest on the corner", "lowest elsewhere"};
  const char* starts[] = {"middle", "knots"};
  for (int seg = 0; seg < 2; ++seg)
    for (int cls = 0; cls < 2; ++cls)
      for (int from = 0; from < 2; ++from) {
        const Tally& t = tally[seg][cls][from];
        std::printf(
            "RimContact CAM-like, %s, %s, from the %s: %d lines, %d found, %d at the lowest "
            "point (%.1f %%, worst %.3g mm); %d elsewhere (up to %.3g mm above)\n",
            segments[seg], classes[cls], starts[from], t.lines, t.found, t.exact,
            100.0 * t.exact / std::max(1, t.lines), t.worst, t.found - t.exact, t.worstFound);
      }
  std::printf("RimContact CAM-like: lowest points elsewhere: %d on a flat face, %d on a flank\n",
              faces, flanks);
  EXPECT_EQ(st.failures, 0);
  for (int seg = 0; seg < 2; ++seg) ASSERT_GE(tally[seg][0][0].lines, 100);
  // Measured on corner lines (this seed): short segments 116 of 126 (92.1 %), long 112 of
  // 139 (80.6 %), the same from either start (the knots are located from the middle
  // too). The long segments' misses are lines whose contact lies far from the middle of
  // the move (t near 0 or 1 in every case looked at), where Newton from t = 0.5 stops.
  // Required just below.
  for (int from = 0; from < 2; ++from) {
    EXPECT_GE(tally[0][0][from].exact, 0.90 * tally[0][0][from].lines) << starts[from];
    EXPECT_GE(tally[1][0][from].exact, 0.78 * tally[1][0][from].lines) << starts[from];
  }
}

// A ball cutter turning about its standing tip T about a horizontal axis w: its centre
// c(theta) = T + r (cos theta z + sin theta h) (h the horizontal unit across w) runs on a
// vertical circle of radius r. On the vertical line at offsets X along h
// and Y along w from T, each sphere meets the plane of the circle's section in a circle of
// radius r' = sqrt(r^2 - Y^2) about c, lowest at
//     f(theta) = T_z + r cos(theta) - sqrt(r'^2 - (r sin(theta) - X)^2),
// whose only stationary point with the centre above T is on the envelope circle of
// radius r - r' about T: sin(theta*) = X / (r - r'), f(theta*) = T_z + (r - r')
// cos(theta*). So the lowest point is min(f(theta0), f(theta1), f(theta*) where theta*
// lies in the turn), valid while the line meets every sphere on the ball's lower half
// (below the centre along the axis: there the ball's lowest point is the cutter's),
// checked here on a fine scan.
TEST(RimContact, BallTurningAboutItsTipMatchesTheClosedForm) {
  std::mt19937_64 rng(8086);
  std::uniform_real_distribution<double> u(0, 1);
  int lines = 0, found = 0, kernel = 0;
  double worstRim = 0, worstKernel = 0;
  for (int k = 0; k < 40; ++k) {
    const double r = 0.5 + 4 * u(rng);
    const Cutter ball = Cutter::make(CutterType::Ball, r, 0, 4 * r);
    const double beta = 2 * kPi * u(rng);
    const Vec3 h{std::cos(beta), std::sin(beta), 0}, w{-h.y, h.x, 0}, z{0, 0, 1};
    const double th0 = (u(rng) - 0.5) * 1.4, th1 = th0 + (u(rng) - 0.5) * 1.2;
    const Vec3 T{5 * (u(rng) - 0.5), 5 * (u(rng) - 0.5), u(rng) - 0.5};
    auto axisAt = [&](double th) { return z * std::cos(th) + h * std::sin(th); };
    const PoseCurve curve = PoseCurve::linear({T, axisAt(th0)}, {T, axisAt(th1)});
    const SweptMove move(ball, curve);
    for (int q = 0; q < 4; ++q) {
      const double X = r * 0.9 * (2 * u(rng) - 1), Y = r * 0.9 * (2 * u(rng) - 1);
      const double x = T.x + X * h.x + Y * w.x, y = T.y + X * h.y + Y * w.y;
      const double rp = std::sqrt(r * r - Y * Y);
      auto f = [&](double th) {
        const double dx = r * std::sin(th) - X;
        return rp * rp - dx * dx > 0 ? T.z + r * std::cos(th) - std::sqrt(rp * rp - dx * dx)
                                     : HUGE_VAL;
      };
      // The precondition: the line meets every sphere, on its lower half.
      bool lowerHalf = true;
      for (int i = 0; i <= 4000 && lowerHalf; ++i) {
        const double th = th0 + (th1 - th0) * i / 4000.0, fz = f(th);
        if (fz == HUGE_VAL) {
          lowerHalf = false;
          break;
        }
        const Vec3 pc{X - r * std::sin(th), Y, fz - T.z - r * std::cos(th)};  // in (h, w, z)
        lowerHalf = pc.x * std::sin(th) + pc.z * std::cos(th) <= 0;
      }
      if (!lowerHalf) continue;
      double expected = std::min(f(th0), f(th1));
      if (std::fabs(X) < r - rp) {
        const double ts = std::asin(X / (r - rp));
        if (ts >= std::min(th0, th1) && ts <= std::max(th0, th1))
          expected = std::min(expected, T.z + (r - rp) * std::cos(ts));
      }
      if (expected == HUGE_VAL) continue;
      ++lines;
      const RimContact rim = locateRimContact(ball, curve, x, y);
      if (rim.found) {
        ++found;
        worstRim = std::max(worstRim, std::fabs(rim.z - expected));
        EXPECT_NEAR(rim.z, expected, 1e-9) << "case " << k << " line " << q;
      }
      const LowestPoint lp = move.lowestPoint(x, y);
      EXPECT_TRUE(lp.hit) << "case " << k << " line " << q;
      if (lp.hit) {
        ++kernel;
        worstKernel = std::max(worstKernel, std::fabs(lp.z - expected));
        EXPECT_NEAR(lp.z, expected, 1e-9) << "case " << k << " line " << q;
      }
    }
  }
  std::printf(
      "RimContact ball about its tip: %d lines, rim contact found on %d (worst %.3g mm), "
      "SweptMove on %d (worst %.3g mm) against the closed form\n",
      lines, found, worstRim, kernel, worstKernel);
  EXPECT_GE(lines, 80);
  EXPECT_GE(found, lines / 2);
}

// ---------------------------------------------------------------------------------------
// SweptMove::lowestPoint, whose fast path is now the rim contact, against the reference.

struct KernelStats {
  int hits = 0, misses = 0, grazing = 0, failures = 0;
  unsigned long long unproven = 0;
  double worst = 0, worstBelow = -HUGE_VAL;
};

void compareKernel(const TurnCase& c, const SweptMove& move, double x, double y, KernelStats& st,
                   bool requireProof = true) {
  const unsigned long long unprovenBefore = SweptMove::unprovenSearches();
  const LowestPoint lp = move.lowestPoint(x, y);
  const unsigned long long unproven = SweptMove::unprovenSearches() - unprovenBefore;
  st.unproven += unproven;
  const RefLine rl = reference(c, x, y);
  char where[200];
  std::snprintf(where, sizeof where, " at (%.17g, %.17g)", x, y);
  if (unproven && requireProof)
    ADD_FAILURE() << "search ran out of samples before its proof closed (kernel hit " << lp.hit
                  << " z " << lp.z << ", reference hit " << rl.hit.hit << " z " << rl.hit.z
                  << "): " << c.describe() << where;
  if (rl.grazing) {
    ++st.grazing;
    return;
  }
  if (lp.hit != rl.hit.hit) {
    ++st.failures;
    ADD_FAILURE() << "kernel hit " << lp.hit << " (z " << lp.z << "), reference hit " << rl.hit.hit
                  << " (z " << rl.hit.z << "): " << c.describe() << where;
    return;
  }
  if (!lp.hit) {
    ++st.misses;
    return;
  }
  ++st.hits;
  const double err = lp.z - rl.hit.z;
  st.worst = std::max(st.worst, std::fabs(err));
  st.worstBelow = std::max(st.worstBelow, -err);
  if (!(std::fabs(err) <= 1e-9)) {
    ++st.failures;
    char vals[160];
    std::snprintf(vals, sizeof vals, "kernel %.17g reference %.17g (t %.17g): ", lp.z, rl.hit.z,
                  lp.t);
    ADD_FAILURE() << vals << c.describe() << where;
  }
}

void printKernel(const char* what, const KernelStats& st) {
  std::printf(
      "RimContact SweptMove %s: %d hits, %d misses, %d grazing skipped, %d failures, %llu "
      "unproven searches; worst |kernel - reference| = %.3g mm, worst reference - kernel = "
      "%.3g mm\n",
      what, st.hits, st.misses, st.grazing, st.failures, st.unproven, st.worst, st.worstBelow);
}

// Lines over the groove and anywhere over the tip's path of CAM-like moves.
TEST(RimContact, SweptMoveAgreesWithBruteForceOnCamLikeMoves) {
  std::mt19937_64 rng(4242);
  KernelStats st;
  for (int k = 0; k < 32; ++k) {
    const TurnCase c = camLikeCase(rng, k);
    const SweptMove move(c.cutter, c.curve());
    for (int q = 0; q < 5; ++q) {
      double x, y;
      camLine(c, rng, q < 3, x, y);
      compareKernel(c, move, x, y, st);
    }
  }
  printKernel("CAM-like", st);
  EXPECT_EQ(st.failures, 0);
  EXPECT_EQ(st.unproven, 0u);
  EXPECT_GE(st.hits, 140);
}

// Lines just inside the footprint's edges of CAM-like moves (1e-2 and 1e-4 R in).
TEST(RimContact, SweptMoveAgreesWithBruteForceNearCamLikeEdges) {
  std::mt19937_64 rng(4243);
  std::uniform_real_distribution<double> u(0, 1);
  KernelStats st;
  for (int k = 0; k < 24; ++k) {
    const TurnCase c = camLikeCase(rng, k);
    const SweptMove move(c.cutter, c.curve());
    for (int q = 0; q < 2; ++q) {
      double x, y;
      edgeLine(c, 2 * kPi * u(rng), c.cutter.radius * (q == 0 ? 1e-2 : 1e-4), x, y);
      compareKernel(c, move, x, y, st);
    }
  }
  printKernel("near CAM-like edges", st);
  EXPECT_EQ(st.failures, 0);
  EXPECT_GE(st.hits, 30);
}

// A line near the footprint's edge whose lowest point is on the flank (t = 0.282), where
// the line first touches the flute top's rim: it meets the cutter only for t in
// (0.28201210, 0.38), leaving it through the flute top. For t below that it misses, but
// the grown cutter and the ray clearance see the flank as if it went on above the flute
// top, so they proved the miss only on intervals whose width shrank in proportion to
// their distance from the touch: the search ran out of its 1 024 samples with its height
// right (2.5e-10 mm from the reference) but unproven. The flute top's bound
// (interval_bounds.cpp step 2e) closes it.
TEST(RimContact, FlankLineNearTheEdgeClosesItsProof) {
  Cutter cutter =
      Cutter::make(CutterType::Bull, 2.3652465323973457, 1.123682671710263, 6.3833612668695023);
  const PoseCurve curve =
      PoseCurve::linear({{3.7700696536383074, 2.0403953206881829, -0.49777901825387594},
                         {0.093084928413781923, 0.20016961062516353, 0.97532934083025091}},
                        {{3.8059290346596915, 2.5365903519764808, -0.49777901825387594},
                         {0.079844064776746618, 0.21095953497301806, 0.97422841260347903}});
  const SweptMove move(cutter, curve);
  const unsigned long long before = SweptMove::unprovenSearches();
  const LowestPoint lp = move.lowestPoint(6.6961881363609574, 3.6493752880627883);
  EXPECT_TRUE(lp.hit);
  EXPECT_NEAR(lp.z, 5.4755369803608041, 1e-9);  // the brute-force reference's height
  EXPECT_EQ(SweptMove::unprovenSearches() - before, 0u);
}

// SweptMove on short-flute cutters (L in [r, 2r)): its height is the true lowest point,
// and a line the solid misses stays a miss.
TEST(RimContact, SweptMoveAgreesWithBruteForceOnShortFlutes) {
  std::mt19937_64 rng(1999);
  KernelStats st;
  for (int k = 0; k < 20; ++k) {
    const TurnCase c = randomTurningCase(rng, k, true, 50);
    const SweptMove move(c.cutter, c.curve());
    for (int q = 0; q < 5; ++q) {
      double x, y;
      shortFluteLine(c, rng, x, y);
      compareKernel(c, move, x, y, st);
    }
  }
  printKernel("short flutes", st);
  EXPECT_EQ(st.failures, 0);
  EXPECT_GE(st.hits, 30);
}

// The smallest such cases: a hemispherical ball (L = R = 1) leaning 80 degrees and a bull
// whose flutes end at its corner (R 3, r = L = 1) leaning 60 degrees, each turning by 2
// degrees while it moves 0.1 mm. Lines beyond the rim along the lean: the rim sphere's
// lowest point there lies above the flute top (s > L), outside the cutter.
TEST(RimContact, ShortFlutesLeaningAlongTheLine) {
  struct Line {
    double x, y;
  };
  struct Case {
    TurnCase c;
    std::vector<Line> lines;
  };
  const double d80 = degToRad(80), d78 = degToRad(78), d60 = degToRad(60), d58 = degToRad(58);
  const Case cases[] = {
      {makeCase(CutterType::Ball, 1, 0, 1, {0, 0, 0}, {0.1, 0, 0},
                {std::sin(d80), 0, std::cos(d80)}, {std::sin(d78), 0.01, std::cos(d78)}),
       {{0.5, 0}, {1.2, 0}, {1.5, 0}, {1.8, 0}}},
      {makeCase(CutterType::Bull, 3, 1, 1, {0, 0, 0}, {0.1, 0, 0},
                {std::sin(d60), 0, std::cos(d60)}, {std::sin(d58), 0.01, std::cos(d58)}),
       {{1.75, -1.6}, {2.25, -2}, {2.5, -1.6}}}};
  ContactStats contacts;
  KernelStats st;
  for (const Case& k : cases) {
    const SweptMove move(k.c.cutter, k.c.curve());
    for (const Line& l : k.lines) {
      checkContact(k.c, l.x, l.y, locateRimContact(k.c.cutter, k.c.curve(), l.x, l.y), nullptr,
                   contacts, "short flute");
      compareKernel(k.c, move, l.x, l.y, st);
    }
  }
  printKernel("short flutes along the lean", st);
  std::printf(
      "RimContact short flutes along the lean: %d contacts, worst max(dist - r, s - L) = %.3g "
      "mm\n",
      contacts.found, contacts.worstMembership);
  EXPECT_EQ(contacts.failures, 0);
  EXPECT_EQ(st.failures, 0);
}

}  // namespace
}  // namespace scallop
