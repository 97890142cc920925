// The effective radius at the contact: see contact_curvature.h for the derivation.
#include "analysis/contact_curvature.h"

#include <fmt/core.h>

#include <cmath>
#include <string>

#include "sweep/raster.h"

namespace scallop {

namespace {

constexpr const char* kName = "effective_radius";

ProcedureResult notApplicable(const std::string& why) {
  return {false, 0.0, std::string(kName) + ": " + why};
}

}  // namespace

// In the (rho, s) half-plane the contact's outward normal is (sin psi, -cos psi), at
// the angle psi - 90 deg from +rho. Along a convex profile from the tip up the
// normal's angle increases, so the contact lies on the segment whose end normals
// enclose it.
ContactArc contactArc(const Cutter& cutter, double sinPsi, double cosPsi) {
  ContactArc arc;
  const double target = std::atan2(-cosPsi, sinPsi);
  constexpr double kAngleTol = 1e-12;  // rad
  switch (cutter.type) {
    case CutterType::Ball:
      return {true, cutter.radius, 0.0, cutter.radius, {}};
    case CutterType::Bull:
      if (sinPsi > 0)
        return {true, cutter.cornerRadius, cutter.bottomRadius(), cutter.cornerRadius, {}};
      arc.reason = "the untilted bull touches the plane along its flat bottom";
      return arc;
    case CutterType::Flat:
      arc.reason = sinPsi > 0 ? "an inclined flat end mill touches the plane with the sharp "
                                "corner of its rim, a point of infinite curvature"
                              : "the untilted flat end mill touches the plane along its bottom";
      return arc;
    default:
      break;
  }
  if (!cutter.profile) {
    arc.reason = std::string("the ") + toString(cutter.type) + " cutter has no profile";
    return arc;
  }
  for (const ProfileSegment& seg : cutter.profile->segments()) {
    if (seg.arcRadius > 0) {
      const double a0 = std::atan2(seg.s0 - seg.centreS, seg.rho0 - seg.centreRho);
      const double a1 = std::atan2(seg.s1 - seg.centreS, seg.rho1 - seg.centreRho);
      if (target > a0 + kAngleTol && target < a1 - kAngleTol)
        return {true, seg.arcRadius, seg.centreRho, seg.centreS, {}};
      if (target >= a0 - kAngleTol && target <= a1 + kAngleTol) {
        arc.reason = "the contact lies where an arc meets the next segment of the profile";
        return arc;
      }
    } else {
      const double a = std::atan2(-(seg.rho1 - seg.rho0), seg.s1 - seg.s0);
      if (std::fabs(target - a) <= kAngleTol) {
        arc.reason = "a straight line of the profile (a cone or a flat) lies on the plane";
        return arc;
      }
    }
  }
  arc.reason = "the contact is a corner of the profile, a point of infinite curvature";
  return arc;
}

ProcedureResult effectiveRadiusAtContact(const Cutter& cutter, double leadDeg, double tiltDeg) {
  if (!std::isfinite(leadDeg) || !std::isfinite(tiltDeg) || std::fabs(leadDeg) >= 90 ||
      std::fabs(tiltDeg) >= 90)
    return notApplicable(
        fmt::format("lead {:g} deg and tilt {:g} deg must satisfy |angle| < 90", leadDeg, tiltDeg));
  const Vec3 a = leadTiltAxis(Vec3{1, 0, 0}, leadDeg, tiltDeg);
  const double sinPsi = std::hypot(a.x, a.y), cosPsi = a.z;
  const ContactArc arc = contactArc(cutter, sinPsi, cosPsi);
  if (!arc.found) return notApplicable(arc.reason);
  if (sinPsi == 0) {
    // Vertical axis: the parallel's radius rho0 / sin(psi) + R_arc tends to R_arc only
    // for an arc centred on the axis; otherwise the contact is a ring.
    if (arc.centreRho != 0)
      return notApplicable("with a vertical axis the arc touches the plane along a ring");
    return {true, arc.radius, {}};
  }
  const double sin2Beta = a.y * a.y / (sinPsi * sinPsi);
  const double parallelRadius = arc.centreRho / sinPsi + arc.radius;  // rho_c / sin(psi)
  return {true, arc.radius * sin2Beta + parallelRadius * (1 - sin2Beta), {}};
}

ProcedureResult halfIntervalEffectiveRadius(const Cutter& cutter, double leadDeg, double tiltDeg,
                                            double scallopHeightMm) {
  return circularHalfInterval(kName, effectiveRadiusAtContact(cutter, leadDeg, tiltDeg),
                              scallopHeightMm, cutter.radius);
}

ProcedureResult scallopHeightEffectiveRadius(const Cutter& cutter, double leadDeg, double tiltDeg,
                                             double halfIntervalMm) {
  return circularScallopHeight(kName, effectiveRadiusAtContact(cutter, leadDeg, tiltDeg),
                               halfIntervalMm, cutter.radius);
}

}  // namespace scallop
