// The exactness hunt's cases: one adversarial move each, written as the job and path file
// a user would write (APT CL data or G-code through a machine), with the hunt's own model
// of its poses (hunt_reference.h) and a small window of cells where the move is hardest.
//
// Draws are weighted to the configurations random tests never meet: a move whose
// direction makes exactly or almost a right angle with the axis (d.a / |d| in {0, +-1e-9,
// +-1e-6, +-1e-4}: a flat end mill moving in its bottom plane), axes near vertical and
// near horizontal, moves shorter than a cell and longer than 10 R, and windows over the
// rim, the corner and the tip of the cutter at either end, on cells from 0.1 um to R / 8.
#pragma once

#include <cstdint>
#include <functional>
#include <utility>
#include <random>
#include <string>
#include <vector>

#include "hunt/hunt_reference.h"

namespace scallop::hunt {

enum class PathKind {
  kClStraight,   // APT MULTAX GOTO, one axis
  kClTurning,    // APT MULTAX GOTO, the axis turns (slerp)
  kTcpOn,        // G-code, xyzac-trt or xyzbc-trt, TCP on: tip straight, angles linear
  kTcpOff,       // G-code, TCP off: joints linear, the tip their forward kinematics
  kArc,          // G-code G2/G3 in XY (helical with a Z), axis fixed by A and C under TCP
};
inline constexpr int kPathKinds = 5;
const char* pathKindName(PathKind kind);

// One move as numbers: what the path file states.
struct MoveSpec {
  PathKind kind = PathKind::kClStraight;
  bool tableAC = true;            // machine kinds: xyzac-trt, else xyzbc-trt
  Vec3 p0, p1;                    // tips (CL, TCP on, arc ends) or joints (TCP off), mm
  Vec3 a0, a1;                    // CL axes (unit)
  double tilt0 = 0, tilt1 = 0;    // machine kinds: A or B, degrees
  double spin0 = 0, spin1 = 0;    // machine kinds: C, degrees
  Vec3 centre;                    // arc: centre (its z: the start's)
  double sweepDeg = 0;            // arc: signed sweep (positive: G3)
  bool split = false;             // CL straight: written as two moves meeting at the middle
};

struct HuntCase {
  std::string name;  // kind, cutter and draw, for the failure report
  MoveSpec move;
  HuntCutter cutter;
  std::string cutterJson;           // the job's "tool" object
  std::string machineJson;          // the job's "machine" object, or empty
  std::string pathText, pathName;   // the path file and its name (extension: format)
  std::vector<HuntCurve> curves;    // the cutting moves, as the reference sees them
  // The window: cells of side `spacing` (a power of two, so that every transform the
  // metamorphic checks make keeps the cells' centres exact) from (x0, y0).
  double x0 = 0, y0 = 0, spacing = 0;
  int nx = 0, ny = 0;
  double zBottom = 0, zTop = 0;  // the stock's box in z: below and above the move
};

// The job file of `c` (the stock is the window's box, the path file beside it).
std::string jobText(const HuntCase& c);
// Fills the path file, its name, the machine and the reference curves from c->move.
void writeMove(HuntCase* c);

// The case drawn from `rng` (its draws in a fixed order, so a seed is a reproducer).
HuntCase drawCase(std::mt19937_64& rng);

// The same move written differently, for the metamorphic checks: the cells of the
// variant at (i, j) are those of the original at mapCell(i, j). Kinds: "reversed", "split"
// (two moves meeting at the middle), "rotated" (90 degrees about Z), "mirrored" (x -> -x),
// "translated" (by whole cells) and "gcode" (a CL straight move as G-code through
// xyzac-trt with TCP on). Returns false where the variant does not apply to `c`.
struct Variant {
  HuntCase moved;
  // (i, j) of the variant -> (i, j) of the original.
  std::function<std::pair<int, int>(int, int)> mapCell;
};
bool makeVariant(const HuntCase& c, const std::string& kind, Variant* out);
inline const char* const kVariantKinds[] = {"reversed", "split",      "rotated",
                                            "mirrored", "translated", "gcode"};

}  // namespace scallop::hunt
