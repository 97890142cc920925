// The ray-clearance proof for a move whose axis turns.
//
// Notation as in swept_move.cpp: pose(t) from a PoseCurve (tip(t) = p0 + t Delta, or a
// curve with TCP off), the cutter turned rigidly by R(t) about its tip, |Omega| <= omega.
// Every cutter is
//     K = ( C (+) Ball(r) ) n { s <= L },   C = Cyl(Rb; s in [r, L])        (cutter.h)
// so K lies in K' = C (+) Ball(r), and a point p lies outside K' iff dist(p, C) > r.
// dist(., C) is the distance to a convex set: convex and 1-Lipschitz, with the closed
// form dist = hypot(max(0, rho - Rb), max(0, r - s, s - L)) in the cutter's frame
// (s along the axis, rho across it).
//
//   1. The cutter's frame at the anchor ts. Seen from the cutter, Q moves along
//          gamma(t) = R(ts) R(t)^-1 (Q - tip(t)),   gamma(ts) = Q - tip(ts),
//          gamma'(ts) = -tip'(ts) - Omega(ts) x (Q - tip(ts)),
//      and world up is d(t) = R(ts) R(t)^-1 z, d(ts) = z. The curve's rates bound R^-1
//      as they bound R (both kinds are products of rotations at constant rates about
//      fixed axes; so are their inverses): |gamma'| <= V = S + omega D and
//      |gamma''| <= E = omega^2 D + 2 omega S + A, D >= |Q - tip(t)| on [t0, t1],
//      S >= |tip'| there and A >= |tip''| (A = 0 and S = |p1 - p0| for a linear tip;
//      the tip of a machine with TCP off follows a curve, pose_curve.h),
//      |d'| <= omega. So gamma stays within E tau^2 / 2 of its tangent line
//      ell(tau) = gamma(ts) + tau gamma'(ts), tau = t - ts (Taylor, integral form).
//   2. Outside. h(tau) = dist(ell(tau), C) is convex in tau (a convex function along a
//      line), so h lies above its tangent at any tau_k. With the 1-Lipschitz distance,
//          dist(gamma(t), C) >= h(tau) - E tau^2 / 2
//                            >= h(tau_k) + h'(tau_k)(tau - tau_k) - E tau^2 / 2,
//      a concave function of tau: where it exceeds r at both ends of a rung
//      [tau_k, tau_k+1], every gamma(t) of the rung lies outside K'. Rungs are as long as
//      that allows (the root of a quadratic), starting at the anchor and walking out to
//      t0 and to t1; each costs one closed-form distance and its derivative.
//   3. Below. Outside is not enough: the line could pass through K(t) entirely below
//      Q. Let c be the point of C nearest gamma, n the unit vector from c to gamma.
//      C lies in n.(p - c) <= 0, so K' lies in n.(p - c) <= r, while the downward ray
//      gamma - lambda d has n.(gamma - lambda d - c) = dist - lambda n.d > r for all
//      lambda >= 0 when n.d <= 0. The unit vector from a convex set's nearest point is
//      (1/m)-Lipschitz among points at distance >= m (here m = r, by step 2), so over
//      the whole range n.d <= n0.z + (2 V / r + omega) |tau| (a factor 2 to spare),
//      checked once. Then the ray misses K'(t), hence K(t): f(t) > Q.z.
// A disc of rays. Every downward ray from a point Q' within rho of Q is, seen from the
// cutter, gamma + w with |w| <= rho. With margin rho added to step 2's need
// (dist(gamma, C) > r + rho, so dist(gamma + w, C) > r) and rho / r to step 3's bound
// (n moves by at most rho / r between the two, by the same Lipschitz constant), each
// of those rays misses K(t) as the argument above has it for one.
// A flat cutter (r = 0) has no such m near its rim, so it is never cleared here.
// Round-off: every inequality keeps a slack of 1e-12 (1 + D + L) mm, far below the
// 1e-9 mm proof gap the callers leave.
#include "sweep/ray_clearance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace scallop {

namespace {

constexpr int kMaxRungs = 48;  // per side; typical: 1 to 4 (growing rungs)

// A point p in the cutter's frame split along the axis: s = p.a, its part across the
// axis and that part's length rho; and h0 = dist(p, C).
struct AxialPoint {
  double s;
  Vec3 perp;
  double rho, h0;
};

// dist(p, C) and its gradient (the unit vector from the nearest point of C), in the
// cutter's frame: tip at the origin, unit axis a. p must lie outside C (dist > 0).
// `axial`, if given, keeps the split of p the distance came from.
struct CoreDistance {
  double rb, r, L;
  Vec3 a;
  double at(const Vec3& p, Vec3* gradient, AxialPoint* axial = nullptr) const {
    const double s = dot(p, a);
    const Vec3 perp = p - a * s;
    const double rho = length(perp);
    const double dx = std::max(0.0, rho - rb);
    double ds = 0, sign = 0;
    if (s < r) ds = r - s, sign = -1;
    if (s > L) ds = s - L, sign = 1;
    const double dist = std::sqrt(dx * dx + ds * ds);
    if (gradient && dist > 0) {
      const double radial = rho > rb ? dx / rho : 0;
      *gradient = (perp * radial + a * (sign * ds)) / dist;
    }
    if (axial) *axial = {s, perp, rho, dist};
    return dist;
  }
  // d^2/dtau^2 of dist(p + tau v, C) at tau = 0 (p outside C): 0 below the flat bottom,
  // rho'' on the side, and (rho'^2 + s'^2 - dist'^2 + (rho - Rb) rho'') / dist at the
  // rim (step 2's curvature bound has the derivation); NaN above the top.
  double curvatureAlong(const Vec3& p, const Vec3& v) const {
    const double s = dot(p, a), sv = dot(v, a);
    const Vec3 perp = p - a * s, vPerp = v - a * sv;
    const double rho = length(perp);
    if (s > L) return std::numeric_limits<double>::quiet_NaN();
    if (!(rho > rb)) return 0;
    const double rhoDot = dot(perp, vPerp) / rho;
    const double rhoDDot = (dot(vPerp, vPerp) - rhoDot * rhoDot) / rho;
    if (s >= r) return rhoDDot;
    const double X = rho - rb, sigma = r - s, d = std::sqrt(X * X + sigma * sigma);
    const double dDot = (X * rhoDot - sigma * sv) / d;
    return (rhoDot * rhoDot + sv * sv - dDot * dDot + X * rhoDDot) / d;
  }
};

// Step 2 along one side: the tangent line ell(tau) = p + tau v, tau in [0, T], proven
// outside K' (dist(gamma, C) > r) rung by rung.
bool sideClears(const CoreDistance& core, const Vec3& p, const Vec3& v, double T, double E,
                double slack, double margin) {
  if (!(T > 0)) return true;
  const double need = core.r + margin + slack;  // dist(gamma, C) must exceed this
  double u = 0, last = 0;                       // the rung's start, the last rung's length
  for (int rung = 0; rung < kMaxRungs; ++rung) {
    Vec3 grad;
    const double hu = core.at(p + v * u, &grad);
    const double g = dot(grad, v);
    if (!(hu - 0.5 * E * u * u > need)) return false;
    // The rung's far end: where hu + g (tau - u) - E tau^2 / 2 falls to `need`.
    const double c0 = hu - g * u - need;
    double far;
    if (E > 0) {
      far = (g + std::sqrt(g * g + 2 * E * c0)) / E;
    } else {
      far = g >= 0 ? HUGE_VAL : u + (hu - need) / -g;
    }
    const double next = std::min(T, u + 0.95 * (far - u));
    if (!(hu + g * (next - u) - 0.5 * E * next * next > need)) return false;
    if (next >= T) return true;
    // Rungs that shrink are closing in on a contact: the proof would fail there.
    if (!(next - u > std::max(1e-12, 0.5 * last))) return false;
    last = next - u;
    u = next;
  }
  return false;
}

// Step 2 with curvature, both sides at once: where the nearest point of C to ell stays
// the rim (rho > Rb and s < r along the whole range), h = hypot(rho - Rb, r - s) and
//     h'' = (rho'^2 + s'^2 - h'^2 + (rho - Rb) rho'') / h >= (w x g)^2 / h,
// w = (rho', -s') and g the unit vector from the rim to ell in the (rho, s) plane
// (rho'' >= 0: rho is convex along a line). Over |tau| <= T, w moves by at most
// T |v_perp|^2 / rho_min (|rho''| <= |v_perp|^2 / rho, s'' = 0) and g by T |v| / h_min
// (|w| <= |v|), which bounds w x g below by c; then h'' >= m = c^2 / h_max and
//     h(tau) - E tau^2 / 2 >= h(0) + h'(0) tau + (m - E) tau^2 / 2,
// a parabola whose minimum over [-left, right] is closed form. Near a minimum of f
// (h'(0) ~ 0, h(0) - r ~ 1e-9 mm) this proves in one evaluation what the rungs need
// ~10 for (their tangents only halve their distance to the minimum).
// `at` is ell(0) as CoreDistance::at left it in step 3.
bool curvatureClears(const CoreDistance& core, const AxialPoint& at, const Vec3& v, double left,
                     double right, double E, double slack, double margin) {
  const double T = std::max(left, right);
  const double sv = dot(v, core.a);
  const Vec3 vPerp = v - core.a * sv;
  const double rho = at.rho, vp = length(vPerp), speed = length(v);
  const double X = rho - core.rb, sigma = core.r - at.s;
  // The rim regime over the whole range, and h bounded away from 0.
  if (!(X > vp * T && sigma > std::fabs(sv) * T && rho > vp * T)) return false;
  const double h0 = at.h0;  // hypot(X, sigma) in this regime
  const double hMin = h0 - speed * T, hMax = h0 + speed * T;
  if (!(hMin > 0)) return false;
  const double rhoDot = dot(at.perp, vPerp) / rho;
  const double h1 = (X * rhoDot - sigma * sv) / h0;  // h'(0)
  const double c0 = std::fabs(rhoDot * sigma - (-sv) * X) / h0;
  const double drift = T * vp * vp / (rho - vp * T) + speed * T * speed / hMin;
  const double c = std::max(0.0, c0 - drift);
  const double m = c * c / hMax;
  if (!(m > E)) return false;
  const double k = m - E;
  const double tau = std::clamp(-h1 / k, -left, right);
  return h0 + h1 * tau + 0.5 * k * tau * tau > core.r + margin + slack * (1 + h0);
}

// The proof from the pose at the anchor (tip, axis, tip velocity and spin there).
bool clearsFrom(const Cutter& c, const PoseCurve& curve, const Vec3& q, double anchor,
                const Vec3& tip, const Vec3& axis, const Vec3& vel, const Vec3& spin, double t0,
                double t1, bool* insideAtAnchor, double margin = 0) {
  const double omega = curve.turnRate(), A = curve.tipAccelBound();
  const Vec3 g0 = q - tip;
  const Vec3 g1 = -vel - cross(spin, g0);  // gamma'(anchor)
  const double left = anchor - t0, right = t1 - anchor, reach = std::max(left, right);
  const double move = length(vel) + A * reach;  // >= |tip'| over the range
  const double D = length(g0) + move * reach;
  const double V = move + omega * D;
  const double E = (omega * omega * D + 2 * omega * move + A) * (1 + 1e-12);
  const CoreDistance core{c.bottomRadius(), c.cornerRadius, c.fluteLength, axis};
  const double slack = 1e-12 * (1 + D + c.fluteLength);

  // Step 3 first (cheap, and it needs dist > 0 at the anchor anyway); the split of g0
  // it leaves serves step 2's curvature bound.
  Vec3 n0;
  AxialPoint at;
  if (!(core.at(g0, &n0, &at) > core.r + margin + slack)) {
    if (insideAtAnchor) *insideAtAnchor = true;
    return false;
  }
  if (!(n0.z + (2 * V / core.r + omega) * reach + margin / core.r < 0)) return false;
  // Step 2 for a line far from the cutter (most of the moves a cell settles from their
  // middle: the lines of other passes, 80 um or more above): gamma moves at most
  // V |tau|, so the 1-Lipschitz distance stays above h0 - V reach.
  if (at.h0 - V * reach > core.r + margin + slack) return true;
  // Step 2: the curvature bound in one go where it applies, else rungs on both sides.
  if (curvatureClears(core, at, g1, left, right, E, slack, margin)) return true;
  return sideClears(core, g0, g1, right, E, slack, margin) &&
         sideClears(core, g0, -g1, left, E, slack, margin);
}

}  // namespace

bool rayClearsMove(const Cutter& c, const PoseCurve& curve, const Vec3& q, double anchor, double t0,
                   double t1, bool* insideAtAnchor) {
  if (insideAtAnchor) *insideAtAnchor = false;
  if (c.general() || !(c.cornerRadius > 0) || !(t0 <= anchor && anchor <= t1)) return false;
  return clearsFrom(c, curve, q, anchor, curve.tip(anchor), curve.axis(anchor),
                    curve.tipVelocity(anchor), curve.spin(anchor), t0, t1, insideAtAnchor);
}

bool raysClearMove(const Cutter& c, const PoseCurve& curve, const Vec3& q, double radius) {
  if (c.general() || !(c.cornerRadius > 0) || !(radius >= 0)) return false;
  return clearsFrom(c, curve, q, 0.5, curve.tip(0.5), curve.axis(0.5), curve.tipVelocity(0.5),
                    curve.spin(0.5), 0, 1, nullptr, radius);
}

bool rayClearsMove(const Cutter& c, const PoseCurve& curve, const Vec3& q, const PoseFrame& anchor,
                   double t0, double t1, bool* insideAtAnchor) {
  if (insideAtAnchor) *insideAtAnchor = false;
  if (c.general() || !(c.cornerRadius > 0) || !(t0 <= anchor.t && anchor.t <= t1)) return false;
  return clearsFrom(c, curve, q, anchor.t, anchor.tip, anchor.axis, anchor.velocity, anchor.spin,
                    t0, t1, insideAtAnchor);
}

double lowestPointCurvature(const Cutter& c, const PoseCurve& curve, double t, const Vec3& p) {
  // f(t) solves G(t, f(t)) = 0 for G(t, z) = dist(gamma_z(t), C) - r (the point at
  // height z of the line, seen from the cutter as in step 1), so implicit
  // differentiation gives f' = -G_t / G_z and
  //     f'' = -(G_tt + 2 G_tz f' + G_zz f'^2) / G_z,
  // with G_t = g.gamma', G_tt = gamma'.H gamma' + g.gamma'', G_tz = z.H gamma' + g.(-Omega x z),
  // G_zz = z.H z, where g and H are the gradient and Hessian of dist(., C) and, at the
  // sample, gamma' = -tip' - Omega x u, gamma'' = Omega x (Omega x u) - Omega' x u +
  // 2 Omega x tip' - tip'' for u = p - tip(t) (tip'' left out: it is 0 for a linear tip,
  // and this only chooses where to sample).
  // The core and its radius r are those of ball, flat and bull cutters.
  if (c.general()) return std::numeric_limits<double>::quiet_NaN();
  const Vec3 tip = curve.tip(t);
  const CoreDistance core{c.bottomRadius(), c.cornerRadius, c.fluteLength, curve.axis(t)};
  const Vec3 u = p - tip, delta = curve.tipVelocity(t);
  const Vec3 w = curve.spin(t), wDot = curve.spinRate(t), up{0, 0, 1};
  const Vec3 v = -delta - cross(w, u);
  const Vec3 acc = cross(w, cross(w, u)) - cross(wDot, u) + cross(w, delta) * 2;
  Vec3 g;
  if (!(core.at(u, &g) > 0) || !(g.z < 0)) return std::numeric_limits<double>::quiet_NaN();
  const double vHv = core.curvatureAlong(u, v), zHz = core.curvatureAlong(u, up);
  const double zHv = 0.25 * (core.curvatureAlong(u, v + up) - core.curvatureAlong(u, v - up));
  const double Gz = g.z, Gt = dot(g, v);
  const double Gtt = vHv + dot(g, acc), Gtz = zHv - dot(g, cross(w, up));
  const double f1 = -Gt / Gz;
  return -(Gtt + 2 * Gtz * f1 + zHz * f1 * f1) / Gz;
}

}  // namespace scallop
