// Arcs of G-code (G2/G3): the geometry of the G-code reader (tools/io/gcode_reader.h),
// apart from its words. An arc is one move whose tip follows it (resolveArc), or, as
// the --arc-chords baseline, chords within a tolerance (arcChords).
//
// An arc lies in the plane G17 (XY), G18 (ZX) or G19 (YZ); the third axis moves
// linearly (a helix). Its centre is given by I/J/K offsets (from the start, or
// absolute with G90.1) or by a radius R (R < 0: the long way round). The chords' ends
// lie on the arc (the radius interpolated between the start and end radii, which may
// differ by kArcRadiusSlack) and no chord strays from it by more than the tolerance.
#pragma once

#include <string>
#include <vector>

#include "base/vec3.h"
#include "sweep/pose.h"

namespace scallop {

// Start and end radii of an arc may differ by this much (mm) before it is an error;
// LinuxCNC uses the same bound.
constexpr double kArcRadiusSlack = 0.002;

struct ArcSpec {
  Vec3 start, end;   // mm
  int plane = 17;    // 17, 18 or 19
  bool ccw = false;  // G3
  bool hasRadius = false;
  double radius = 0;  // mm, when hasRadius
  // The centre in the plane's (u, v) coordinates when !hasRadius, mm (absolute).
  double centreU = 0, centreV = 0;
};

// The in-plane coordinates of the plane: (u, v, normal) axis indices 0 = x, 1 = y, 2 = z.
void arcPlaneAxes(int plane, int& u, int& v, int& w);

// The arc as the tip's motion of one move (pose.h ArcMotion): its centre, the plane's
// axes, the start angle, the signed sweep (a full circle, start = end with I/J/K, is
// 2 pi), the radii at both ends and the rise along the normal. Throws InputError(where)
// for an R too small for the chord, an R arc whose start is its end, radii that
// differ by more than kArcRadiusSlack, or a zero radius.
ArcMotion resolveArc(const ArcSpec& arc, const std::string& where);

// The chord ends from the first one after the start to `end` itself (exactly), each
// the resolved arc's point at t = k / n. Throws as resolveArc does, or for more than a
// million chords.
std::vector<Vec3> arcChords(const ArcSpec& arc, double tolerance, const std::string& where);

}  // namespace scallop
