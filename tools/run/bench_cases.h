// The standard benchmark cases of `scallop bench` (B1, B2, B3), built as plain jobs so
// that the benchmark runs exactly what `simulate` would run.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/vec3.h"
#include "raycast/zmap.h"
#include "sweep/cutter.h"
#include "sweep/cutting_model.h"
#include "sweep/pose.h"
#include "sweep/tool_path_sweep.h"

namespace scallop {

struct BenchCase {
  std::string name;         // "B1", "B2", "B3", "B3c", "B4", "B5", "B6", "B7", "B8", "B9"
  std::string description;  // one line for people
  Cutter cutter;
  Box3 stock;
  GridSpec grid;
  ToolPath path;
  CuttingModel cutting;  // B5, B8: teeth; the others: the envelope
};

struct BenchCaseOptions {
  bool quick = false;  // 10x coarser grid spacing (100x fewer cells)
  double area = 0;     // > 0: a square stock of this side, mm, instead of 20 x 20 mm
};

// "B1", "B2", "B3", "B3c", "B4", "B5", "B6", "B7", "B8", "B9" in the order they are
// reported.
const std::vector<std::string>& benchCaseNames();
// The cases a bench without --case runs: B1 to B5 (B6 and B7, the general-profile
// cutters, B8, the face mill, and B9, 10^6 moves, run only when asked for: CI's quick
// bench keeps its time).
const std::vector<std::string>& defaultBenchCaseNames();

// Throws InputError (field "--case" / "--area") for an unknown name or a bad area.
//  B1: stock 20 x 20 mm, bull R = 3, r = 1, lead 5 deg, step-over 0.8 mm, depth 0.5 mm,
//      one move per pass, spacing 1 um (4e8 cells).
//  B2: B1 with every pass cut into 0.05 mm moves.
//  B3: freeform 5-axis as CAM writes it (freeformClText through the CL-text reader:
//      the axis turns inside every move); spacing 2 um (1e8 cells).
//  B3c: B3's tips with one axis per move (makeFreeformPath), as before turning moves
//      were swept exactly.
//  B4: the mount_rush ball-nose drop-cutter path (real 3-axis CAM output,
//      tests/data/mount_rush) over its stock at 0.01 mm. Throws InputError naming the
//      file when the data folder is not there (an installed binary without sources).
//  B5: B1 with the teeth cutting model (2 flutes, fz 0.1 mm, phase 0). With `quick`
//      its stock is a 4 mm square (or --area's, if smaller): the teeth cost about
//      100 times the envelope a cell, and the quick bench runs in CI.
//  B6: B3's freeform path (lead 5 deg, the axis turning inside every move) with a taper
//      barrel (form radius 250 mm, tip radius 2 mm, taper 10 deg, reference diameter
//      8 mm, flute length 20 mm), its passes as far apart as leaves the scallop of B3's
//      bull at 0.5 mm on a plane at that lead (analysis/pass_section.h); 2 um.
//  B7: B1's raster with a tapered ball (tip radius 1 mm, taper 5 deg per side, flute
//      length 12 mm); 1 um.
//  B8: surf-topo's face-milling case A2 (b8FaceMill in the .cpp): a face mill
//      with two round inserts (bull R 10, r 5, edge_span the corner arc), the second
//      insert 26 um nearer the axis and 9 um higher, fz 0.4 mm, ap 0.4 mm, CCW, one pass
//      along +y at x = 5 over a 5 x 5 mm stock (--area A: A x A) at 25 um (4e4 cells).
//  B9: a program of 10^6 moves: ball R1 finishing a 100 x 50 mm stock (--area A:
//      A x A/2 mm), passes along X 0.1 mm apart with a point every 0.05 mm on
//      finishingHeight, written by finishingGcode and read through the G-code reader;
//      spacing 20 um (1.25e7 cells).
BenchCase makeBenchCase(const std::string& name, const BenchCaseOptions& options);

// The freeform 5-axis finishing path of B3 and B3c: passes along +X, `passGap` mm apart
// in Y (from stock.min.y while <= stock.max.y), each from a cutter radius + 1 mm before
// the stock to as far past it, with a CL point every `pointGap` mm on the surface
//     z(x, y) = 0.5 sin(2 pi x / 10) cos(2 pi y / 14)   (mm)
// and the unit surface normal leaned `leanDeg` towards the feed (rotated in the plane of
// the normal and the feed) as the tool axis.
//  - freeformClText: the path as CAM writes it, CL text "x y z i j k" with the axis of
//    every CL point (6 and 9 decimals), a blank line between passes. Read back through
//    the CL-text reader, the axis turns inside every move (~0.01 rad per 0.05 mm).
//  - makeFreeformPath: the same tips with one axis per move, the normal at its
//    midpoint (B3c, the constant-axis version kept for comparison): the axis jumps at
//    every CL point and each move end leaves its own dimple.
std::string freeformClText(const Cutter& cutter, const Box3& stock, double passGap, double pointGap,
                           double leanDeg);
ToolPath makeFreeformPath(const Cutter& cutter, const Box3& stock, double passGap,
                          double moveLength, double leanDeg);
double freeformHeight(double x, double y);

// B9's surface, z = 0.3 sin(x / 3) sin(y / 4) - 0.5 (mm), and its program as G-code text:
// passes along +X, `passGap` mm apart in Y over the stock, each from a cutter radius + 1
// mm before the stock to as far past it, a G1 every `pointGap` mm with the tip on the
// surface (4 decimals), and rapids over the stock between passes.
double finishingHeight(double x, double y);
std::string finishingGcode(const Cutter& cutter, const Box3& stock, double passGap,
                           double pointGap);

// The stamping baseline's window: a square of side `side` mm (at most the stock)
// centred on the stock, with the case's grid spacing.
GridSpec stampWindow(const BenchCase& bench, double side);

// FNV-1a over the bit patterns of the heights, in storage order: equal hashes mean
// the same heights bit for bit (for the bench's own checks and the tests).
uint64_t heightsHash(const ZMap& map);

}  // namespace scallop
