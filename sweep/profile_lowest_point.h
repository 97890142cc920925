// The stationary kernel of a cutter of any convex profile (cutter_profile.h): its
// support point and its exact lowest point on a vertical line. cutterSupport and
// cutterLowestPoint (swept_segment.h) call these for general cutters; the derivation is
// in profile_lowest_point.cpp and docs/algorithm.md "Cutters of any profile".
#pragma once

#include <cmath>

#include "base/vec3.h"
#include "sweep/cutter_profile.h"
#include "sweep/swept_segment.h"

namespace scallop {

// A point of K (tip at the origin, unit axis `axis`) maximising dot(dir, p).
Vec3 profileSupport(const CutterProfile& profile, const Vec3& axis, const Vec3& dir);

// The lowest point of K (tip at the origin) on the vertical line through (x, y), its z a
// proven lower bound of the true one within 1e-11 mm of it (up to round-off), its normal
// the outward normal of K there. `zBelow` must be a proven lower bound of the answer.
LowestPoint profileLowestPoint(const CutterProfile& profile, const Vec3& axis, double x, double y,
                               double zBelow = -HUGE_VAL);

}  // namespace scallop
