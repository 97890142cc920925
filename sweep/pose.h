// Pose and Move: where the cutter is (APT CL convention, CONVENTIONS.md "Tool pose"),
// and what a tool path holds besides its moves: the cutters of a multi-tool program
// (CONVENTIONS.md "Tools"), the rotary motion of a 5-axis machine ("Machines") and
// the arcs of G-code (G2/G3).
#pragma once

#include <cstdint>
#include <vector>

#include "base/vec3.h"
#include "sweep/cutter.h"

namespace scallop {

struct Pose {
  Vec3 tip;   // centre of the cutter's bottom on its axis, mm
  Vec3 axis;  // unit vector from the tip towards the shank
};

enum class RotaryKinematics : uint8_t { TableBC, TableAC };  // xyzbc-trt, xyzac-trt

// A table-table machine's geometry as LinuxCNC's trtfuncs take it (its HAL pins
// x/y/z-rot-point, x/y/z-offset; the z offset includes the tool offset). Only moves
// with TCP off use it: the tip in the part frame is then the forward kinematics of the
// joints (PoseCurve::jointLinear).
struct TableMachine {
  RotaryKinematics kinematics = RotaryKinematics::TableBC;
  Vec3 pivot;   // rotation point, mm
  Vec3 offset;  // xyzbc-trt uses x and z, xyzac-trt y and z, mm
};

// The rotary motion of one move of a 5-axis machine: the tilt (B or A) and spin (C)
// angles at both ends, radians, linear in t. With TCP on the move's tips are the tool
// tip (linear in t); with TCP off the joints X Y Z move linearly from joints0 to
// joints1 and the tip follows the machine's forward kinematics.
struct RotaryMotion {
  double tilt0 = 0, tilt1 = 0, spin0 = 0, spin1 = 0;
  bool tcp = true;
  Vec3 joints0, joints1;  // TCP off: machine X Y Z at both ends, mm
};

// The tip's motion of a G-code arc (G2/G3) with a constant tool axis: a circle, or a
// helix rising along the plane's normal n = u x v,
//     tip(t) = centre + rho(t) (cos theta(t) u + sin theta(t) v) + rise t n,
//     theta(t) = angle0 + sweep t,   rho(t) = radius0 + (radius1 - radius0) t,
// with u, v the plane's unit axes (G17: x, y; G18: z, x; G19: y, z). The radii may
// differ by the 0.002 mm G-code allows (a spiral, as LinuxCNC interpolates it); a full
// circle sweeps 2 pi.
struct ArcMotion {
  Vec3 centre;                      // mm, at the start's height along n
  Vec3 u, v;                        // unit and orthogonal
  double angle0 = 0, sweep = 0;     // rad; sweep > 0 turns counter-clockwise about n (G3)
  double radius0 = 0, radius1 = 0;  // mm, > 0
  double rise = 0;                  // mm along n over the move
  Vec3 at(double t) const;          // tip(t) above
  // A box holding every tip(t): the whole circle's cylinder, rise included.
  Box3 bounds() const;
};

// One move: the tip goes straight from `from.tip` to `to.tip`; the axis is
// interpolated (slerp) when the two axes differ, unless the move is a machine's rotary
// motion (`rotary` > 0: ToolPath::rotary[rotary - 1] gives the pose curve) or an arc
// (`arc` > 0: its tip follows ToolPath::arcs[arc - 1], the axis stays from.axis). Rapids
// never touch the stock and are not simulated. `tool` indexes ToolPath::cutters.
struct Move {
  Pose from;
  Pose to;
  bool rapid = false;
  uint16_t tool = 0;
  uint32_t rotary = 0;
  uint32_t arc = 0;
  // Feed per tooth of this move, mm (G-code: F / (S flutes)); 0: the job's
  // cutting.feed_per_tooth. Read by the "teeth" cutting model only.
  double feedPerTooth = 0;
  // The spindle's direction for the teeth model: 0 the job's (CuttingModel), 1
  // clockwise (G-code M3), -1 counter-clockwise (M4).
  int8_t spindle = 0;
};

struct ToolPath {
  std::vector<Move> moves;
  // The cutters the moves' `tool` indices name (a multi-tool program); empty: every
  // move cuts with the one cutter the sweep is given.
  std::vector<Cutter> cutters;
  // Rotary motions of a 5-axis machine's moves (Move::rotary), and the machine.
  std::vector<RotaryMotion> rotary;
  TableMachine machine;
  // The arcs of the moves that follow one (Move::arc).
  std::vector<ArcMotion> arcs;
  // The teeth model's spindle angle (rad) at the start of moves whose predecessors in the
  // program were left out (a reader keeping only the moves that can reach the grid,
  // tools/io/move_window.h), sorted by move: the sweep takes it there instead of carrying
  // its own across the gap, so the phase is the whole program's.
  struct PhaseMark {
    size_t move;
    double phase;
  };
  std::vector<PhaseMark> phaseMarks;
  size_t cuttingMoves() const;
  // The path of move k alone, with its cutter and machine motion (for sweeping one
  // move apart from the others).
  ToolPath single(size_t k) const;
};

}  // namespace scallop
