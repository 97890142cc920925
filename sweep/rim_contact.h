// RimContact: where a turning bull or ball cutter's swept solid is lowest on a vertical
// line, located by Newton's method over the move's parameter t and the angle phi round
// the cutter's rim: one small smooth problem instead of a search over t of stationary
// lowest points. It only locates: the height it returns is a real point of the swept
// solid, and the caller proves it is the lowest to 1e-9 mm (ray_clearance.h) or falls
// back to the certified search (certified_search.h). Derivation in rim_contact.cpp.
#pragma once

#include "sweep/cutter.h"
#include "sweep/pose_curve.h"
#include "base/vec3.h"

namespace scallop {

// Where Newton's method starts: t, and the rim direction (cos phi, sin phi) in the
// cutter's turning frame (PoseFrame e1, e2) when one is known; otherwise the direction
// towards the point where the line crosses the rim's plane.
struct RimStart {
  double t = 0.5;
  bool hasDirection = false;
  double cosPhi = 1, sinPhi = 0;
};

struct RimContact {
  bool found = false;             // false: Newton left its safe region; nothing below is set
  double t = 0;                   // pose parameter of the contact, in [0, 1]
  double z = 0;                   // mm: the height of the point (x, y, z), which lies in K(t)
  double cosPhi = 1, sinPhi = 0;  // the rim point's direction in the turning frame
  Vec3 normal;                    // outward unit normal of K(t) there, normal.z < 0
  PoseFrame pose;                 // the pose at t (for the proof that follows)
  int iterations = 0;             // Newton steps taken
};

// How a found contact moves with the line: the derivatives of its t and phi with
// respect to the line's x and y (per mm), from the implicit function theorem at the
// minimum (rim_contact.cpp). Where the contact sits at a move's end, they and the
// step (tBeyond, phiBeyond) are those of the minimum of g's smooth extension past the
// end, one unconstrained Newton step away: a start blended from knots on both sides of
// the end then lands near the contact instead of dragged towards the end.
struct RimSensitivity {
  double dtdx = 0, dtdy = 0, dphidx = 0, dphidy = 0;
  double tBeyond = 0, phiBeyond = 0;  // 0 for a contact inside the move
};

// Locates the lowest point over t in [0, 1] of the spheres of radius r round the rim
// circle of K(t) on the vertical line through (x, y), from `start`. Needs
// cornerRadius > 0. `sensitivity`, if given, is set where a contact is found.
RimContact locateRimContact(const Cutter& cutter, const PoseCurve& curve, double x, double y,
                            const RimStart& start = {}, RimSensitivity* sensitivity = nullptr);

}  // namespace scallop
