// CutterProfile: the meridian profile of a cutter of any shape that CONVENTIONS.md
// "Cutter shapes" describes (tapered ball and bull, cone, the barrel family, APT's
// 7-parameter CUTTER, a free profile): a solid of revolution whose profile, from the tip
// up, is a convex chain of straight lines and circular arcs.
//
// In the (rho, s) half-plane of one meridian (rho >= 0 the distance from the axis, s the
// height above the tip along the axis) the cutter is the region
//     P = { (rho, s) : 0 <= s <= L,  0 <= rho <= w(s) }
// where w, the chain, is concave, starts at (w(0), 0) (w(0) > 0: a flat bottom of that
// radius, the chain's first segment is then the horizontal line from the axis) and ends
// at (w(L), L), the flute top, closed by the horizontal cap s = L. The solid K is P swept
// about the axis. Mirrored about the axis P is convex, so K is convex, which is what the
// kernel's exactness rests on (docs/algorithm.md).
//
// Ball, flat and bull cutters keep their own kernel (sweep/swept_segment.cpp and
// friends, bit for bit); CutterProfile::of gives their profile too, so the general
// kernel can be checked against theirs.
#pragma once

#include <string>
#include <vector>

namespace scallop {

struct Cutter;

// One piece of the chain, from (rho0, s0) to (rho1, s1), mm.
struct ProfileSegment {
  double rho0 = 0, s0 = 0, rho1 = 0, s1 = 0;
  // 0: a straight line. > 0: the circular arc of this radius (mm) through both ends
  // whose centre lies on the solid's side of the chord (the arc bulges outwards, as a
  // convex profile needs), the shorter of the two such arcs.
  double arcRadius = 0;
  // Arcs: the centre (rho, s), mm; filled in by CutterProfile::make.
  double centreRho = 0, centreS = 0;
};

// A point of the (rho, s) half-plane.
struct ProfilePoint {
  double rho = 0, s = 0;
};

class CutterProfile {
 public:
  // From the tip up. The first segment starts at (0, 0) (the tip on the axis); the last
  // ends at s = L > 0; each starts where the previous ended (within 1e-9 mm, then made
  // exact); the chain turns only towards the solid (convex, corners allowed) and stays
  // at rho >= 0; its tangent at the tip points up or outwards (no spike below the tip)
  // and its last tangent no further round than the cap's. Throws InputError naming
  // `field` + "[i]" (the segment) and what is wrong otherwise.
  static CutterProfile make(std::vector<ProfileSegment> chain, const std::string& field);
  // The profile of a ball, flat or bull cutter (or of a profile cutter: its own).
  static CutterProfile of(const Cutter& cutter);

  const std::vector<ProfileSegment>& segments() const { return segments_; }
  double fluteLength() const { return fluteLength_; }    // L, mm
  double maxRadius() const { return maxRadius_; }        // max of w, mm
  double bottomRadius() const { return bottomRadius_; }  // w(0): the flat bottom's, mm
  // hypot(L, maxRadius): no point of K is farther from the tip, mm.
  double reach() const { return reach_; }

  // w(s) for s in [0, L] (0 outside), mm.
  double width(double s) const;
  // A point of P maximising nRho * rho + nS * s (nRho >= 0; the pair need not be unit):
  // the support point of K in a direction whose component across the axis is nRho.
  ProfilePoint support(double nRho, double nS) const;
  // The signed Euclidean distance from (rho, s), rho >= 0, to P (negative inside), and
  // its gradient where asked (unit outside; at a point where it is not differentiable,
  // one subgradient). It is the signed distance from the 3D point to K.
  double signedDistance(double rho, double s, double* dRho = nullptr, double* dS = nullptr) const;
  // The profile of K (+) Ball(delta) cut at s <= L + 2 delta with its tip moved delta
  // lower (that is, every point of K within delta, in the frame of a tip delta lower):
  // still a convex chain of lines and arcs (corners become arcs of radius delta).
  CutterProfile grown(double delta) const;
  // The profile moved dRho mm away from the axis at every height: w(s) + dRho, its flat
  // bottom's radius w(0) + dRho (a sharp tip gains a flat bottom of radius dRho). The
  // solid a tooth's radial offset or the spindle's runout sweeps (cutter.h). Needs
  // dRho >= -bottomRadius(); still convex (w + dRho is concave).
  CutterProfile widened(double dRho) const;

  // Arc length along the chain from the axis at the tip (edge spans' parameter, mm): the
  // whole chain's, and that of the chain point nearest (rho, s) (a point of the chain
  // gives its own; one on the cap, the chain's end).
  double arcLength() const;
  double arcLengthAt(double rho, double s) const;
  // The chain's point at arc length u, clamped to [0, arcLength()].
  ProfilePoint pointAt(double u) const;
  // The smallest and largest distance from the axis of the chain's points whose arc
  // length lies in [from, to], mm (a barrel's chain need not widen all the way up).
  void radiusRange(double from, double to, double* lo, double* hi) const;

 private:
  // A chain already known to be valid, with its arcs' centres: the derived values.
  static CutterProfile fromChain(std::vector<ProfileSegment> chain);

  std::vector<ProfileSegment> segments_;
  // Each segment's tangent angle from +rho towards +s at its start and end, radians.
  std::vector<double> startAngle_, endAngle_;
  double fluteLength_ = 0, maxRadius_ = 0, bottomRadius_ = 0, reach_ = 0;
};

}  // namespace scallop
