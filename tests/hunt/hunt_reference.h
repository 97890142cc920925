// The exactness hunt's reference: rigorous brackets of a swept solid's lowest point on a
// vertical line, written from the definitions in CONVENTIONS.md ("Cutters", "Tool pose",
// "Machines") and sharing no code with sweep/ (only Vec3 from base/).
//
// A move is a pose curve t in [0, 1] -> (tip(t), axis(t)) of a cutter of the torus family
// K = (K0 (+) Ball(r)) n {s <= L}, K0 the solid cylinder of radius Rb = R - r between
// s = r and s = L (ball: Rb = 0; flat: r = 0). The kernel's height z at (x, y) is checked
// from both sides, each by a certificate that is a proof and not a sample:
//
//   * not too deep: the point (x, y, z + tol) lies in some K(t). A best-first search over
//     intervals of t evaluates the signed distance phi of the point to K(t_mid); no t in
//     an interval of half-width h can bring it inside if phi exceeds the most any body
//     point moves in h (speed bound S and turn rate w: S h + w h (|p - tip| + S h)). Found:
//     proven. Every interval excluded: proven too deep.
//   * not too high: the ray below (x, y, z - tol) misses every K(t). Over an interval of t,
//     the cutters lie in K(t_mid) grown by eps = w h |k|max + A h^2 / 2 (A: the tip's
//     acceleration bound) swept along the chord tip(t0) -> tip(t1): a convex solid. A
//     separating plane proves the miss: its normal n (from the nearest point of that
//     solid to the ray's top, a golden-section search over the chord of a convex
//     distance) is checked with the closed-form support function
//         h(n) = h_K(n) + eps |n| + max(n . c0, n . c1),
//         h_K(n) = max(r n.a + Rb |n_perp| + r (n.a <= 0 ? |n| : |n_perp|), L n.a + R |n_perp|)
//     (the lowest quarter of the torus and the top rim are K's extreme points), and it
//     proves the whole ray when n.z <= 0. Intervals that no plane separates are halved; a
//     short one whose own cutter reaches below the ray's top proves the kernel too high.
// A constant-axis straight move is one interval with eps = 0: the plane is the exact dual
// certificate of a convex solid, which is what makes flat faces (a flat end mill moving in
// its bottom plane) cheap. Intervals are capped; a check that runs out says "unresolved".
#pragma once

#include <functional>
#include <string>

#include "base/vec3.h"

namespace scallop::hunt {

// A cutter of the torus family (ball: r = R; flat: r = 0), mm.
struct HuntCutter {
  double R = 0, r = 0, L = 0;
  double Rb() const { return R - r; }
  // The largest distance of a cutter point from its tip.
  double reach() const { return std::sqrt(L * L + R * R); }
  // K (+) Ball(eps) lies in the cutter (R + eps, r + eps, L + 2 eps) whose tip is eps
  // below along the axis.
  HuntCutter grown(double eps) const { return {R + eps, r + eps, L + 2 * eps}; }
};

// A move as the reference sees it: its poses and the bounds the certificates use.
struct HuntCurve {
  std::function<Vec3(double)> tip, axis;
  double speed = 0;  // >= |tip'(t)|, mm per unit t
  double accel = 0;  // >= |tip''(t)|, mm per unit t^2 (0: the tip moves straight)
  double turn = 0;   // >= the axis' angular speed, rad per unit t
};

// Signed distance-like function of a point p (tool frame: tip at the origin, unit axis a):
// <= 0 exactly inside K, and 1-Lipschitz in p.
double insideMeasure(const HuntCutter& c, const Vec3& a, const Vec3& p);
// Support function h_K(n) (tip at the origin), any n.
double supportValue(const HuntCutter& c, const Vec3& a, const Vec3& n);
// The lowest z of the stationary cutter (tip, axis) on the vertical line (x, y):
// Newton's method from below on the convex insideMeasure, so the value returned is at or
// below the true one to round-off; false: the line misses it.
bool stationaryLowest(const HuntCutter& c, const Vec3& tip, const Vec3& a, double x, double y,
                      double* z);

enum class Verdict { kProven, kFails, kUnresolved };

// (x, y, z) lies in the swept solid (within round-off).
Verdict provesReached(const HuntCutter& c, const HuntCurve& curve, const Vec3& p);
// The ray below (x, y, z) misses the swept solid. On kFails, `*lower` receives a height of
// a real cutter position on the line below z.
Verdict provesClear(const HuntCutter& c, const HuntCurve& curve, const Vec3& p,
                    double* lower = nullptr);

// The curves of the hunt, with their bounds, from the numbers a path file states.
HuntCurve straightCurve(const Vec3& p0, const Vec3& p1, const Vec3& a0, const Vec3& a1);
// Table-table machines (CONVENTIONS.md "Machines"), angles in radians, linear in t.
// `tableAC`: xyzac-trt, else xyzbc-trt. TCP on: the tip straight from p0 to p1.
HuntCurve rotaryCurve(bool tableAC, const Vec3& p0, const Vec3& p1, double tilt0, double tilt1,
                      double spin0, double spin1);
// TCP off, pivot and offsets zero: joints linear, the tip their forward kinematics.
HuntCurve jointCurve(bool tableAC, const Vec3& j0, const Vec3& j1, double tilt0, double tilt1,
                     double spin0, double spin1);
// A G-code arc in the XY plane (G17) about `centre`, from angle th0 by `sweep` radians
// (positive: counter-clockwise, G3), radius `rho`, the tip rising by `rise`; fixed axis.
HuntCurve arcCurve(const Vec3& centre, double rho, double th0, double sweep, double rise,
                   const Vec3& axis);

}  // namespace scallop::hunt
