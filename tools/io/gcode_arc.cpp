#include "tools/io/gcode_arc.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "base/constants.h"
#include "base/input_error.h"

namespace scallop {

namespace {

double component(const Vec3& p, int i) {
  return i == 0 ? p.x : i == 1 ? p.y : p.z;
}

}  // namespace

void arcPlaneAxes(int plane, int& u, int& v, int& w) {
  // G17: (x, y) normal z; G18: (z, x) normal y; G19: (y, z) normal x.
  u = plane == 17 ? 0 : plane == 18 ? 2 : 1;
  v = plane == 17 ? 1 : plane == 18 ? 0 : 2;
  w = 3 - u - v;
}

ArcMotion resolveArc(const ArcSpec& arc, const std::string& where) {
  int iu, iv, iw;
  arcPlaneAxes(arc.plane, iu, iv, iw);
  const double su = component(arc.start, iu), sv = component(arc.start, iv);
  const double eu = component(arc.end, iu), ev = component(arc.end, iv);
  double cu = arc.centreU, cv = arc.centreV;
  if (arc.hasRadius) {
    const double du = eu - su, dv = ev - sv, chord = std::hypot(du, dv);
    if (chord == 0)
      throw InputError(where, "an R arc needs distinct start and end; use I/J/K for a full circle");
    if (chord > 2 * std::fabs(arc.radius) + kArcRadiusSlack)
      throw InputError(where, fmt::format("arc radius R = {:g} mm is smaller than half the "
                                          "chord ({:g} mm)",
                                          std::fabs(arc.radius), chord / 2));
    const double h = std::sqrt(std::max(0.0, arc.radius * arc.radius - chord * chord / 4));
    // Left of the chord for a counter-clockwise short arc; R < 0 asks for the long one.
    const double side = (arc.ccw ? 1.0 : -1.0) * (arc.radius < 0 ? -1.0 : 1.0);
    cu = (su + eu) / 2 - side * h * dv / chord;
    cv = (sv + ev) / 2 + side * h * du / chord;
  }
  const double r0 = std::hypot(su - cu, sv - cv), r1 = std::hypot(eu - cu, ev - cv);
  if (r0 == 0) throw InputError(where, "arc centre is at the start point (radius 0)");
  if (std::fabs(r0 - r1) > kArcRadiusSlack)
    throw InputError(where, fmt::format("arc radii differ: {:.6g} mm at the start, {:.6g} mm at "
                                        "the end (more than {:g} mm)",
                                        r0, r1, kArcRadiusSlack));
  const double a0 = std::atan2(sv - cv, su - cu), a1 = std::atan2(ev - cv, eu - cu);
  double sweep = a1 - a0;
  if (arc.ccw) {
    while (sweep <= 0) sweep += 2 * kPi;
  } else {
    while (sweep >= 0) sweep -= 2 * kPi;
  }
  ArcMotion out;
  double centre[3], u[3] = {0, 0, 0}, v[3] = {0, 0, 0};
  centre[iu] = cu, centre[iv] = cv, centre[iw] = component(arc.start, iw);
  u[iu] = 1, v[iv] = 1;
  out.centre = {centre[0], centre[1], centre[2]};
  out.u = {u[0], u[1], u[2]}, out.v = {v[0], v[1], v[2]};
  out.angle0 = a0, out.sweep = sweep;
  out.radius0 = r0, out.radius1 = r1;
  out.rise = component(arc.end, iw) - component(arc.start, iw);
  return out;
}

std::vector<Vec3> arcChords(const ArcSpec& spec, double tol, const std::string& where) {
  const ArcMotion arc = resolveArc(spec, where);
  const double rMax = std::max(arc.radius0, arc.radius1), sweep = arc.sweep;
  // Chords with sagitta r (1 - cos(step / 2)) <= tolerance.
  const double step = tol < rMax ? 2 * std::acos(1 - tol / rMax) : kPi / 2;
  const double pieces = std::ceil(std::fabs(sweep) / std::min(step, kPi / 2));
  if (pieces > 1e6)
    throw InputError(where, fmt::format("arc needs {:g} chords for the tolerance {:g} mm; too "
                                        "many",
                                        pieces, tol));
  const int n = std::max(1, int(pieces));
  std::vector<Vec3> points;
  points.reserve(size_t(n));
  for (int k = 1; k < n; ++k) points.push_back(arc.at(double(k) / n));
  points.push_back(spec.end);
  return points;
}

}  // namespace scallop
