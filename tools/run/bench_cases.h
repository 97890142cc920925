// The standard benchmark cases of `scallop bench` (B1, B2, B3), built as plain jobs so
// that the benchmark runs exactly what `simulate` would run.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "raycast/zmap.h"
#include "sweep/cutter.h"
#include "sweep/pose.h"
#include "sweep/tool_path_sweep.h"
#include "sweep/vec3.h"

namespace scallop {

struct BenchCase {
  std::string name;         // "B1", "B2", "B3"
  std::string description;  // one line for people
  Cutter cutter;
  Box3 stock;
  GridSpec grid;
  ToolPath path;
};

struct BenchCaseOptions {
  bool quick = false;  // 10x coarser grid spacing (100x fewer cells)
  double area = 0;     // > 0: a square stock of this side, mm, instead of 20 x 20 mm
};

// "B1", "B2", "B3" in the order they are reported.
const std::vector<std::string>& benchCaseNames();

// Throws InputError (field "--case" / "--area") for an unknown name or a bad area.
//  B1: stock 20 x 20 mm, bull R = 3, r = 1, lead 5 deg, step-over 0.8 mm, depth 0.5 mm,
//      one move per pass, spacing 1 um (4e8 cells).
//  B2: B1 with every pass cut into 0.05 mm moves.
//  B3: freeform 5-axis, see makeFreeformPath; spacing 2 um (1e8 cells).
BenchCase makeBenchCase(const std::string& name, const BenchCaseOptions& options);

// B3's tool path: passes along +X, `passGap` mm apart in Y (from stock.min.y while
// <= stock.max.y), each from a cutter radius + 1 mm before the stock to as far past it,
// cut into moves of `moveLength` mm whose tips lie on the surface
//     z(x, y) = 0.5 sin(2 pi x / 10) cos(2 pi y / 14)   (mm),
// as the performance issue states ("the tip follows z = ..."). Each move holds one
// axis: the unit surface normal at its midpoint leaned `leanDeg` towards the feed
// (rotated in the plane of the normal and the feed), so the axis turns by ~0.01 rad
// between moves and the cutter's toe, 2 mm from the tip, steps by ~0.02 mm in z there:
// every move end leaves its own dimple, and most cells are cut by a cutter standing
// at a move end rather than by a move's envelope. That is the true swept solid of
// this path. Why not interpolate the axis inside each move: sweepToolPath would split
// every 0.05 mm move into ~600 constant-axis pieces at the 1e-4 mm tolerance
// (0.01 rad x 12.4 mm reach of the flutes), ~1.4e7 segments for the 20 x 20 mm stock,
// which no scene fits in memory. (An earlier version placed the tips so that the
// cutter touched the surface at both move ends; under a 5 deg lean the flat bottom's
// contact point swings around the rim with the normal, so each 0.05 mm move also
// moved ~0.15 mm sideways and jumped back: not moves along X.)
ToolPath makeFreeformPath(const Cutter& cutter, const Box3& stock, double passGap,
                          double moveLength, double leanDeg);
double freeformHeight(double x, double y);

// The stamping baseline's window: a square of side `side` mm (at most the stock)
// centred on the stock, with the case's grid spacing.
GridSpec stampWindow(const BenchCase& bench, double side);

// FNV-1a over the bit patterns of the heights, in storage order: equal hashes mean
// the same heights bit for bit (for the bench's own checks and the tests).
uint64_t heightsHash(const ZMap& map);

}  // namespace scallop
