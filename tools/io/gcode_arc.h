// Arcs of G-code (G2/G3) cut into chords: the geometry of the G-code reader
// (tools/io/gcode_reader.h), apart from its words.
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

// The chord ends from the first one after the start to `end` itself (exactly).
// Throws InputError(where) for an R too small for the chord, radii that differ, a
// zero radius, or more than a million chords.
std::vector<Vec3> arcChords(const ArcSpec& arc, double tolerance, const std::string& where);

}  // namespace scallop
