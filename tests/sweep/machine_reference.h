// The table-table machines of CONVENTIONS.md "Machines" as the tests write them, apart
// from the project's own PoseCurve: LinuxCNC's trtfuncs forward kinematics term by term
// and the convention's axis formulas. Used by tests/sweep/pose_curve_test.cpp and the
// brute-force sweeps of machine moves (tests/sweep/tcp_off_sweep_test.cpp).
#pragma once

#include <cmath>

#include "sweep/pose.h"
#include "base/vec3.h"

namespace scallop {

// xyzbcKinematicsForward / xyzacKinematicsForward as trtfuncs.c writes them (offsets
// x/y/z, the z offset including the tool offset), angles in radians.
inline Vec3 trtForward(const TableMachine& m, const Vec3& j, double tilt, double c) {
  const double xr = m.pivot.x, yr = m.pivot.y, zr = m.pivot.z;
  const double dx = m.offset.x, dy = m.offset.y, dz = m.offset.z;
  const double sc = std::sin(c), cc = std::cos(c), st = std::sin(tilt), ct = std::cos(tilt);
  if (m.kinematics == RotaryKinematics::TableBC)
    return {cc * ct * (j.x - dx - xr) + sc * (j.y - yr) - cc * st * (j.z - dz - zr) + cc * dx + xr,
            -sc * ct * (j.x - dx - xr) + cc * (j.y - yr) + sc * st * (j.z - dz - zr) - sc * dx + yr,
            st * (j.x - dx - xr) + ct * (j.z - dz - zr) + dz + zr};
  return {cc * (j.x - xr) + sc * ct * (j.y - dy - yr) + sc * st * (j.z - dz - zr) + sc * dy + xr,
          -sc * (j.x - xr) + cc * ct * (j.y - dy - yr) + cc * st * (j.z - dz - zr) + cc * dy + yr,
          -st * (j.y - dy - yr) + ct * (j.z - dz - zr) + dz + zr};
}

// CONVENTIONS.md "Machines": the tool axis in the part frame.
inline Vec3 conventionAxis(RotaryKinematics k, double tilt, double c) {
  if (k == RotaryKinematics::TableBC)
    return {-std::cos(c) * std::sin(tilt), std::sin(c) * std::sin(tilt), std::cos(tilt)};
  return {std::sin(c) * std::sin(tilt), std::cos(c) * std::sin(tilt), std::cos(tilt)};
}

}  // namespace scallop
