// Per-tooth geometry of a cutter with teeth (CONVENTIONS.md "Teeth: spindle direction and
// per-tooth geometry", docs/teeth.md "Per-tooth geometry"): each tooth's body angle
// (unequal pitch), its radial and axial offset from the nominal edge, the span of the
// profile that its edge covers (an insert), and the rake that turns its edge out of the
// meridian plane.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace scallop {

// Tooth k's edge moved as a whole: `radial` mm away from the cutter's axis (every edge
// point's radius rho becomes rho + radial) and `axial` mm along the axis towards the tip
// (its height h above the tip becomes h - axial). Positive: the tooth cuts deeper.
struct ToothOffset {
  double radial = 0;  // mm
  double axial = 0;   // mm
  bool operator==(const ToothOffset& o) const { return radial == o.radial && axial == o.axial; }
  bool operator!=(const ToothOffset& o) const { return !(*this == o); }
};

// Tooth k's edge covers the meridian profile only between these arc lengths, mm,
// measured along the profile from the axis at the tip: the flat bottom from 0 to Rb, the
// corner arc from Rb to Rb + r pi / 2, then the flank up to the flute length (a ball's
// arc from 0, a flat end mill's flank from R). A round insert on a bull cutter is
// [Rb, Rb + r pi / 2]. The body behind the rest of the profile does not cut. The span
// is the nominal edge's: a tooth's offsets move it with its edge.
struct EdgeSpan {
  double from = 0;  // mm
  double to = 0;    // mm
  bool operator==(const EdgeSpan& o) const { return from == o.from && to == o.to; }
  bool operator!=(const EdgeSpan& o) const { return !(*this == o); }
};

// Tooth k's rake (tool keys "rake_deg", "tooth_rakes_deg"), degrees. The edge lies on
// its rake face, a plane through the edge's reference point P0 (the nominal profile's
// point at the span's start, or at the tip's axis for a whole edge). In the tooth's own
// frame (radial c, trailing s, axial h; s > 0 behind the radial line in the spindle's
// turn) that plane is
//     s = (c - rho0) tan(radial) + (h - h0) tan(axial),
// the meridian plane s = 0 turned by `radial` about the axis-parallel line through P0 and
// by `axial` about the radial line through it. Positive axial rake: points above P0
// trail, as a right-hand helix's do; positive radial rake: points farther out trail.
struct ToothRake {
  double axialDeg = 0;   // degrees, in [-45, 45]
  double radialDeg = 0;  // degrees, in [-45, 45]
  bool zero() const { return axialDeg == 0 && radialDeg == 0; }
  bool operator==(const ToothRake& o) const {
    return axialDeg == o.axialDeg && radialDeg == o.radialDeg;
  }
  bool operator!=(const ToothRake& o) const { return !(*this == o); }
};

// The angle by which a raked edge's point trails the tooth's body angle, radians: the
// rake face meets the profile's surface of revolution (the edge stays on it, so the
// spindle envelope does not change) at the point of radius rho and height h whose angle
// lambda from the radial line solves rho sin(lambda) = (rho cos(lambda) - rho0)
// tan(gr) + (h - h0) tan(ga), that is
//     rho sin(lambda - gr) = D(h) = -rho0 sin(gr) + (h - h0) tan(ga) cos(gr),
//     lambda = gr + asin(D / rho)   (the branch through P0, where lambda = 0).
// The face meets the circle of radius rho only where |D| <= rho; checkToothRakes keeps
// every edge point within |D| <= rho sin(60 deg). The argument is clamped to [-1, 1]
// elsewhere (points off the span, which carry no edge, stay continuous).
class RakeLag {
 public:
  RakeLag() = default;
  RakeLag(const ToothRake& rake, double rho0, double h0);
  bool active() const { return active_; }
  double operator()(double rho, double h) const {
    if (!active_) return 0;
    const double d = d0_ + (h - h0_) * slope_;
    // At the axis (rho -> 0) the face through it (d = 0) is the radial line turned by gr.
    if (!(rho > 1e-300)) return gr_;
    return gr_ + std::asin(std::clamp(d / rho, -1.0, 1.0));
  }
  // D at height h, mm (for checkToothRakes).
  double offset(double h) const { return d0_ + (h - h0_) * slope_; }

 private:
  bool active_ = false;
  double gr_ = 0;     // the radial rake, rad
  double d0_ = 0;     // -rho0 sin(gr), mm
  double slope_ = 0;  // tan(ga) cos(gr)
  double h0_ = 0;     // mm
};

// The arc length along a ball, flat or bull profile (flat bottom radius `bottomRadius`,
// corner radius `cornerRadius`) from the axis to its point at height h above the tip
// and radius rho from the axis, mm.
double profileArcLength(double bottomRadius, double cornerRadius, double h, double rho);
// The radius from the axis of that profile's point at arc length u (its inverse's
// radius), mm: non-decreasing in u.
double profileRadiusAt(double bottomRadius, double cornerRadius, double u);
// And its height above the tip, mm.
double profileHeightAt(double bottomRadius, double cornerRadius, double u);

// Validates the tool key "edge_span" (one span for every tooth) or "tooth_edge_spans"
// (one per flute): each within [0, edgeLength] (the profile's whole arc length), from <
// to. Empty: every edge whole. Throws InputError naming `field` and the entry.
void checkEdgeSpans(const std::vector<EdgeSpan>& spans, int flutes, double edgeLength,
                    const std::string& field, bool perTooth);

// Validates the tool keys "tooth_angles_deg" (one body angle per flute, degrees, the
// first 0, strictly increasing, below 360) and "tooth_offsets" (one pair per flute, each
// offset within radius / 10, and a radial one no less than -(R - r): the edge may not
// cross the axis). Empty vectors mean the defaults (equal pitch, no offsets). Throws
// InputError naming fieldPrefix + ".tooth_angles_deg" / ".tooth_offsets" and the entry.
void checkToothGeometry(const std::vector<double>& anglesDeg,
                        const std::vector<ToothOffset>& offsets, int flutes, double radius,
                        double bottomRadius, const std::string& fieldPrefix);

// Validates the tool key "rake_deg" (one [axial, radial] pair for every tooth) or
// "tooth_rakes_deg" (one per flute): each angle finite and within [-45, 45] degrees.
// (Where the face leaves the profile is checked by Cutter::checkRakes, which knows the
// profile.) Throws InputError naming `field` and the entry.
void checkToothRakes(const std::vector<ToothRake>& rakes, int flutes, const std::string& field,
                     bool perTooth);

}  // namespace scallop
