// Brute-force reference for the "teeth" cutting model, used only by the tests.
//
// Written from the definitions in sweep/tooth_sweep.h's header comment, sharing no code
// with sweep/tooth_sweep.cpp (it reads the Cutter's parameters and uses Vec3, nothing
// else of the project). The edge of tooth k is a curve in the cutter's body, by arc
// length u along the meridian profile from the axis:
//     bottom  u in [0, Rb]:               rho = u, h = 0
//     corner  u in [Rb, Rb + r pi / 2]:   alpha = (u - Rb) / r, rho = Rb + r sin(alpha),
//                                         h = r (1 - cos(alpha))
//     flank   up to u = Rb + r pi / 2 + L - r:  rho = R, h from r to L
// and at time t its point is (tooth_sweep.h)
//     P(k, u, t) = tip(t) + Q(t) [ runout (cos(psi_r - phi) e1 + sin(psi_r - phi) e2)
//                   + (rho + dr_k) (cos(psi_k + h tan(beta) / R + lambda_k - phi) e1
//                                   + sin(...) e2)
//                   + (h - da_k) a0 ]
// with psi_k tooth k's body angle (2 pi k / flutes, or tooth_angles_deg), (dr_k, da_k)
// its tooth_offsets, lambda_k(rho, h) the angle at which the profile's circle at (rho,
// h) meets tooth k's rake face (tooth_geometry.h's ToothRake; solved by bisection,
// sharing nothing with RakeLag's closed form; 0 without rake), (e1, e2, a0) the
// spindle frame at t = 0 (e1 = world X made perpendicular to a0, world Y when a0 is
// within 30 degrees of X; e2 = a0 x e1, or e1 x a0 for a counter-clockwise spindle),
// Q(t) the axis's rotation (slerp: a turn about w = a0 x a1 / |a0 x a1| by the angle
// between them times t, written here with Rodrigues' formula) and phi = phaseStart +
// phaseRate t.
//
// A tooth whose edge covers a span of the profile (CutterTeeth::edgeSpans, [from, to] in
// this arc length u) has only u in [from, to]: every tooth's u below runs over its span.
//
// The search: the lowest z over every k, u in [0, U], t in [0, 1] with P.xy = (x, y),
// by best-first subdivision of the (u, t) rectangle of each tooth. A cell of half-sizes
// (du, dt) around its centre c holds no edge point farther than
//     B = Lu du + Lt dt   from P(c),   Lu = hypot(1, (R + |dr|max) tan(beta) / R
//                                                 + the rake's turn bound),
//     Lt = |p1 - p0| + (turn + |phaseRate|) (runout + hypot(rho(u_top) + |dr|max,
//                                                           h(u_top) + |da|max))
// (|dP/du| <= Lu: the meridian is by arc length, the helix adds (rho + dr) tan(beta) / R
// across it, a rake its own turn, bounded per tooth in the test file; |dP/dt|: the
// tip's speed plus the rotation of the body point, whose angular velocity is at most
// turn + |phaseRate|). So a cell can hold a crossing only if |P(c).xy - (x, y)| <= B,
// and none below P(c).z - B. Cells are taken lowest bound first and halved; Newton on
// the 2x2 system P(u, t).xy = (x, y) (clamped to the
// domain) is run from a cell once it is small, and every converged root is a real
// crossing, so the lowest root found is an upper bound of the answer and the search
// stops when no cell's bound is below it less 1e-9 mm (the answer is within 1e-9 mm of
// the least crossing). A cell that shrinks to B < 1e-10 mm without a root is a
// near-crossing (the line passes within 1e-10 mm of an edge point): its centre's height
// is taken and it is counted in ToothStats.
#pragma once

#include "base/vec3.h"
#include "sweep/cutter.h"

namespace scallop {
namespace ref {

// One move as the definition sees it: tip straight from p0 to p1, axis slerp from a0
// to a1 (unit), spindle angle phi(t) = phaseStart + phaseRate t (radians).
struct ToothMove {
  Vec3 p0, p1, a0, a1;
  double phaseStart = 0, phaseRate = 0;
  bool counterClockwise = false;  // M4
};

// The meridian profile point at arc length u (clamped to [0, edgeLength]).
struct EdgeSpot {
  double rho = 0, h = 0;
};
double edgeLength(const Cutter& c);
EdgeSpot edgeSpot(const Cutter& c, double u);

// Tooth k's edge point at arc length u and time t, in the world.
Vec3 toothEdgePoint(const Cutter& c, const ToothMove& m, int k, double u, double t);

struct ToothHit {
  bool hit = false;
  double z = 0;  // mm
  double t = 0, u = 0;
  int tooth = -1;
};

struct ToothStats {
  long cells = 0;          // cells evaluated
  long newtonRoots = 0;    // converged Newton solves
  long nearCrossings = 0;  // cells down to B < 1e-10 mm without a root (see above)
};

// The lowest point on the vertical line (x, y) that an edge of the move passes through.
ToothHit toothLowest(const Cutter& c, const ToothMove& m, double x, double y,
                     ToothStats* stats = nullptr);

// A second, plain method for checking the first: every tooth on a uniform grid of
// `nu` x `nt` (u, t) samples, Newton from every grid point that is a local minimum of
// |P.xy - (x, y)| and within `near` mm of the line. Slow; for small cases only.
ToothHit toothLowestDense(const Cutter& c, const ToothMove& m, double x, double y, int nu, int nt,
                          double near);

}  // namespace ref
}  // namespace scallop
