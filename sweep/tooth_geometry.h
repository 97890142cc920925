// Per-tooth geometry of a cutter with teeth (CONVENTIONS.md "Teeth: spindle direction and
// per-tooth geometry", docs/teeth.md "Per-tooth geometry"): each tooth's body angle
// (unequal pitch) and its radial and axial offset from the nominal edge.
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

// Validates the tool keys "tooth_angles_deg" (one body angle per flute, degrees, the
// first 0, strictly increasing, below 360) and "tooth_offsets" (one pair per flute, each
// offset within radius / 10, and a radial one no less than -(R - r): the edge may not
// cross the axis). Empty vectors mean the defaults (equal pitch, no offsets). Throws
// InputError naming fieldPrefix + ".tooth_angles_deg" / ".tooth_offsets" and the entry.
void checkToothGeometry(const std::vector<double>& anglesDeg,
                        const std::vector<ToothOffset>& offsets, int flutes, double radius,
                        double bottomRadius, const std::string& fieldPrefix);

}  // namespace scallop
