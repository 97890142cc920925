#include "sweep/tooth_geometry.h"

#include <algorithm>
#include <cmath>

#include "base/constants.h"
#include "base/input_error.h"
#include "base/number_text.h"

namespace scallop {

namespace {

std::string entry(const std::string& field, size_t k) {
  return field + "[" + std::to_string(k) + "]";
}

}  // namespace

void checkToothGeometry(const std::vector<double>& anglesDeg,
                        const std::vector<ToothOffset>& offsets, int flutes, double radius,
                        double bottomRadius, const std::string& fieldPrefix) {
  const std::string angles = fieldPrefix + ".tooth_angles_deg";
  const std::string count = std::to_string(flutes) + " (one per flute)";
  if (!anglesDeg.empty()) {
    if (anglesDeg.size() != size_t(flutes))
      throw InputError(
          angles, "expected " + count + " body angles, got " + std::to_string(anglesDeg.size()));
    for (size_t k = 0; k < anglesDeg.size(); ++k) {
      const double a = anglesDeg[k];
      if (!std::isfinite(a) || (k == 0 && a != 0) || a >= 360 || (k > 0 && !(a > anglesDeg[k - 1])))
        throw InputError(entry(angles, k),
                         "body angles in degrees must start at 0, increase strictly and stay "
                         "below 360, got " +
                             formatNumber(a));
    }
  }
  if (offsets.empty()) return;
  const std::string field = fieldPrefix + ".tooth_offsets";
  if (offsets.size() != size_t(flutes))
    throw InputError(field, "expected " + count + " [radial_mm, axial_mm] pairs, got " +
                                std::to_string(offsets.size()));
  // Offsets are errors of microns; beyond R / 10 the edges are another cutter's, and the
  // spindle envelope (Cutter::spindleEnvelope) would be a poor bound.
  const double most = 0.1 * radius;
  for (size_t k = 0; k < offsets.size(); ++k) {
    const ToothOffset& o = offsets[k];
    if (!std::isfinite(o.radial) || !std::isfinite(o.axial) || std::abs(o.radial) > most ||
        std::abs(o.axial) > most)
      throw InputError(entry(field, k), "offsets must be finite and within radius / 10 (" +
                                            formatNumber(most) + " mm), got [" +
                                            formatNumber(o.radial) + ", " + formatNumber(o.axial) +
                                            "]");
    if (o.radial < -bottomRadius)
      throw InputError(entry(field, k) + "[0]",
                       "a radial offset below -(R - r) = " + formatNumber(-bottomRadius) +
                           " mm carries the edge across the axis (give the other teeth "
                           "positive offsets instead), got " +
                           formatNumber(o.radial));
  }
}

RakeLag::RakeLag(const ToothRake& rake, double rho0, double h0) {
  if (rake.zero()) return;
  active_ = true;
  gr_ = degToRad(rake.radialDeg);
  const double ga = degToRad(rake.axialDeg);
  d0_ = -rho0 * std::sin(gr_);
  slope_ = std::tan(ga) * std::cos(gr_);
  h0_ = h0;
}

void checkToothRakes(const std::vector<ToothRake>& rakes, int flutes, const std::string& field,
                     bool perTooth) {
  if (rakes.empty()) return;
  if (perTooth && rakes.size() != size_t(flutes))
    throw InputError(field, "expected " + std::to_string(flutes) +
                                " (one per flute) [axial_deg, radial_deg] pairs, got " +
                                std::to_string(rakes.size()));
  for (size_t k = 0; k < rakes.size(); ++k) {
    const ToothRake& r = rakes[k];
    if (!std::isfinite(r.axialDeg) || !std::isfinite(r.radialDeg) || std::abs(r.axialDeg) > 45 ||
        std::abs(r.radialDeg) > 45)
      throw InputError(perTooth ? entry(field, k) : field,
                       "a rake [axial_deg, radial_deg] has each angle within -45 to 45 degrees, "
                       "got [" +
                           formatNumber(r.axialDeg) + ", " + formatNumber(r.radialDeg) + "]");
  }
}

double profileArcLength(double bottomRadius, double cornerRadius, double h, double rho) {
  const double rb = bottomRadius, r = cornerRadius;
  // The flat bottom (h = 0 to round-off; on a flat end mill the flank's foot has
  // rho = rb too, and there both forms agree).
  if (rho <= rb && h <= 1e-12 * (1 + rb)) return rho;
  if (h < r) return rb + r * std::atan2(std::max(0.0, rho - rb), r - h);  // the corner
  return rb + r * kPi / 2 + (h - r);                                      // the flank
}

double profileRadiusAt(double bottomRadius, double cornerRadius, double u) {
  const double rb = bottomRadius, r = cornerRadius;
  if (u <= rb) return u;
  if (u < rb + r * kPi / 2) return rb + r * std::sin((u - rb) / r);
  return rb + r;
}

double profileHeightAt(double bottomRadius, double cornerRadius, double u) {
  const double rb = bottomRadius, r = cornerRadius;
  if (u <= rb) return 0;
  if (u < rb + r * kPi / 2) return r * (1 - std::cos((u - rb) / r));
  return r + (u - rb - r * kPi / 2);
}

void checkEdgeSpans(const std::vector<EdgeSpan>& spans, int flutes, double edgeLength,
                    const std::string& field, bool perTooth) {
  if (spans.empty()) return;
  if (perTooth && spans.size() != size_t(flutes))
    throw InputError(field, "expected " + std::to_string(flutes) +
                                " (one per flute) [from_mm, to_mm] pairs, got " +
                                std::to_string(spans.size()));
  for (size_t k = 0; k < spans.size(); ++k) {
    const EdgeSpan& s = spans[k];
    if (!std::isfinite(s.from) || !std::isfinite(s.to) || s.from < 0 || s.to > edgeLength ||
        !(s.from < s.to))
      throw InputError(perTooth ? entry(field, k) : field,
                       "an edge span [from_mm, to_mm] is arc length along the profile from "
                       "the axis, 0 <= from < to <= " +
                           formatNumber(edgeLength) + " mm (the whole edge), got [" +
                           formatNumber(s.from) + ", " + formatNumber(s.to) + "]");
  }
}

}  // namespace scallop
