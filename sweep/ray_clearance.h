// RayClearance: a proof, without any lowest-point search, that the cutter stays above
// a height on a vertical line during part of a move whose axis turns.
//
// "The downward ray from Q = (x, y, z) misses K(t) for every t in [t0, t1]" is exactly
// "f(t) > z on [t0, t1]" for the lowest point f(t) of K(t) on the line through (x, y).
// The turning-axis search (swept_move.cpp) asks it twice: with z = the caller's cutoff
// before sampling anything (a move that cannot beat the cell's best height costs a few
// closed-form distances instead of two stationary searches), and with z = U - 1e-9 once
// the minimum of f is located (the whole move proven in one pass instead of a ladder
// of intervals). The argument is in ray_clearance.cpp; a false return proves nothing
// and the caller's branch and bound goes on.
#pragma once

#include "sweep/cutter.h"
#include "sweep/pose_curve.h"
#include "base/vec3.h"

namespace scallop {

// True only if the downward vertical ray from `q` provably misses every K(t) with t in
// [t0, t1]; `anchor` in [t0, t1] is where the cutter's motion is linearised (the
// proof is tightest near it). Ball and bull cutters (r > 0); a flat cutter always
// returns false (its sharp rim leaves the argument's normal bound without a radius).
// `insideAtAnchor`, if given, is set when q lies inside the cutter's convex hull of core
// and corner (K' below) at the anchor itself: no other anchor can clear it either.
bool rayClearsMove(const Cutter& cutter, const PoseCurve& curve, const Vec3& q, double anchor,
                   double t0, double t1, bool* insideAtAnchor = nullptr);
// The same for every downward ray from a point within `radius` (mm) of q, all at once:
// the rays of a block of cells below an upper bound of its heights (ray_clearance.cpp,
// "A disc of rays").
bool raysClearMove(const Cutter& cutter, const PoseCurve& curve, const Vec3& q, double radius);
// The same from a pose already computed at the anchor (anchor.t).
bool rayClearsMove(const Cutter& cutter, const PoseCurve& curve, const Vec3& q,
                   const PoseFrame& anchor, double t0, double t1, bool* insideAtAnchor = nullptr);

// d^2 f / dt^2 at t for the lowest point f(t) of K(t) on the vertical line through p,
// p being that lowest point (on K(t)'s boundary): the Newton step of the search's
// first probe (certified_search.cpp step 5). A heuristic that only chooses where to sample,
// not a bound; NaN where p lies above the flute top or on K's upper side.
double lowestPointCurvature(const Cutter& cutter, const PoseCurve& curve, double t, const Vec3& p);

}  // namespace scallop
