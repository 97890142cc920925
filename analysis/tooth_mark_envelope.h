// The feed marks that the teeth of a cutter leave on the centre line of a level pass, as
// the lower envelope of their arcs (docs/teeth.md "Marks of any set of teeth").
//
// Each time tooth k passes the contact it leaves the meridian arc of the profile there: a
// circle of radius rho_f whose bottom lies at `positionMm` along the feed (within one
// revolution's feed P = z fz, repeating with period P) and `lowerMm` below the nominal
// tooth's. The surface is the lower envelope of all these arcs. Arcs of one radius meet
// pairwise once on their lower halves, so where arc k is the lowest is one interval
// [left, right]: the intersection of the half-lines where it is below each other arc.
// Tooth k cuts iff that interval is not empty; the envelope's highest points are the
// ends of those intervals (its breakpoints: between them it is one convex arc) and its
// lowest is an arc's bottom (or an interval's end, for an arc whose bottom another
// covers). So the peak-to-valley is exact for the circles.
// The parabola z = x^2 / (2 rho_f) (the arcs' osculating parabola) gives the same
// construction with straight-line algebra: the classical fz^2 / (8 rho_f) forms.
#pragma once

#include <vector>

namespace scallop {

struct ToothMark {
  double positionMm = 0;  // the arc's bottom along the feed, mm
  double lowerMm = 0;     // how far below the nominal arc it lies, mm
};

struct MarkEnvelope {
  bool valid = false;         // every arc narrower than 2 rho_f apart from its neighbours
  double peakToValleyMm = 0;  // the circles' envelope
  double peakToValleyParabolaMm = 0;
  std::vector<int> cuttingTeeth;  // the teeth whose arc reaches the envelope (circles)
  // Per cutting tooth: its valley's depth below the lower of the cusps beside it, mm.
  std::vector<double> valleyDepthsMm;
};

// `marks` one per tooth, `periodMm` = P > 0, `radiusMm` = rho_f > 0. Not valid when two
// arcs next to each other (period included) are 2 rho_f or more apart (the circles do
// not meet: the marks are not arcs of this radius only).
MarkEnvelope markEnvelope(const std::vector<ToothMark>& marks, double periodMm, double radiusMm);

}  // namespace scallop
