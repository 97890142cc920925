#include "tools/io/gcode_cycles.h"

#include <algorithm>

namespace scallop {

void drillHole(const DrillCycle& c, const Vec3& current, double x, double y,
               const std::function<void(const Vec3&, bool)>& moveTo) {
  // --- To the hole, at the R level. ---
  double z = current.z;
  if (z < c.clearZ) {
    moveTo({current.x, current.y, c.clearZ}, true);
    z = c.clearZ;
  }
  moveTo({x, y, z}, true);
  moveTo({x, y, c.clearZ}, true);
  const auto at = [&](double level) { return Vec3{x, y, level}; };
  // --- Down, and out to R or the end level. ---
  switch (c.code) {
    case 730:
    case 830: {
      double depth = c.clearZ;
      while (true) {
        depth = std::max(depth - c.peck, c.bottomZ);
        moveTo(at(depth), false);
        if (depth <= c.bottomZ) break;
        if (c.code == 730) {
          moveTo(at(depth + kPeckClearance), true);
        } else {
          moveTo(at(c.clearZ), true);
          moveTo(at(std::min(depth + kPeckClearance, c.clearZ)), false);  // inside the hole
        }
      }
      break;
    }
    case 840:
    case 850:
    case 890:
      moveTo(at(c.bottomZ), false);
      moveTo(at(c.clearZ), false);
      break;
    default:  // 810, 820, 860, 880
      moveTo(at(c.bottomZ), false);
      break;
  }
  moveTo(at(c.retractZ), true);
}

}  // namespace scallop
