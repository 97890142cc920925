// CertifiedSearch: the branch and bound over t that finds and proves a turning move's
// lowest point on a vertical line where the fast paths of SweptMove (swept_move.cpp: the
// cutoff's ray clearance, the rim contact) do not settle it, and the chord bound of the
// support function that SweptMove::support shares. Internal to sweep/: SweptMove is its
// one caller. The derivation is in certified_search.cpp, that of its bounds (and of the
// chord bound, defined there) in interval_bounds.cpp.
#pragma once

#include "sweep/cutter.h"
#include "sweep/pose_curve.h"
#include "sweep/swept_segment.h"

namespace scallop {

// mm: the proven lower bound of a turning move's height and the height returned meet
// within this.
constexpr double kProofGap = 1e-9;

// What the search needs of a move besides its cutter and curve.
struct TurningBounds {
  double reach = 0;     // farthest cutter point from the tip, hypot(L, R), mm
  double zTop = 0;      // an upper bound of the swept solid's highest z, mm
  double tipSpeed = 0;  // PoseCurve::tipSpeedBound(), kept with the move
};

// >= max over t in [0, 1] of the support of K(t) in the unit direction N (the chord bound,
// interval_bounds.cpp step 2a, over the whole move), before round-off.
double turningSupport(const Cutter& cutter, const PoseCurve& curve, const TurningBounds& bounds,
                      const Vec3& N);

// The lowest point on the vertical line through (x, y), proven to kProofGap, or a miss
// when the height is proven at or above `cutoff`. The height returned does not depend
// on the cutoff.
LowestPoint certifiedLowestPoint(const Cutter& cutter, const PoseCurve& curve,
                                 const TurningBounds& bounds, double x, double y, double cutoff);

// Searches, over all threads so far, that ran out of samples before their proof closed.
unsigned long long unprovenCertifiedSearches();
// The searches of the calling thread alone (what a caster's tile adds to its run's count).
unsigned long long unprovenCertifiedSearchesOnThisThread();

}  // namespace scallop
