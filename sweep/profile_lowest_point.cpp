// The lowest point of a cutter of any convex profile on a vertical line.
//
// Tool frame: tip at the origin, unit axis a; a point p has s = p.a and
// rho = |p - a s|. Phi(p) = sd(rho, s), the profile's signed distance
// (CutterProfile::signedDistance), is the signed distance from p to K, a convex
// function of p; along the vertical line l(z) = (x, y, z) it is a convex function
// phi(z), and the lowest point of K on l is phi's lowest root.
//
//   * Start: a proven lower bound z0 of that root: the caller's, K's lowest z, and the
//     tip plane (K lies in s >= 0, so a.z > 0 gives z >= -(a.x x + a.y y) / a.z).
//   * Newton from below: outside K, phi is the distance to a convex set, differentiable
//     with phi' = dRho (perp.z / rho) + dS a.z; a convex function lies above its tangent,
//     so the tangent's root z + step, step = -phi / phi', is still <= the lowest root
//     (no overshoot, whatever the profile's corners). phi' >= 0 with phi > 0 means l
//     stays outside above z: a miss.
//   * Stop: once a step is below 1e-12 (1 + |z|) mm, the point step (at least
//     1e-13 (1 + |z|)) above the new iterate is tested: phi <= 0 there puts the root
//     between the two, so the iterate (returned) is a proven lower bound within twice the
//     step of an attained height. Where the probe is still outside (a line grazing K,
//     where Newton converges only linearly), Newton goes on; a step lost in round-off
//     with phi within 1e-12 (1 + reach) of zero is a grazing hit.
// The normal is the distance's gradient at the last iterate outside K: the unit vector
// from its nearest point of K, a normal of K within the last step of the contact.
#include "sweep/profile_lowest_point.h"

#include <algorithm>
#include <cmath>

namespace scallop {

Vec3 profileSupport(const CutterProfile& profile, const Vec3& a, const Vec3& dir) {
  const double va = dot(dir, a);
  Vec3 perp = dir - a * va;
  perp -= a * dot(perp, a);
  const double lp = length(perp);
  // Below 1e-14 |dir| the direction is axial: the support set is a whole end face,
  // whose centre (on the axis) is returned.
  const bool radial = lp > 1e-14 * length(dir);
  const ProfilePoint q = profile.support(radial ? lp : 0.0, va);
  return a * q.s + (radial ? perp * (q.rho / lp) : Vec3{});
}

namespace {

struct PhiAt {
  double value, slope;  // phi(z) and phi'(z)
  Vec3 gradient;        // of Phi in 3D (unit where phi != 0)
};

PhiAt phiAt(const CutterProfile& profile, const Vec3& a, double x, double y, double z) {
  const Vec3 p{x, y, z};
  const double s = dot(p, a);
  const Vec3 perp = p - a * s;
  const double rho = length(perp);
  double dRho = 0, dS = 0;
  PhiAt out;
  out.value = profile.signedDistance(rho, s, &dRho, &dS);
  const Vec3 e = rho > 0 ? perp / rho : Vec3{};
  out.gradient = e * dRho + a * dS;
  out.slope = out.gradient.z;
  return out;
}

}  // namespace

LowestPoint profileLowestPoint(const CutterProfile& profile, const Vec3& a, double x, double y,
                               double zBelow) {
  const double reach = profile.reach();
  // K's lowest z, less a margin for round-off, and the tip plane.
  double z = std::max(profileSupport(profile, a, {0, 0, -1}).z - 1e-9 * (1 + reach), zBelow);
  Vec3 startNormal{0, 0, -1};
  if (a.z > 0) {
    const double tipPlane = -(a.x * x + a.y * y) / a.z - 1e-12 * (1 + reach) / a.z;
    if (tipPlane > z) z = tipPlane, startNormal = -a;
  }
  LowestPoint out;
  const double graze = 1e-12 * (1 + reach);
  double lastStep = HUGE_VAL;
  Vec3 outsideNormal = startNormal;
  for (int iter = 0; iter < 400; ++iter) {
    const PhiAt f = phiAt(profile, a, x, y, z);
    if (f.value <= 0) {  // at the root (from below, up to round-off)
      out.hit = true, out.z = z;
      // The normal from just below: the nearest point of K to a point 1e-10 mm under
      // the contact is within that of it, so its plane supports K through the contact
      // (to 1e-10 mm times the normal's tilt); the last iterate's may come from afar.
      Vec3 normal = outsideNormal;
      if (!(lastStep <= 1e-10)) {
        const PhiAt below = phiAt(profile, a, x, y, z - 1e-10 * (1 + std::fabs(z)));
        normal = below.value > 0 ? below.gradient : length(f.gradient) > 0 ? f.gradient : normal;
      }
      out.normal = normalize(normal);
      return out;
    }
    outsideNormal = f.gradient;
    if (!(f.slope < 0)) {  // l stays outside K above z
      if (f.value <= graze) out.hit = true, out.z = z, out.normal = normalize(f.gradient);
      return out;
    }
    const double step = -f.value / f.slope;
    const double next = z + step;
    const double scale = 1 + std::fabs(next);
    if (step <= 1e-12 * scale) {
      const double probe = next + std::max(step, 1e-13 * scale);
      if (phiAt(profile, a, x, y, probe).value <= 0 ||
          (step <= 1e-15 * scale && f.value <= graze)) {
        out.hit = true, out.z = next, out.normal = normalize(f.gradient);
        return out;
      }
    }
    z = next, lastStep = step;
  }
  return out;
}

}  // namespace scallop
