// The exact lowest point of the solid swept by a cutter of any convex profile along a
// constant-axis move with a linear tip, without the certified search's interval bounds.
//
// With the axis a fixed and tip(t) = p0 + t d, the cutter at t is K(t) = K + tip(t), and
// the set {(t, z) : (x, y, z) in K(t)} is the preimage of the convex K under an affine map,
// so it is convex: f(t), the lowest point of K(t) on the vertical line l through (x, y),
// is a convex function of t on an interval of t (+inf outside: l misses K(t)).
//
//   * Upper bound: every f(t) evaluated (profileLowestPoint, exact) is attained; U is
//     the smallest.
//   * Lower bounds (any unit n with n_z < 0): K(t) lies in n . p <= h(n) + n . tip(t),
//     h the support function of K (profileSupport, exact), so on l
//         f(t) >= (h(n) + n . tip(t) - n_x x - n_y y) / n_z,
//     a line in t valid on all of [0, 1] whatever n is. With n the outward normal at
//     the lowest point of K(t0) it is the tangent of f at t0, slope (n . d) / n_z
//     (a plunge, d = (0, 0, dz): dz). An inexact normal only lowers it.
//   * Misses: where l misses K(t0), a horizontal direction m with
//     m . (x, y) > h(m) + m . tip(t0) separates them, and every t with
//     m . (x, y) - m . tip(t) > h(m) misses too (linear in t): it cuts [0, 1] down.
//   * Kelley's method: the next t is the minimiser of the largest tangent line over
//     what is left of [0, 1]; stop once U - (that minimum) <= kProofGap (a proven height),
//     or the minimum is at or above the cutoff, or nothing is left (a miss).
// Where it cannot close (no separating direction found, a normal too near horizontal,
// 40 samples), it says so and the caller runs the certified search.
#pragma once

#include <cmath>

#include "base/vec3.h"
#include "sweep/cutter_profile.h"
#include "sweep/swept_segment.h"

namespace scallop {

struct ProfileSweepResult {
  bool decided = false;  // false: undecided, the caller must search otherwise
  LowestPoint point;     // when decided: the proven lowest point, or a miss
};

// The lowest point on the vertical line through (x, y) of the profile's cutter (unit axis
// `axis`) swept with its tip from p0 to p1, proven within kProofGap; a height at or above
// `cutoff` may be reported as a miss.
ProfileSweepResult profileSweepLowestPoint(const CutterProfile& profile, const Vec3& axis,
                                           const Vec3& p0, const Vec3& p1, double x, double y,
                                           double cutoff = HUGE_VAL);

}  // namespace scallop
