// Random cases shared by the tests: cutter shapes and 5-axis machine moves drawn from a
// caller's seeded std::mt19937_64, always in the same order, so a test that switches to
// these draws the very cases it drew before. Curves come with their tip and axis as
// CONVENTIONS.md writes them (tests/sweep/machine_reference.h), not PoseCurve's code.
#pragma once

#include <functional>
#include <random>
#include <string>

#include "base/vec3.h"
#include "sweep/cutter.h"
#include "sweep/pose.h"
#include "sweep/pose_curve.h"

namespace scallop::test {

// A cutter's shape, for Cutter::make and the brute-force reference's makeRefCutter alike.
struct CutterShape {
  CutterType type = CutterType::Ball;
  double radius = 0, cornerRadius = 0, fluteLength = 0;  // mm
};

// Ball, flat, bull by k % 3; radius in [1, 5) mm, a bull's corner 0.15 to 0.85 of it,
// flutes 2 to 5 radii long. Draws 2 numbers (3 for a bull) in [0, 1).
CutterShape randomCutterShape(std::mt19937_64& rng, int k);

// The ranges of a random table-table machine and TCP-off move: each value is its scale
// times a draw in [-1, 1), a step is added to the start.
struct MachineMoveRanges {
  double pivot;                           // each coordinate, mm
  double offsetXY, offsetZ0, offsetZ;     // offset {xy, xy, z0 + z}, mm
  double tilt, tiltStep, spin, spinStep;  // rad
  double joints, jointStep;               // each machine axis, mm
};

struct MachineMove {
  TableMachine machine;
  RotaryMotion motion;  // tcp = false
};

// Draws 15 numbers: pivot, offset, tilt0, tilt1, spin0, spin1, joints0, joints1.
MachineMove randomMachineMove(std::mt19937_64& rng, RotaryKinematics kinematics,
                              const MachineMoveRanges& ranges);

// A pose curve with its tip and axis at t as the conventions write them.
struct CheckedCurve {
  std::string name;
  PoseCurve curve;
  std::function<Vec3(double)> tip, axis;
};

// PoseCurve::jointLinear of `move`; the tip follows trtfuncs' forward kinematics.
CheckedCurve jointLinearCurve(const std::string& name, const MachineMove& move);

// A TCP-on rotary move: tilt0 = tilt u, spin0 = spin u, each end moved by its step times
// u unless `tiltStands` / `spinStands`; tips {u, u, u} to {2u, 2u, u} (u in [-1, 1)).
struct RotaryRanges {
  double tilt, tiltStep, spin, spinStep;  // rad
  bool tiltStands = false, spinStands = false;
};
CheckedCurve randomRotaryCurve(const std::string& name, std::mt19937_64& rng,
                               RotaryKinematics kinematics, const RotaryRanges& ranges);

}  // namespace scallop::test
