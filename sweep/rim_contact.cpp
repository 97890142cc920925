// Locating the lowest point of a turning cutter's swept solid on a vertical line.
//
// Every cutter is K = (C (+) Ball(r)) n {s <= L} (cutter.h) with C the core cylinder of
// radius Rb on the axis from s = r up. Where a bull or ball cutter meets a vertical line
// l from below on its corner, the nearest point of C is on C's bottom rim, the circle
//     c(t, phi) = tip(t) + r a(t) + Rb (cos phi e1(t) + sin phi e2(t)),
// with (e1, e2, a) the frame turning with the cutter (PoseCurve::frame). The ball of
// radius r round c meets l = {(x, y, z)} lowest at
//     g(t, phi) = c_z - sqrt(r^2 - |D|^2),   D = (c_x - x, c_y - y),
// and the swept solid's lowest point on l, where it lies on a corner, is the minimum of
// g over t in [0, 1] and phi: a smooth two-variable problem with closed-form derivatives.
// With k = c - tip (a vector fixed to the cutter, so k' = Omega x k) and c_i, c_ij the
// partial derivatives of c:
//     c_t = tip' + Omega x k,          c_phi = Rb (-sin phi e1 + cos phi e2),
//     c_tt = tip'' + Omega' x k + Omega x (Omega x k),
//     c_tphi = Omega x c_phi,          c_phiphi = -Rb (cos phi e1 + sin phi e2),
// and, with s = sqrt(r^2 - |D|^2) and D_i the horizontal part of c_i,
//     g_i  = c_i.z + D.D_i / s,
//     g_ij = c_ij.z + (D_i.D_j + D.D_ij) / s + (D.D_i)(D.D_j) / s^3.
// Newton's step solves H delta = -grad g where H is positive definite; at t = 0 or 1 with
// the slope pointing out of [0, 1] the step runs along phi alone (the minimum at a move's
// end), and a step leaving [0, 1] is clamped. Quadratic convergence takes 3 to 5 steps
// from the middle of a move on CAM paths.
//
// How the contact moves with the line (RimSensitivity, for the knots' starts): at the
// minimum grad g = 0 holds for every nearby line, so differentiating it in the line's x
//     H d(t, phi)/dx = -(d g_t/dx, d g_phi/dx),   d g_i/dx = -(c_i.x + (D.D_i) D_x / s^2) / s
// (D depends on x through D_x = c_x - x, and s through s_x = D_x / s); the same in y.
// At a move's end, t stays put and only phi moves: d phi/dx = -(d g_phi/dx) / g_phiphi.
//
// Why nothing here needs a proof: every (x, y, g(t, phi)) lies on a ball of radius r
// round a point of C, so in K' = C (+) Ball(r), and in K(t) where its height along the
// axis, r + (p - c).a, is at most the flute length L (checked: a short flute, L < 2r,
// can fail it); the height returned is attained, an upper bound of the true lowest point. The
// caller proves it is the lowest (ray clearance at 1e-9 mm below it) or, where the contact is not
// on the corner (a flat bottom face, a flank) or Newton stops, runs the certified search.
#include "sweep/rim_contact.h"

#include <algorithm>
#include <cmath>

namespace scallop {

namespace {

constexpr int kRimNewtonSteps = 12;
// mm: Newton's decrement (about how far g lies above its minimum) at which g is taken as
// converged: 10 times below the proof gap, so the proof that follows has room to close;
// a smaller one costs a step more for heights no more proven.
constexpr double kRimDecrementDone = 1e-10;

// g and its first and second partial derivatives at (t, phi); ok = false where l misses
// the ball round c (|D| >= r, to a margin).
struct Local {
  bool ok = false;
  double g = 0, gt = 0, gp = 0, gtt = 0, gtp = 0, gpp = 0;
  double gtx = 0, gty = 0, gpx = 0, gpy = 0;  // d g_t / dx, ..., d g_phi / dy of the line
  Vec3 normal;
};

Local evaluate(const Cutter& cutter, const PoseFrame& f, double x, double y, double cs, double sn) {
  const double r = cutter.cornerRadius, rb = cutter.bottomRadius();
  const Vec3 radial = f.e1 * cs + f.e2 * sn;
  const Vec3 k = f.axis * r + radial * rb;
  const Vec3 c = f.tip + k;
  const Vec3 ct = f.velocity + cross(f.spin, k);
  const Vec3 cp = (f.e2 * cs - f.e1 * sn) * rb;
  const Vec3 ctt = f.acceleration + cross(f.spinRate, k) + cross(f.spin, cross(f.spin, k));
  const Vec3 ctp = cross(f.spin, cp);
  const Vec3 cpp = radial * -rb;

  Local out;
  const double dx = c.x - x, dy = c.y - y, dd = dx * dx + dy * dy;
  const double ss = r * r - dd;
  if (!(ss > 1e-6 * r * r)) return out;  // l misses the ball, or grazes it steeply
  const double s = std::sqrt(ss), is = 1 / s, is2 = is * is;
  const double dt = dx * ct.x + dy * ct.y, dp = dx * cp.x + dy * cp.y;  // D.D_i
  out.ok = true;
  out.g = c.z - s;
  out.gt = ct.z + dt * is;
  out.gp = cp.z + dp * is;
  out.gtt = ctt.z + (ct.x * ct.x + ct.y * ct.y + dx * ctt.x + dy * ctt.y + dt * dt * is2) * is;
  out.gtp = ctp.z + (ct.x * cp.x + ct.y * cp.y + dx * ctp.x + dy * ctp.y + dt * dp * is2) * is;
  out.gpp = cpp.z + (cp.x * cp.x + cp.y * cp.y + dx * cpp.x + dy * cpp.y + dp * dp * is2) * is;
  out.gtx = -(ct.x + dt * dx * is2) * is, out.gty = -(ct.y + dt * dy * is2) * is;
  out.gpx = -(cp.x + dp * dx * is2) * is, out.gpy = -(cp.y + dp * dy * is2) * is;
  out.normal = Vec3{-dx, -dy, -s} * (1 / r);
  return out;
}

// The start's rim direction (cos phi, sin phi): towards the point where l crosses the
// rim's plane (so that c lies nearly above or below (x, y)); straight down the rim where
// that point is the rim's centre.
void startDirection(const Cutter& cutter, const PoseFrame& f, double x, double y, double& cs,
                    double& sn) {
  const Vec3& axis = f.axis;
  const Vec3 centre = f.tip + axis * cutter.cornerRadius;
  Vec3 towards{0, 0, -1};
  if (axis.z > 1e-9) {
    const double z = centre.z - ((x - centre.x) * axis.x + (y - centre.y) * axis.y) / axis.z;
    const Vec3 d = Vec3{x, y, z} - centre;
    if (length(d) > 1e-9 * (1 + cutter.radius)) towards = d;
  }
  cs = dot(towards, f.e1), sn = dot(towards, f.e2);
  const double n = std::sqrt(cs * cs + sn * sn);
  if (n > 0) {
    cs /= n, sn /= n;
  } else {
    cs = 1, sn = 0;
  }
}

// d(t, phi)/d(x, y) at a minimum where the last step's Hessian was positive definite
// (the header's derivation); at a move's end, those of the unconstrained minimum past it,
// with the Newton step there (g's Hessian, where it is not positive definite there, gives
// the end's own: t fixed).
RimSensitivity sensitivityAt(const Local& L, bool ball, bool atEnd) {
  RimSensitivity d;
  if (ball) {
    if (!(L.gtt > 0)) return d;
    d.dtdx = -L.gtx / L.gtt, d.dtdy = -L.gty / L.gtt;
    if (atEnd) d.tBeyond = -L.gt / L.gtt;
    return d;
  }
  const double det = L.gtt * L.gpp - L.gtp * L.gtp;
  if (!(L.gtt > 0 && det > 0)) {
    d.dphidx = -L.gpx / L.gpp, d.dphidy = -L.gpy / L.gpp;
    return d;
  }
  d.dtdx = -(L.gpp * L.gtx - L.gtp * L.gpx) / det;
  d.dtdy = -(L.gpp * L.gty - L.gtp * L.gpy) / det;
  d.dphidx = -(L.gtt * L.gpx - L.gtp * L.gtx) / det;
  d.dphidy = -(L.gtt * L.gpy - L.gtp * L.gty) / det;
  if (atEnd) {
    d.tBeyond = -(L.gpp * L.gt - L.gtp * L.gp) / det;
    d.phiBeyond = -(L.gtt * L.gp - L.gtp * L.gt) / det;
  }
  return d;
}

}  // namespace

RimContact locateRimContact(const Cutter& cutter, const PoseCurve& curve, double x, double y,
                            const RimStart& start, RimSensitivity* sensitivity) {
  RimContact out;
  if (cutter.general() || !(cutter.cornerRadius > 0)) return out;
  const bool ball = !(cutter.bottomRadius() > 0);  // phi plays no part
  double t = std::clamp(start.t, 0.0, 1.0);
  // phi is carried as the unit vector (cos phi, sin phi): a step d phi moves it along its
  // tangent and renormalises, which is as good a point of the circle as any and needs no
  // trigonometry.
  double cs = 1, sn = 0;
  PoseFrame& f = out.pose;  // written in place: returned with the contact
  curve.frame(t, f);
  if (start.hasDirection) {
    cs = start.cosPhi, sn = start.sinPhi;
  } else if (!ball) {
    startDirection(cutter, f, x, y, cs, sn);
  }
  for (int step = 0; step < kRimNewtonSteps; ++step) {
    if (step > 0) curve.frame(t, f);
    const Local L = evaluate(cutter, f, x, y, cs, sn);
    if (!L.ok) return out;
    // Newton's step, on [0, 1] x R: along phi alone at an end whose slope points out.
    const bool atEnd = (t <= 0 && L.gt > 0) || (t >= 1 && L.gt < 0);
    double dt = 0, dp = 0;
    if (ball) {
      if (!atEnd) {
        if (!(L.gtt > 0)) return out;
        dt = -L.gt / L.gtt;
      }
    } else if (atEnd) {
      if (!(L.gpp > 0)) return out;
      dp = -L.gp / L.gpp;
    } else {
      const double det = L.gtt * L.gpp - L.gtp * L.gtp;
      if (!(L.gtt > 0 && L.gpp > 0 && det > 0)) return out;
      dt = -(L.gpp * L.gt - L.gtp * L.gp) / det;
      dp = -(L.gtt * L.gp - L.gtp * L.gt) / det;
    }
    dt = std::clamp(t + dt, 0.0, 1.0) - t;
    // The Newton decrement -grad g . delta / 2 estimates how far g here lies above the
    // minimum (g is nearly quadratic this close): far below the 1e-9 mm proof gap, stop.
    if (-0.5 * (L.gt * dt + L.gp * dp) <= kRimDecrementDone) {
      // The point is in K(t) only below the flute top: s = r + (p - c).a <= L, which a
      // short flute (L < 2r) and a line running up the lean can break (K' has no top,
      // so the proof would not notice).
      const double r = cutter.cornerRadius;
      if (!(r + r * dot(L.normal, f.axis) <= cutter.fluteLength)) return out;
      out.found = true;
      out.t = t, out.z = L.g, out.normal = L.normal;
      out.cosPhi = cs, out.sinPhi = sn;
      out.iterations = step;
      if (sensitivity) *sensitivity = sensitivityAt(L, ball, atEnd);
      return out;
    }
    t += dt;
    const double c1 = cs - sn * dp, s1 = sn + cs * dp, n = std::sqrt(c1 * c1 + s1 * s1);
    cs = c1 / n, sn = s1 / n;
  }
  return out;
}

}  // namespace scallop
