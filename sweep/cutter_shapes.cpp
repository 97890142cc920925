#include "sweep/cutter_shapes.h"

#include <cmath>
#include <memory>
#include <utility>

#include "base/constants.h"
#include "base/input_error.h"
#include "base/number_text.h"
#include "sweep/profile_chain.h"

namespace scallop {

namespace {

// The point of the circle (centre, radius) in the direction of `towards` from the centre.
ProfilePoint pointTowards(ProfilePoint centre, double radius, ProfilePoint towards) {
  const double dr = towards.rho - centre.rho, ds = towards.s - centre.s;
  const double len = std::hypot(dr, ds);
  return {centre.rho + radius * dr / len, centre.s + radius * ds / len};
}

// The top of a side arc (centre, radius) at height L, on the outer side of the circle;
// `L` must lie within radius of the centre's height (checked by the caller).
ProfilePoint sideArcTop(ProfilePoint centre, double radius, double L) {
  const double ds = L - centre.s;
  return {centre.rho + std::sqrt(radius * radius - ds * ds), L};
}

// The flute length or the flute diameter of a tapered flank through (rhoAt0, 0) with
// half-angle `taper` (radians): the length, checked to lie above `flankStart`.
double taperedFluteLength(double fluteLength, double fluteDiameter, double rhoAt0, double taper,
                          double flankStart, const std::string& field) {
  if (fluteLength > 0 && fluteDiameter > 0)
    throw InputError(field + ".flute_diameter",
                     "give flute_length or flute_diameter (the diameter at the flute top), not "
                     "both");
  if (fluteDiameter > 0) {
    requirePositiveLength(fluteDiameter, field + ".flute_diameter");
    const double L = (fluteDiameter / 2 - rhoAt0) / std::tan(taper);
    if (!(L > flankStart))
      throw InputError(field + ".flute_diameter",
                       "must be > " + formatNumber(2 * (rhoAt0 + flankStart * std::tan(taper))) +
                           " mm (the diameter where the flank begins), got " +
                           formatNumber(fluteDiameter));
    return L;
  }
  requirePositiveLength(fluteLength, field + ".flute_length");
  if (!(fluteLength > flankStart))
    throw InputError(field + ".flute_length", "must be > " + formatNumber(flankStart) +
                                                  " mm (the height where the flank begins), got " +
                                                  formatNumber(fluteLength));
  return fluteLength;
}

// A side arc (centre, radius) must reach up to L without passing its top.
void requireSideArcReaches(ProfilePoint centre, double radius, double L, double arcStart,
                           const std::string& field) {
  if (!(L > arcStart && L - centre.s < radius))
    throw InputError(
        field + ".flute_length",
        "must be in (" + formatNumber(arcStart) + ", " + formatNumber(centre.s + radius) +
            ") mm: above where the side arc begins and below its top, got " + formatNumber(L));
}

}  // namespace

std::vector<ProfileSegment> taperBallChain(const TaperBallShape& shape, const std::string& field) {
  requirePositiveLength(shape.tipRadius, field + ".tip_radius");
  requireWithin(shape.taperDeg, 0, 45, true, false, field + ".taper_deg", "degrees");
  const double r = shape.tipRadius, b = shape.taperDeg * kRadPerDeg;
  const ProfilePoint tangent{r * std::cos(b), r * (1 - std::sin(b))};
  // The flank extended down meets s = 0 at rho = r cos b - s_t tan b.
  const double rhoAt0 = tangent.rho - tangent.s * std::tan(b);
  const double L =
      taperedFluteLength(shape.fluteLength, shape.fluteDiameter, rhoAt0, b, tangent.s, field);
  std::vector<ProfileSegment> chain;
  appendArc(chain, {0, 0}, tangent, r, {0, r});
  appendLine(chain, tangent, {tangent.rho + (L - tangent.s) * std::tan(b), L});
  return chain;
}

std::vector<ProfileSegment> taperBullChain(const TaperBullShape& shape, const std::string& field) {
  requirePositiveLength(shape.tipDiameter, field + ".tip_diameter");
  requireWithin(shape.taperDeg, 0, 45, true, false, field + ".taper_deg", "degrees");
  const double b = shape.taperDeg * kRadPerDeg, r = shape.cornerRadius;
  // The corner centre (e, r) at distance r from the flank through (tip_diameter / 2, 0):
  // e = d/2 - r (1 - sin b) / cos b, which must leave a flat bottom (e > 0).
  const double rMax = shape.tipDiameter / 2 * std::cos(b) / (1 - std::sin(b));
  requireWithin(r, 0, rMax, false, true, field + ".corner_radius",
                "mm (a flat bottom must remain; with none the tool is a taper_ball)");
  const double e = shape.tipDiameter / 2 - r * (1 - std::sin(b)) / std::cos(b);
  const ProfilePoint tangent{e + r * std::cos(b), r * (1 - std::sin(b))};
  const double L = taperedFluteLength(shape.fluteLength, shape.fluteDiameter, shape.tipDiameter / 2,
                                      b, tangent.s, field);
  std::vector<ProfileSegment> chain;
  appendLine(chain, {0, 0}, {e, 0});
  if (r > 0) appendArc(chain, {e, 0}, tangent, r, {e, r});
  appendLine(chain, tangent, {shape.tipDiameter / 2 + L * std::tan(b), L});
  return chain;
}

std::vector<ProfileSegment> coneChain(const ConeShape& shape, const std::string& field) {
  requireWithin(shape.angleDeg, 0, 180, true, true, field + ".angle_deg",
                "degrees (the included angle)");
  requirePositiveLength(shape.diameter, field + ".diameter");
  requireWithin(shape.tipDiameter, 0, shape.diameter, false, true, field + ".tip_diameter",
                "mm (0 for a sharp point, less than the diameter)");
  requirePositiveLength(shape.fluteLength, field + ".flute_length");
  const double half = shape.angleDeg / 2 * kRadPerDeg;
  const double R = shape.diameter / 2, tipRho = shape.tipDiameter / 2;
  const double coneHeight = (R - tipRho) / std::tan(half);
  if (shape.fluteLength < coneHeight)
    throw InputError(field + ".flute_length", "must be >= the cone's height " +
                                                  formatNumber(coneHeight) + " mm, got " +
                                                  formatNumber(shape.fluteLength));
  std::vector<ProfileSegment> chain;
  appendLine(chain, {0, 0}, {tipRho, 0});
  appendLine(chain, {tipRho, 0}, {R, coneHeight});
  appendLine(chain, {R, coneHeight}, {R, shape.fluteLength});
  return chain;
}

std::vector<ProfileSegment> barrelChain(const BarrelShape& shape, const std::string& field) {
  requirePositiveLength(shape.diameter, field + ".diameter");
  requirePositiveLength(shape.fluteLength, field + ".flute_length");
  requireWithin(shape.formRadius, shape.diameter / 2, kMaxMagnitudeMm, true, false,
                field + ".form_radius", "mm (more than half the diameter)");
  const double L = shape.fluteLength, Rf = shape.formRadius, r = shape.tipRadius;
  const double he = shape.equatorHeight > 0 ? shape.equatorHeight : L / 2;
  requireWithin(he, 0, L, true, false, field + ".equator_height",
                "mm (the widest point's height, within the flute)");
  const ProfilePoint form{shape.diameter / 2 - Rf, he};
  // The corner circle (e, r) lies inside the form circle, tangent to it and to s = 0:
  // |(e, r) - form| = Rf - r.
  requireWithin(r, 0, he, false, true, field + ".tip_radius",
                "mm (below the widest point's height)");
  const double reach = (Rf - r) * (Rf - r) - (he - r) * (he - r);
  if (!(reach >= 0))
    throw InputError(field + ".equator_height",
                     "must be < form_radius (" + formatNumber(Rf) +
                         " mm): the side arc must reach down to the tip, got " + formatNumber(he));
  const double e = form.rho + std::sqrt(reach);
  if (!(e > 0))
    throw InputError(field + ".tip_radius",
                     "leaves no flat bottom (the corner's centre would be at " + formatNumber(e) +
                         " mm from the axis; with a ball tip the tool is an oval)");
  const ProfilePoint corner{e, r};
  const ProfilePoint tangent = r > 0 ? pointTowards(form, Rf, corner) : ProfilePoint{e, 0};
  requireSideArcReaches(form, Rf, L, tangent.s, field);
  std::vector<ProfileSegment> chain;
  appendLine(chain, {0, 0}, {e, 0});
  if (r > 0) appendArc(chain, {e, 0}, tangent, r, corner);
  appendArc(chain, tangent, sideArcTop(form, Rf, L), Rf, form);
  return chain;
}

std::vector<ProfileSegment> taperBarrelChain(const TaperBarrelShape& shape,
                                             const std::string& field) {
  requirePositiveLength(shape.tipRadius, field + ".tip_radius");
  requireWithin(shape.formRadius, shape.tipRadius, kMaxMagnitudeMm, true, false,
                field + ".form_radius", "mm (more than the tip radius)");
  requireWithin(shape.taperDeg, 0, 45, false, false, field + ".taper_deg", "degrees");
  requirePositiveLength(shape.referenceDiameter, field + ".reference_diameter");
  requirePositiveLength(shape.fluteLength, field + ".flute_length");
  const double r = shape.tipRadius, Rf = shape.formRadius, b = shape.taperDeg * kRadPerDeg;
  // The reference point (d/2, sRef) has its tangent at b from the axis, so the form
  // centre is (d/2 - Rf cos b, sRef + Rf sin b); tangency to the tip ball about (0, r)
  // (|centre - (0, r)| = Rf - r, the centre above the ball's) fixes sRef.
  const double centreRho = shape.referenceDiameter / 2 - Rf * std::cos(b);
  const double reach = (Rf - r) * (Rf - r) - centreRho * centreRho;
  if (!(reach > 0))
    throw InputError(field + ".reference_diameter",
                     "no side arc of this form radius and taper is tangent to the tip ball at "
                     "this diameter (expected less than " +
                         formatNumber(2 * (Rf * std::cos(b) + Rf - r)) + " mm)");
  const ProfilePoint form{centreRho, r + std::sqrt(reach)};
  const ProfilePoint tip{0, r};
  const ProfilePoint tangent = pointTowards(form, Rf, tip);
  const double sRef = form.s - Rf * std::sin(b);
  if (!(sRef > tangent.s) || !(tangent.rho > 0))
    throw InputError(field + ".reference_diameter",
                     "puts the reference point (where the side arc's tangent makes taper_deg with "
                     "the axis) on the tip ball, not on the side arc");
  requireSideArcReaches(form, Rf, shape.fluteLength, sRef, field);
  std::vector<ProfileSegment> chain;
  appendArc(chain, {0, 0}, tangent, r, tip);
  appendArc(chain, tangent, sideArcTop(form, Rf, shape.fluteLength), Rf, form);
  return chain;
}

std::vector<ProfileSegment> ovalChain(const OvalShape& shape, const std::string& field) {
  requirePositiveLength(shape.diameter, field + ".diameter");
  requireWithin(shape.tipRadius, 0, shape.diameter / 2, true, true, field + ".tip_radius",
                "mm (less than half the diameter)");
  requireWithin(shape.formRadius, shape.diameter / 2, kMaxMagnitudeMm, true, false,
                field + ".form_radius", "mm (more than half the diameter)");
  requirePositiveLength(shape.fluteLength, field + ".flute_length");
  const double r = shape.tipRadius, Rf = shape.formRadius;
  // The side circle's centre (D/2 - Rf, he) at Rf - r from the tip ball's (0, r).
  const double centreRho = shape.diameter / 2 - Rf;
  const ProfilePoint form{centreRho, r + std::sqrt((Rf - r) * (Rf - r) - centreRho * centreRho)};
  const ProfilePoint tip{0, r};
  const ProfilePoint tangent = pointTowards(form, Rf, tip);
  requireSideArcReaches(form, Rf, shape.fluteLength, tangent.s, field);
  std::vector<ProfileSegment> chain;
  appendArc(chain, {0, 0}, tangent, r, tip);
  appendArc(chain, tangent, sideArcTop(form, Rf, shape.fluteLength), Rf, form);
  return chain;
}

std::vector<ProfileSegment> lensChain(const LensShape& shape, const std::string& field) {
  requirePositiveLength(shape.diameter, field + ".diameter");
  requireWithin(shape.formRadius, shape.diameter / 2, kMaxMagnitudeMm, true, false,
                field + ".form_radius", "mm (the tip arc: more than half the diameter)");
  requireWithin(shape.cornerRadius, 0, shape.diameter / 2, false, true, field + ".corner_radius",
                "mm (less than half the diameter)");
  const double R = shape.diameter / 2, Rf = shape.formRadius, rc = shape.cornerRadius;
  const ProfilePoint lens{0, Rf};
  // The corner circle (R - rc, sc) inside the lens circle, tangent to it: the lower root.
  const ProfilePoint corner{R - rc, Rf - std::sqrt((Rf - rc) * (Rf - rc) - (R - rc) * (R - rc))};
  const ProfilePoint tangent = pointTowards(lens, Rf, corner);
  requirePositiveLength(shape.fluteLength, field + ".flute_length");
  if (shape.fluteLength < corner.s)
    throw InputError(field + ".flute_length",
                     "must be >= " + formatNumber(corner.s) +
                         " mm (the height where the cylinder begins), got " +
                         formatNumber(shape.fluteLength));
  std::vector<ProfileSegment> chain;
  appendArc(chain, {0, 0}, tangent, Rf, lens);
  if (rc > 0) appendArc(chain, tangent, {R, corner.s}, rc, corner);
  appendLine(chain, {R, corner.s}, {R, shape.fluteLength});
  return chain;
}

Cutter cutterOfChain(CutterType type, std::vector<ProfileSegment> chain, const std::string& field) {
  auto profile = std::make_shared<const CutterProfile>(
      CutterProfile::make(std::move(chain), field + ".segments"));
  Cutter cutter;
  cutter.type = type;
  cutter.radius = profile->maxRadius();
  cutter.cornerRadius = 0;
  cutter.fluteLength = profile->fluteLength();
  cutter.profile = std::move(profile);
  return cutter;
}

bool sameShape(const Cutter& a, const Cutter& b) {
  if (a.type != b.type || a.radius != b.radius || a.cornerRadius != b.cornerRadius ||
      a.fluteLength != b.fluteLength || a.general() != b.general())
    return false;
  if (!a.general()) return true;
  const auto& x = a.profile->segments();
  const auto& y = b.profile->segments();
  if (x.size() != y.size()) return false;
  for (size_t i = 0; i < x.size(); ++i)
    if (x[i].rho0 != y[i].rho0 || x[i].s0 != y[i].s0 || x[i].rho1 != y[i].rho1 ||
        x[i].s1 != y[i].s1 || x[i].arcRadius != y[i].arcRadius)
      return false;
  return true;
}

}  // namespace scallop
