// Per-tooth geometry of a cutter with teeth (CONVENTIONS.md "Teeth: spindle direction and
// per-tooth geometry", docs/teeth.md "Per-tooth geometry"): each tooth's body angle
// (unequal pitch), its radial and axial offset from the nominal edge, and the span of
// the profile that its edge covers (an insert).
#pragma once

#include <string>
#include <vector>

namespace scallop {

// Tooth k's edge moved as a whole: `radial` mm away from the cutter's axis (every edge
// point's radius rho becomes rho + radial) and `axial` mm along the axis towards the tip
// (its height h above the tip becomes h - axial). Positive: the tooth cuts deeper.
struct ToothOffset {
  double radial = 0;  // mm
  double axial = 0;   // mm
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

// The arc length along a ball, flat or bull profile (flat bottom radius `bottomRadius`,
// corner radius `cornerRadius`) from the axis to its point at height h above the tip
// and radius rho from the axis, mm.
double profileArcLength(double bottomRadius, double cornerRadius, double h, double rho);
// The radius from the axis of that profile's point at arc length u (its inverse's
// radius), mm: non-decreasing in u.
double profileRadiusAt(double bottomRadius, double cornerRadius, double u);

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

}  // namespace scallop
