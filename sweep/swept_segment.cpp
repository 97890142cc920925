// Exact lowest point of a swept cutter on a vertical line.
//
// Notation (tool frame: tip at the origin, unit axis a, s = p.a, rho = distance from
// the axis): the cutter is K = (K0 (+) Ball(r)) with s <= L, where K0 is the solid
// cylinder of radius Rb = R - r between s = r and s = L (cutter.h). K is convex.
//
// The swept solid of a move d is C = K (+) [0, d]. Its lowest point on the vertical
// line l through q is found by a reduction to two dimensions:
//
//   1. Every point of C on l is k + t d with k in K and t in [0, 1]. Because d lies in
//      the vertical plane P that contains l and is parallel to d, k lies in P too. So
//      only the plane section S = K n P matters, and l n C is the lowest point of the
//      2D Minkowski sum S (+) [0, d] on the line u = u0 (u: horizontal coordinate
//      along d in P).
//   2. With lambda(v) the (convex) lower boundary of S and sigma = dz / |d_xy| the slope
//      of the move, the lowest point is
//          z* = min over v in [u0 - |d_xy|, u0] of  lambda(v) + (u0 - v) sigma,
//      a convex function of v. Its unconstrained minimiser is the support point of S
//      in direction n = sigma u_hat - z_hat (the point where S's lower boundary has
//      slope sigma: the envelope or "grazing" point). Clamped to the interval, the
//      minimiser is either that point swept along d, or the cutter at the start
//      (t = 0) or at the end (t = 1) of the move.
//   3. The support point of the section S in direction n is the support point of K in
//      a direction n cos(theta) + m sin(theta) (m: normal of P) for the theta at which
//      it lies on P (Lagrange). Its offset from P is monotone in theta, so it is found
//      by a bracketing root finder on closed-form support points of K. Where the
//      support point jumps (a flat face), the chord between the bracketing points lies
//      on the face and crosses P: that is the section's support point.
//
// The stationary cutter's lowest point on a vertical line (the t = 0 / t = 1 cases)
// is the lowest root of the convex function Phi(z) = max(dist(p, K0) - r, s - L)
// along the line, found by Newton's method from below: for a convex function the
// tangent root never overshoots the lowest root, so the iteration is monotone.
#include "sweep/swept_segment.h"

#include <algorithm>
#include <cmath>

#include "sweep/profile_lowest_point.h"

namespace scallop {

namespace {

// Distance from p (tool frame) to K0, for the Newton iteration: its value and slope
// along z on every step, the whole gradient only for the normal of the answer.
struct DistanceToCore {
  Vec3 perp;           // p minus its axial part
  double rho, ds, dr;  // distance from the axis; axial and radial excess over K0
  double value;        // the distance, sqrt(ds^2 + dr^2)

  Vec3 gradient(const Vec3& a) const {
    if (!(value > 0)) return {};
    Vec3 grad = a * (ds / value);
    if (dr > 0) grad += perp * (dr / (value * rho));
    return grad;
  }
  double slopeZ(const Vec3& a) const {
    if (!(value > 0)) return 0;
    return (ds * a.z + (dr > 0 ? dr * perp.z / rho : 0.0)) / value;
  }
};

DistanceToCore distanceToCore(const Cutter& c, const Vec3& a, const Vec3& p) {
  const double r = c.cornerRadius, L = c.fluteLength, Rb = c.bottomRadius();
  DistanceToCore d;
  const double s = dot(p, a);
  d.perp = p - a * s;
  d.rho = length(d.perp);
  d.ds = s < r ? s - r : (s > L ? s - L : 0.0);
  d.dr = d.rho > Rb ? d.rho - Rb : 0.0;
  d.value = std::sqrt(d.ds * d.ds + d.dr * d.dr);
  return d;
}

// A support point of K in direction v and, on the smooth parts (the torus and the top
// rim), its derivative along dv: d/dt of the support point of v + t dv at t = 0, which the
// Newton steps of the section search use. dv = 0 gives the plain support point.
struct SupportWithSlope {
  Vec3 point, slope;
};

// K's support point for a direction v with unit radial part e: the top rim (s = L) when v
// points towards the shank (`top`), else the torus point, bottom rim + r v / |v|
// (`rOverLength` = r / |v|). The one place these two formulas are written.
Vec3 rimOrTorusPoint(const Cutter& c, const Vec3& a, const Vec3& e, const Vec3& v,
                     double rOverLength, bool top) {
  if (top) return a * c.fluteLength + e * c.radius;
  return a * c.cornerRadius + e * c.bottomRadius() + v * rOverLength;
}

inline __attribute__((always_inline)) SupportWithSlope supportWithSlope(const Cutter& c,
                                                                        const Vec3& a,
                                                                        const Vec3& v,
                                                                        const Vec3& dv) {
  const double va = dot(v, a);
  // The radial part of v, re-orthogonalised: for v (anti)parallel to a the first
  // subtraction leaves round-off that may point along a itself. Below 1e-14 |v| the
  // direction is treated as axial, whose support set is a whole end face; its centre
  // is returned (and no slope).
  Vec3 perp = v - a * va;
  perp -= a * dot(perp, a);
  const double lp = length(perp);
  const double len = length(v);
  const bool radial = lp > 1e-14 * len;
  const Vec3 e = radial ? perp / lp : Vec3{};
  Vec3 de;
  if (radial) {
    const Vec3 dperp = dv - a * dot(dv, a);
    de = (dperp - e * dot(e, dperp)) / lp;
  }
  // Pointing towards the shank: the rim of the flat top at s = L. Pointing down or
  // sideways: the torus (ball, or the sharp rim of a flat cutter when r = 0).
  const Vec3 point = rimOrTorusPoint(c, a, e, v, c.cornerRadius / len, va > 0);
  if (va > 0) return {point, de * c.radius};
  const Vec3 vh = v / len;
  const Vec3 dvh = (dv - vh * dot(vh, dv)) / len;
  return {point, radial ? de * c.bottomRadius() + dvh * c.cornerRadius : Vec3{}};
}

}  // namespace

Vec3 cutterSupport(const Cutter& c, const Vec3& a, const Vec3& dir) {
  if (c.general()) return profileSupport(*c.profile, a, dir);
  return supportWithSlope(c, a, dir, Vec3{}).point;
}

namespace {

// The highest of two supporting planes of K on the vertical line through (x, y), a
// lower bound of Phi's lowest root that is tight where the line meets the bottom face
// or the torus near its point at z0:
//  - the bottom face's plane s = 0 (K lies in s >= 0), exact where the line crosses
//    the face itself;
//  - the torus's tangent plane at the point whose nearest spine point (the circle of
//    radius Rb at s = r) lies in the radial direction e of the line's point at z0, at
//    the torus angle beta with Rb + r sin(beta) = that point's distance from the axis.
//    Its unit normal N = e sin(beta) - a cos(beta) has support value
//    h_K(N) = N . (r a + Rb e) + r, so z >= (h_K(N) - N_x x - N_y y) / N_z (N_z < 0).
// The axis is nearly vertical wherever a vertical line meets the bottom, so the
// distance from the axis changes slowly along the line and z0 need not be close.
struct PlaneBound {
  double z = -HUGE_VAL;
  Vec3 normal{0, 0, -1};  // the plane's outward unit normal
};
PlaneBound supportingPlaneBound(const Cutter& c, const Vec3& a, double x, double y, double z0) {
  const double r = c.cornerRadius, Rb = c.bottomRadius();
  PlaneBound bound;
  if (a.z > 0) bound = {-(a.x * x + a.y * y) / a.z, -a};
  const Vec3 p{x, y, z0};
  const Vec3 perp = p - a * dot(p, a);
  const double rho = length(perp);
  if (r > 0 && rho > Rb) {
    const Vec3 e = perp / rho;
    const double sinB = std::min(1.0, (rho - Rb) / r), cosB = std::sqrt(1 - sinB * sinB);
    const Vec3 N = e * sinB - a * cosB;
    if (N.z < -1e-3) {
      const double h = dot(N, a * r + e * Rb) + r;
      const double z = (h - N.x * x - N.y * y) / N.z;
      if (z > bound.z) bound = {z, N};
    }
  }
  return bound;
}

// Newton's method on Phi from z, which must lie below Phi's lowest root on the line.
struct NewtonResult {
  LowestPoint point;
  // A miss decided at the starting point itself, or a hit there with no normal: the
  // caller starts again from below.
  bool retry = false;
};
NewtonResult newtonFromBelow(const Cutter& c, const Vec3& a, double x, double y, double z,
                             const Vec3& normalBelow) {
  const double r = c.cornerRadius, L = c.fluteLength;
  NewtonResult result;
  LowestPoint& out = result.point;
  // The gradient of Phi at an iterate: the distance's, or the axis on the top face's
  // branch.
  auto gradientOf = [&](const DistanceToCore& d, bool topBranch) {
    return topBranch ? a : d.gradient(a);
  };
  // The gradient at the last iterate outside K: a valid outward normal in the limit.
  // (At the root itself the distance gradient vanishes for a flat cutter, r = 0.)
  // Before the first step: the normal of the plane the start came from (or zero).
  Vec3 outsideNormal = normalBelow;
  DistanceToCore outside{};
  bool outsideTop = false, haveOutside = false;
  auto lastOutsideNormal = [&] {
    return haveOutside ? gradientOf(outside, outsideTop) : outsideNormal;
  };
  for (int iter = 0; iter < 200; ++iter) {
    const Vec3 p{x, y, z};
    const DistanceToCore d = distanceToCore(c, a, p);
    double phi = d.value - r;
    const double top = dot(p, a) - L;
    const bool topBranch = top > phi;
    double dphi;
    if (topBranch) {
      phi = top;
      dphi = a.z;
    } else {
      dphi = d.slopeZ(a);
    }
    if (phi <= 0) {  // reached the boundary (only ever from below, up to round-off)
      // At a tight start (inside K by round-off) the distance gradient is the normal of
      // the offset surface there; in the core itself (the flat bottom of a flat cutter)
      // it vanishes, and the start plane's normal is the normal.
      const Vec3 grad = gradientOf(d, topBranch);
      const bool useGrad = (phi == 0 || iter == 0) && length(grad) > 0;
      const Vec3 normal = useGrad ? grad : lastOutsideNormal();
      if (length(normal) == 0) {  // no normal known: start again below
        result.retry = true;
        return result;
      }
      out.hit = true;
      out.z = z;
      out.normal = normalize(normal);
      return result;
    }
    outside = d, outsideTop = topBranch, haveOutside = true;
    // Phi > 0 and not decreasing: l stays outside K above this point.
    if (!(dphi < 0)) {
      result.retry = iter == 0;
      return result;
    }
    const double step = -phi / dphi;
    z += step;
    // Newton's error: on the torus branch Phi'' <= 1/r between here and the root (the
    // distance to a convex set curves by at most 1 / distance, and distance >= r
    // there), so the new z lies below the root by at most step^2 / (2 r |Phi'|) to
    // leading order. When that is within round-off, it is the answer: no need for
    // another evaluation. (Not on the top face's branch, whose kink has no such bound.)
    if (r > 0 && top + std::fabs(a.z * step) < -1e-9 * (1 + L) &&
        step * step <= 2e-15 * r * -dphi * (1 + std::fabs(z))) {
      out.hit = true;
      out.z = z;
      out.normal = normalize(gradientOf(d, topBranch));
      return result;
    }
    if (step < 1e-13 * (1 + std::fabs(z))) {
      // Converged to within round-off, possibly on a grazing line where Phi' -> 0;
      // accept only if Phi really reached zero to within the same round-off.
      if (phi <= 1e-12 * (1 + c.radius)) {
        out.hit = true;
        out.z = z;
        out.normal = normalize(gradientOf(d, topBranch));
      }
      return result;
    }
  }
  return result;
}

// The lowest point of K on the line, given K's lowest z (zMin) and a proven lower bound
// zBelow of the answer: Newton starts at the highest lower bound known, less a margin
// for round-off, so that it starts below the root.
LowestPoint lowestPointOfCutter(const Cutter& c, const Vec3& a, double zMin, double x, double y,
                                double zBelow) {
  // Below the lowest point of K, Phi > 0 and (if l hits K) decreasing.
  double z = std::max(zMin - 1e-3 * c.radius - 1e-9, zBelow);
  const PlaneBound plane = supportingPlaneBound(c, a, x, y, z);
  const Vec3 normal = plane.z > z ? plane.normal : Vec3{};
  z = std::max(z, plane.z);
  // Started at the bound itself, a tight bound is answered by one evaluation of Phi
  // (Phi <= 0 there: the bound is the root to round-off). A bound above the root by
  // round-off on a line that only grazes K could look like a miss, and inside a flat
  // cutter's core the start has no normal: then Newton starts again from below.
  const NewtonResult tight = newtonFromBelow(c, a, x, y, z, normal);
  if (!tight.retry) return tight.point;
  return newtonFromBelow(c, a, x, y, z - 1e-9 * (1 + std::fabs(z)), Vec3{0, 0, -1}).point;
}

}  // namespace

LowestPoint cutterLowestPoint(const Cutter& c, const Vec3& a, double x, double y, double zBelow) {
  if (c.general()) return profileLowestPoint(*c.profile, a, x, y, zBelow);
  return lowestPointOfCutter(c, a, cutterSupport(c, a, Vec3{0, 0, -1}).z, x, y, zBelow);
}

SweptSegment::SweptSegment(const Cutter& cutter, const Vec3& start, const Vec3& end,
                           const Vec3& axis)
    : cutter_(cutter),
      start_(start),
      end_(end),
      axis_(axis),
      delta_(end - start),
      zMin_(cutterSupport(cutter, axis, Vec3{0, 0, -1}).z) {
  // The frame of the plane P (step 1), the same for every vertical line.
  w_ = std::hypot(delta_.x, delta_.y);
  if (w_ > 1e-12) {
    uHat_ = {delta_.x / w_, delta_.y / w_, 0};
    m_ = {-uHat_.y, uHat_.x, 0};
    sigma_ = delta_.z / w_;
    n_ = normalize(Vec3{sigma_ * uHat_.x, sigma_ * uHat_.y, -1});
    lowM_ = cutterSupport(cutter_, axis_, -m_);
    highM_ = cutterSupport(cutter_, axis_, m_);
  }
}

SweptSegment::SweptSegment(const SweptSegment& o)
    : cutter_(o.cutter_),
      start_(o.start_),
      end_(o.end_),
      axis_(o.axis_),
      delta_(o.delta_),
      zMin_(o.zMin_),
      w_(o.w_),
      sigma_(o.sigma_),
      uHat_(o.uHat_),
      m_(o.m_),
      n_(o.n_),
      lowM_(o.lowM_),
      highM_(o.highM_) {
  const uint32_t ready = o.nodesReady_.load(std::memory_order_acquire);
  for (int k = 0; k < kSectionNodes; ++k)
    if ((ready >> k) & 1) nodes_[size_t(k)] = o.nodes_[size_t(k)];
  nodesClaimed_.store(ready, std::memory_order_relaxed);
  nodesReady_.store(ready, std::memory_order_relaxed);
}

SweptSegment::SectionNode SweptSegment::buildSectionNode(int k) const {
  // The section root at the k-th of evenly spaced offsets across K (see section()).
  SectionNode node;
  if (k == 0) {
    node = {-1, lowM_, 0.0};
  } else if (k == kSectionNodes - 1) {
    node = {1, highM_, 0.0};
  } else {
    const double cMin = dot(lowM_, m_), cMax = dot(highM_, m_);
    const double c = cMin + (cMax - cMin) * k / (kSectionNodes - 1);
    double root = 0;
    const Section sec = search(c, -1, lowM_, 1, highM_, 0, &root);
    const SupportWithSlope sw = supportWithSlope(
        cutter_, axis_, n_ * (1 - root * root) + m_ * (2 * root), n_ * (-2 * root) + m_ * 2);
    const double dcdt = dot(sw.slope, m_);
    node = {root, sec.point, std::isfinite(dcdt) ? dcdt : 0.0};
  }
  const uint32_t bit = uint32_t(1) << k;
  if (!(nodesClaimed_.fetch_or(bit, std::memory_order_relaxed) & bit)) {
    nodes_[size_t(k)] = node;
    nodesReady_.fetch_or(bit, std::memory_order_release);
  }
  return node;
}

Box3 SweptSegment::bounds() const {
  // The cutter's box from its six axis-aligned support points, at both ends.
  Box3 box;
  const Vec3 dirs[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const Vec3& dir : dirs) {
    const Vec3 p = cutterSupport(cutter_, axis_, dir);
    box.extend(start_ + p);
    box.extend(end_ + p);
  }
  return box;
}

double SweptSegment::support(const Vec3& dir) const {
  // h_C(dir) = h_K(dir) + max(0, dir . d): a Minkowski sum adds support functions.
  const Vec3 d = end_ - start_;
  return dot(dir, start_ + cutterSupport(cutter_, axis_, dir)) + std::max(0.0, dot(dir, d));
}

SweptSegment::Section SweptSegment::search(double c, double th1, Vec3 x1, double th2, Vec3 x2,
                                           double th, double* root) const {
  // Step 3: the support point of S = K n P in direction n = sigma u_hat - z_hat, where
  // P is the plane at offset c along m. Directions n cos(theta) + m sin(theta), theta
  // in [-pi/2, pi/2], are parametrised without trigonometry by t = tan(theta / 2) in
  // [-1, 1]: (1 - t^2) n + 2 t m points the same way, and support points do not depend
  // on a direction's length. [th1, th2] brackets the root, th is the first guess.
  const Vec3& n = n_;
  const Vec3& m = m_;
  auto direction = [&](double t) { return n * (1 - t * t) + m * (2 * t); };
  Section out;
  const double thStart1 = th1, thStart2 = th2;  // x1, x2 belong to these

  // Root of the monotone f(t) = x_K(t) . m - c by Newton's method with the analytic
  // slope of the support point, safeguarded by the bracket [th1, th2] (as in
  // Numerical Recipes' rtsafe): a step that leaves the bracket, a non-positive slope,
  // or a step that does not at least halve the previous one falls back to bisection, so
  // jumps of the support point (flat faces) are still found.
  // The cylinder's side is a ruled face: where the direction turns through v . a = 0
  // the support point jumps from the bottom rim (s = r) up the side line to the top rim
  // (s = L). If P crosses that side line, the jump is the root and the answer is the
  // crossing itself, found in closed form instead of by bisecting down to the jump.
  {
    // v(t) . a = 0:  -(n.a) t^2 + 2 (m.a) t + (n.a) = 0; the roots' product is -1, so
    // at most one lies inside (-1, 1): t = (m.a - sqrt((m.a)^2 + (n.a)^2)) / (n.a),
    // written without cancellation.
    const double na = dot(n, axis_), ma = dot(m, axis_);
    const double q = ma + std::copysign(std::sqrt(ma * ma + na * na), ma);
    const double ts = q != 0 ? -na / q : 2.0;
    if (ts > th1 && ts < th2 && ma != 0) {
      const Vec3 v = direction(ts);
      const Vec3 e = normalize(v - axis_ * dot(v, axis_));
      // The side line a s + e R crosses P where s = (c - R (m . e)) / (m . a).
      const double s = (c - cutter_.radius * dot(m, e)) / ma;
      if (s >= cutter_.cornerRadius && s <= cutter_.fluteLength) {
        out.hit = true;
        out.point = axis_ * s + e * cutter_.radius;
        out.point -= m * (dot(out.point, m) - c);  // onto P to round-off
        out.normal = e;
        if (root) *root = ts;
        return out;
      }
    }
  }
  // f(t) and its slope in closed form. n and m are orthonormal, so |v(t)| = 1 + t^2,
  // and the radial part v - a (v . a) of v(t) has the m-component Pm(t) and the squared
  // length Q(t), both polynomials in t (below, with na = n . a, ma = m . a):
  //   v . a = (1 - t^2) na + 2 t ma,   Pm = (1 - t^2) B + 2 t C,
  //   Q = (1 - t^2)^2 (1 - na^2) + 4 t (1 - t^2) B + 4 t^2 C,  B = -na ma, C = 1 - ma^2.
  // With g = Pm / sqrt(Q) = e . m, the support points of supportWithSlope give
  //   top rim (v . a > 0):  f = L ma + R g - c
  //   torus   (v . a <= 0): f = r ma + Rb g + r 2t / (1 + t^2) - c.
  // Near an axial direction the vector form is used instead: Q is a sum of terms of order
  // one that cancel to |v_perp|^2, so its round-off (~1e-16) makes g wrong by ~1e-16 / Q,
  // times the rim's radius (7e-5 mm at Q = 1e-12: a bull moving almost in its bottom
  // plane was 1e-6 mm too high), while the vector form's e = v_perp / |v_perp| keeps the
  // point on the rim whatever its error. Below |v_perp| = 1e-2 |v| (Q = 1e-4 (1 + t^2)^2)
  // the closed form's error stays below 1e-12 Rb. Only rims of a radius need it: a
  // ball's torus term (Rb = 0) has none.
  const double r = cutter_.cornerRadius, L = cutter_.fluteLength, R = cutter_.radius;
  const double Rb = cutter_.bottomRadius();
  const double na = dot(n, axis_), ma = dot(m, axis_);
  const double A = 1 - na * na, B = -na * ma, C = 1 - ma * ma;
  auto closedForm = [&](double t, double u, double Q) {
    const double w = 1 + t * t;
    return Q > 1e-20 && (Q > 1e-4 * w * w || (Rb == 0 && !(u * na + 2 * t * ma > 0)));
  };
  auto offsetAndSlope = [&](double t, double& f, double& slope) {
    const double u = 1 - t * t;
    const double Q = u * u * A + 4 * t * u * B + 4 * t * t * C;
    if (closedForm(t, u, Q)) {
      const double Pm = u * B + 2 * t * C, dPm = -2 * t * B + 2 * C;
      const double dQ = -4 * t * u * A + (4 - 12 * t * t) * B + 8 * t * C;
      const double sq = std::sqrt(Q);
      const double g = Pm / sq, dg = (dPm - 0.5 * Pm * dQ / Q) / sq;
      if (u * na + 2 * t * ma > 0) {
        f = L * ma + R * g - c;
        slope = R * dg;
      } else {
        const double w = 1 / (1 + t * t);
        f = r * ma + Rb * g + 2 * r * t * w - c;
        slope = Rb * dg + 2 * r * u * w * w;
      }
      return;
    }
    const SupportWithSlope sw =
        supportWithSlope(cutter_, axis_, direction(t), n * (-2 * t) + m * 2);
    f = dot(sw.point, m) - c;
    slope = dot(sw.slope, m);
  };
  // The support point at t, on the same side of a jump as offsetAndSlope decided (at
  // v . a ~ 0 the vector form may round the other way).
  auto supportAt = [&](double t) {
    const double u = 1 - t * t;
    const Vec3 v = direction(t);
    if (!closedForm(t, u, u * u * A + 4 * t * u * B + 4 * t * t * C))
      return cutterSupport(cutter_, axis_, v);
    const Vec3 e = normalize(v - axis_ * dot(v, axis_));
    return rimOrTorusPoint(cutter_, axis_, e, v, r / (1 + t * t), u * na + 2 * t * ma > 0);
  };
  // ... moved onto P (it is on P to round-off when f(t) ~ 0).
  auto pointOnP = [&](double t) {
    const Vec3 p = supportAt(t);
    return p - m * (dot(p, m) - c);
  };

  const double tol = 1e-14 * (R + L);
  double stepBefore = th2 - th1;
  for (int iter = 0; iter < 200 && th2 - th1 > 1e-16; ++iter) {
    double fm, slope;
    offsetAndSlope(th, fm, slope);
    const bool converged = std::fabs(fm) <= tol;
    if (fm < 0) {
      th1 = th;
    } else {
      th2 = th;
    }
    const double newton = slope > 0 ? fm / slope : HUGE_VAL;
    double step;
    if (!converged && th - newton > th1 && th - newton < th2 &&
        std::fabs(2 * newton) <= std::fabs(stepBefore)) {
      step = newton;
    } else {
      step = th - 0.5 * (th1 + th2);
    }
    if (converged || (std::fabs(newton) <= 1e-16 && std::fabs(fm) <= 1e3 * tol)) {
      // On P to round-off (or Newton has stalled there): move it onto P exactly.
      out.hit = true;
      out.point = pointOnP(th);
      out.normal = normalize(direction(th));
      if (root) *root = th;
      return out;
    }
    stepBefore = step;
    th -= step;
  }
  // The bracket closed on a jump of the support point: a flat face (the bottom disk,
  // the top disk or a side line). The chord between the two bracketing support points
  // lies on that face, which is the support set, and crosses P. The same happens where
  // the support point only moves too fast for t's resolution: a direction within ~1e-5
  // of the axis, whose rim point turns through half a circle while t changes by ~1e-5
  // (a flat end mill moving almost in its bottom plane: d . a ~ 1e-6 |d|). The points
  // at the two ends of a one-ulp bracket then lie on the same side of P by round-off,
  // and the chord's crossing would be an extrapolation far off K (0.11 mm below it, seen
  // on LinuxCNC's boat program). Kept on the chord, the point is a point of K within
  // the bracket's spread of the true one (1e-10 mm there).
  if (th1 != thStart1) x1 = supportAt(th1);
  if (th2 != thStart2) x2 = supportAt(th2);
  const double f1 = dot(x1, m) - c, f2 = dot(x2, m) - c;
  const double lam = f2 > f1 ? std::clamp(-f1 / (f2 - f1), 0.0, 1.0) : (f1 >= 0 ? 0.0 : 1.0);
  out.hit = true;
  out.point = x1 + (x2 - x1) * lam;
  out.normal = normalize(direction(0.5 * (th1 + th2)));
  if (root) *root = 0.5 * (th1 + th2);
  return out;
}

SweptSegment::Section SweptSegment::section(double c) const {
  const double cMin = dot(lowM_, m_), cMax = dot(highM_, m_);
  if (c < cMin || c > cMax) return {};  // P misses K, so l misses C
  // Two nodes (built on first use) bracket the root between two neighbours and give
  // a first guess by linear interpolation; Newton then needs about three steps. The
  // nodes depend only on the segment, so the result is a function of c alone.
  const double u = (c - cMin) / (cMax - cMin) * (kSectionNodes - 1);
  const int k = std::clamp(int(u), 0, kSectionNodes - 2);
  const SectionNode a = sectionNode(k), b = sectionNode(k + 1);
  const double ca = dot(a.point, m_), cb = dot(b.point, m_);
  if (ca - c <= 0 && cb - c >= 0) {
    // Cubic Hermite interpolation of t(c) with the nodes' slopes dt/dc where both are
    // finite (near K's extremes dc/dt vanishes), linear otherwise.
    const double dc = cb - ca, x = dc > 0 ? (c - ca) / dc : 0.0;
    double guess = a.t + x * (b.t - a.t);
    if (a.dcdt > 1e-9 && b.dcdt > 1e-9 && dc > 0) {
      const double x2 = x * x, x3 = x2 * x;
      guess = (2 * x3 - 3 * x2 + 1) * a.t + (x3 - 2 * x2 + x) * dc / a.dcdt +
              (-2 * x3 + 3 * x2) * b.t + (x3 - x2) * dc / b.dcdt;
    }
    return search(c, a.t, a.point, b.t, b.point, std::clamp(guess, a.t, b.t), nullptr);
  }
  return search(c, -1, lowM_, 1, highM_, 0, nullptr);
}

LowestPoint SweptSegment::lowestPoint(double x, double y) const {
  return lowestPoint(x, y, nullptr);
}

// Inlined into SweptMove::envelopeLowestPoint (the same unity unit), the constant-axis
// cell's one call: GCC's heuristics dropped it once the Cutter grew a profile pointer, for
// 4 % more instructions a cell on B1 (scripts/perf-guard.sh). Other callers get the usual
// out-of-line copy, which is what the attribute's warning is about.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wattributes"
__attribute__((always_inline)) LowestPoint SweptSegment::lowestPoint(double x, double y,
                                                                     SectionMemo* memo,
                                                                     double cutoff) const {
  const double qx = x - start_.x, qy = y - start_.y;

  // A plunge, a retract or a zero-length move: the cutter slides along l itself.
  if (w_ <= 1e-12) {
    LowestPoint lp = lowestPointOfCutter(cutter_, axis_, zMin_, qx, qy, -HUGE_VAL);
    lp.z += start_.z + std::min(0.0, delta_.z);
    return lp;
  }

  // Step 1: the plane P through l parallel to d, in coordinates (u along d_xy, z).
  const double c = qx * m_.x + qy * m_.y;
  const double u0 = qx * uHat_.x + qy * uHat_.y;

  // Step 3's search depends on c alone: reuse it along a line of cells
  // parallel to the move. The memo is keyed by c's exact bits, so the result is the
  // same with or without it.
  Section sec;
  if (memo && memo->owner == this && memo->offset == c) {
    sec = memo->section;
  } else {
    sec = section(c);
    if (memo) *memo = SectionMemo{this, c, sec};
  }
  if (!sec.hit) return {};
  const double vs = dot(sec.point, uHat_);
  // The unclamped minimum (the envelope line through the support point) bounds the
  // clamped one from below, so a move that cannot beat `cutoff` is dropped here,
  // before the Newton iterations of the end cases.
  const double envelopeZ = start_.z + sec.point.z + (u0 - vs) * sigma_;
  if (envelopeZ >= cutoff) return {};

  // Step 2: clamp the envelope point to the move. The section's lower boundary is
  // convex, so it lies above its tangent of slope sigma at the support point: the end
  // cases are no lower than envelopeZ, and their Newton search starts there.
  if (vs > u0) {  // the minimiser lies before the start: the cutter at t = 0
    LowestPoint lp = lowestPointOfCutter(cutter_, axis_, zMin_, qx, qy, envelopeZ - start_.z);
    lp.z += start_.z;
    return lp;
  }
  if (vs < u0 - w_) {  // beyond the end: the cutter at t = 1
    LowestPoint lp = lowestPointOfCutter(cutter_, axis_, zMin_, qx - delta_.x, qy - delta_.y,
                                         envelopeZ - end_.z);
    lp.z += end_.z;
    return lp;
  }
  LowestPoint out;
  out.hit = true;
  out.z = envelopeZ;
  out.normal = sec.normal;
  return out;
}

#pragma GCC diagnostic pop

}  // namespace scallop
