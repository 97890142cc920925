// RimContact: where a turning bull or ball cutter's swept solid is lowest on a vertical
// line, located by Newton's method over the move's parameter t and the angle phi round
// the cutter's rim: one small smooth problem instead of a search over t of stationary
// lowest points. It only locates: the height it returns is a real point of the swept
// solid, and the caller proves it is the lowest to 1e-9 mm (ray_clearance.h) or falls
// back to the certified search (swept_move.cpp). Derivation in rim_contact.cpp.
#pragma once

#include "sweep/cutter.h"
#include "sweep/pose_curve.h"
#include "sweep/vec3.h"

namespace scallop {

struct RimContact {
  bool found = false;  // false: Newton left its safe region; nothing below is set
  double t = 0;        // pose parameter of the contact, in [0, 1]
  double z = 0;        // mm: the height of the point (x, y, z), which lies in K(t)
  Vec3 normal;         // outward unit normal of K(t) there, normal.z < 0
  PoseFrame pose;      // the pose at t (for the proof that follows)
  int iterations = 0;  // Newton steps taken
};

// Locates the lowest point over t in [0, 1] of the spheres of radius r round the rim
// circle of K(t) on the vertical line through (x, y), from the start t0 (phi starts where
// the line crosses the rim's plane). Needs cornerRadius > 0.
RimContact locateRimContact(const Cutter& cutter, const PoseCurve& curve, double x, double y,
                            double t0);

}  // namespace scallop
