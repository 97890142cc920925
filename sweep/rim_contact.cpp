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

constexpr int kMaxSteps = 12;
// mm: Newton's decrement (about how far g lies above its minimum) at which g is taken as
// converged: 10 times below the proof gap, so the proof that follows has room to close;
// a smaller one costs a step more for heights no more proven.
constexpr double kDecrementDone = 1e-10;

// g and its first and second partial derivatives at (t, phi); ok = false where l misses
// the ball round c (|D| >= r, to a margin).
struct Local {
  bool ok = false;
  double g = 0, gt = 0, gp = 0, gtt = 0, gtp = 0, gpp = 0;
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
  const double s = std::sqrt(ss);
  const double dt = dx * ct.x + dy * ct.y, dp = dx * cp.x + dy * cp.y;  // D.D_i
  out.ok = true;
  out.g = c.z - s;
  out.gt = ct.z + dt / s;
  out.gp = cp.z + dp / s;
  const double s3 = s * ss;
  out.gtt = ctt.z + (ct.x * ct.x + ct.y * ct.y + dx * ctt.x + dy * ctt.y) / s + dt * dt / s3;
  out.gtp = ctp.z + (ct.x * cp.x + ct.y * cp.y + dx * ctp.x + dy * ctp.y) / s + dt * dp / s3;
  out.gpp = cpp.z + (cp.x * cp.x + cp.y * cp.y + dx * cpp.x + dy * cpp.y) / s + dp * dp / s3;
  out.normal = Vec3{-dx, -dy, -s} / r;
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

}  // namespace

RimContact locateRimContact(const Cutter& cutter, const PoseCurve& curve, double x, double y,
                            const RimStart& start) {
  RimContact out;
  if (!(cutter.cornerRadius > 0)) return out;
  const bool ball = !(cutter.bottomRadius() > 0);  // phi plays no part
  double t = std::clamp(start.t, 0.0, 1.0);
  // phi is carried as the unit vector (cos phi, sin phi): a step d phi moves it along its
  // tangent and renormalises, which is as good a point of the circle as any and needs no
  // trigonometry.
  double cs = 1, sn = 0;
  PoseFrame f = curve.frame(t);
  if (start.hasDirection) {
    cs = start.cosPhi, sn = start.sinPhi;
  } else if (!ball) {
    startDirection(cutter, f, x, y, cs, sn);
  }
  for (int step = 0; step < kMaxSteps; ++step) {
    if (step > 0) f = curve.frame(t);
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
    if (-0.5 * (L.gt * dt + L.gp * dp) <= kDecrementDone) {
      // The point is in K(t) only below the flute top: s = r + (p - c).a <= L, which a
      // short flute (L < 2r) and a line running up the lean can break (K' has no top,
      // so the proof would not notice).
      const double r = cutter.cornerRadius;
      if (!(r + r * dot(L.normal, f.axis) <= cutter.fluteLength)) return out;
      out.found = true;
      out.t = t, out.z = L.g, out.normal = L.normal, out.pose = f;
      out.cosPhi = cs, out.sinPhi = sn;
      out.iterations = step;
      return out;
    }
    t += dt;
    const double c1 = cs - sn * dp, s1 = sn + cs * dp, n = std::sqrt(c1 * c1 + s1 * s1);
    cs = c1 / n, sn = s1 / n;
  }
  return out;
}

}  // namespace scallop
