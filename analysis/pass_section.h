// PassSection: the exact path interval of any cutter of revolution,
// the seeds' computational procedure (seed 000 Fig. 1) generalised from the inclined
// torus to every convex cutter and to lead and tilt together.
//
// Setting. Straight passes feed along +x on the plane z = 0 with a fixed axis a
// (leadTiltAxis: lead towards +x, tilt towards +y), w apart along y. K is the cutter
// (a convex solid, tip at the origin), known only through its support map
// S(u) = argmax_{p in K} u.p (sweep/swept_segment.h cutterSupport). Far from a pass's
// ends the surface it leaves at offset y is the lower envelope of its shadow along x:
//     F(y) = min { z : (x, y, z) in K for some x } - z_min,
// the lower boundary of the projection P of K onto the (y, z) plane, measured from the
// floor z_min = S(-z).z (the depth rule). P is convex, so F is convex.
//
// Sides. With zh = z_min + h, the farthest offset on the +y side where F <= h is
//     y+(h) = max { p_y : p in K, p_z <= zh }.
// Lagrange duality (K convex, and p = S(-z) is strictly feasible for h > 0) gives for
// every direction u(phi) = (0, cos phi, -sin phi), phi in [0, pi/2):
//     y+(h) <= U(phi) = q_y + tan(phi) (zh - q_z),   q = S(u(phi)),
// since cos(phi) p_y - sin(phi) p_z <= u.q for every p in K; equality holds at the
// optimal phi*. q_z falls monotonically from the top of the shadow's right end
// (phi = 0) to z_min (phi = pi/2), so phi* is where q_z crosses zh: bisection on phi
// keeps q(phi_a) at or above zh and q(phi_b) below, and the chord between the two
// support points (both in K) crosses z = zh at a point of K, a proven lower bound
// y+ >= y_L. The bracket [y_L, min U] shrinks to zero (at phi* the support set holds
// the boundary point (y+, zh), or an edge through it, which the chord then contains);
// we stop when it is below `toleranceMm` (default 1e-10 mm, the procedure is exact to
// 1e-9 mm). If phi* = 0, the shadow ends at a vertical flank that starts below zh:
// F never rises to h on that side ("h is beyond the cutter"). The -y side is the same
// with u = (0, -cos phi, -sin phi).
//
// Step-over and scallop. Two passes w apart leave min(F(y), F(y - w)): F rises to the
// right of its minimum and F(y - w) falls to the left of the next pass's, so the
// highest point between them is where they cross, and
//     scallop(w) = max_y min(F(y), F(y - w)) = min { h : y+(h) + y-(h) >= w }.
// The width W(h) = y+(h) + y-(h) of P at height h is concave and nondecreasing, so the
// step-over for a scallop h is W(h) itself (no iteration beyond the two sides) and the
// scallop of a step-over w is the root of the monotone W(h) - w, found by bisection on
// h with the certified brackets of W.
//
// Offsets are reported from the pass's centre line y_c = (r a).y, r the corner radius
// (the centre of the ball or of the torus's spine circle, the tip otherwise), as
// analysis/simulated_interval.h measures them; the step-over does not depend on it.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "analysis/path_interval.h"
#include "base/vec3.h"
#include "sweep/cutter.h"

namespace scallop {

// A support map of a convex body: a point p of it maximising dot(dir, p), mm.
using SupportMap = std::function<Vec3(const Vec3& dir)>;

// A certified enclosure of an exact value, mm: low <= value <= high.
struct Enclosure {
  double low = 0, high = 0;
  double mid() const { return 0.5 * (low + high); }
  double width() const { return high - low; }
};

// One side of the section at height h above the floor.
struct SectionSide {
  bool reachable = false;  // false: the shadow's flank starts below h (see the header)
  Enclosure offset;        // y+ (or y- on the -y side) from the tip's y, outwards, mm
};

// A pass of a set of parallel passes, in a cross coordinate across them: its tip's
// position, and whether the section's +y side points towards decreasing cross
// coordinates (a pass fed the other way, or a cross axis along -y).
struct PassPlacement {
  double crossMm = 0;
  bool mirrored = false;
};

class PassSection {
 public:
  // `support` is the inclined cutter's support map in the world frame (tip at the
  // origin); `centreY` the centre line's offset from the tip, mm.
  PassSection(SupportMap support, double centreY, double toleranceMm = 1e-10);
  // The cutter tilted by leadTiltAxis(+x, leadDeg, tiltDeg).
  static PassSection of(const Cutter& cutter, double leadDeg, double tiltDeg,
                        double toleranceMm = 1e-10);

  double floorZ() const { return floorZ_; }  // z_min, mm (tip at z = 0)
  double centreY() const { return centreY_; }
  // The shadow's extent on each side (the support in +-y), from the centre line, mm.
  double reachPlusMm() const { return reachPlus_ - centreY_; }
  double reachMinusMm() const { return reachMinus_ + centreY_; }
  // The highest point of the cutter above the floor, mm: no scallop exceeds it.
  double heightMm() const { return top_ - floorZ_; }

  // Where F rises h above the floor, from the tip's y; sign = +1 for +y, -1 for -y
  // (then the offset is positive outwards: the point is at y = -offset).
  SectionSide side(double h, int sign) const;
  // The same from the centre line (positive outwards).
  SectionSide sideFromCentre(double h, int sign) const;
  // W(h) = y+(h) + y-(h), the step-over that leaves a scallop of exactly h; false
  // if h is beyond the cutter on either side.
  bool stepOver(double h, Enclosure* width) const;
  // The scallop that two passes `stepOverMm` apart leave, mm, to `toleranceMm`;
  // false (with `reason`) if the passes leave an uncut strip or meet only on a
  // vertical flank.
  bool scallop(double stepOverMm, double* scallopMm, std::string* reason) const;
  // The same for any set of parallel passes (a raster, a zigzag's mirrored passes):
  // the largest scallop over the cross coordinates [fromMm, toMm], the least h at which
  // the intervals where each pass leaves at most h, [c - y-(h), c + y+(h)] (mirrored:
  // [c - y+(h), c + y-(h)]), cover it. Monotone in h, so bisection on h.
  bool coverScallop(const std::vector<PassPlacement>& passes, double fromMm, double toMm,
                    double* scallopMm, std::string* reason) const;
  // The floor contact's offset from the tip along +y, mm.
  double floorY() const { return floorY_; }

 private:
  SupportMap support_;
  double centreY_, tolerance_;
  double floorZ_ = 0, floorY_ = 0, top_ = 0, reachPlus_ = 0, reachMinus_ = 0;
};

// The procedure "exact" of `scallop interval` for any cutter, lead and tilt: L/2 =
// W(h) / 2 (half the step-over that leaves exactly h), and h back from L/2; the
// reasons name "exact". Exact to `toleranceMm` + 1e-12 mm.
ProcedureResult halfIntervalExact(const Cutter& cutter, double leadDeg, double tiltDeg,
                                  double scallopHeightMm, double toleranceMm = 1e-10);
ProcedureResult scallopHeightExact(const Cutter& cutter, double leadDeg, double tiltDeg,
                                   double halfIntervalMm, double toleranceMm = 1e-10);

}  // namespace scallop
