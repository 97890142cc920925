// Exact gouge checking of peripheral-milling postures (the step 4), next to
// the vertex test of seed 004 §2.3 that it audits.
//
// Cylinder: the flat cutter's flute, radius R, axis segment from `tip` to
// tip + L * axis (CONVENTIONS.md "Cutters", "Tool pose").
//
// Penetration depth of a triangle into the cylinder, the definition used throughout:
//     depth = max over points p of the triangle with 0 <= s(p) <= L of (R - d(p)),
// clamped below at 0, where s(p) = (p - tip) . axis and d(p) is p's distance from
// the axis line: how far the surface reaches radially into the cutter. A surface
// tangent to the flank has depth 0; a vertex inside the cutter (the seed's test)
// gives depth >= R - d(vertex) > 0, but so does a facet interior or an edge that
// crosses the cutter with every vertex outside, which the vertex test cannot see.
// Penetration through the end faces alone (the triangle inside the slab only in a
// sliver) is measured the same way: only radial depth counts.
//
// The z-map check sweeps the accepted postures with the exact swept-solid machinery
// (raycast/simulation.h) and compares with the design surface ray-cast from above.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "analysis/triangle_mesh.h"
#include "raycast/zmap.h"
#include "sweep/cutter.h"
#include "sweep/pose.h"
#include "sweep/tool_path_sweep.h"

namespace scallop {

struct Cylinder {
  Vec3 tip;           // centre of the bottom disk, mm
  Vec3 axis;          // unit, tip -> shank
  double radius = 0;  // R, mm
  double length = 0;  // L, mm (the flute length)
};

// Seed 004 §2.3: the vertex lies inside the tool when 0 <= y_T <= `length` along the
// axis and its distance from the axis is below R by more than `tolerance` (mm), so
// that vertices on the flank's contact line (distance R up to round-off) are free.
bool vertexInside(const Vec3& v, const Cylinder& c, double tolerance);

// The exact penetration depth defined above, mm (>= 0). Closed form over the convex
// triangle clipped to the slab 0 <= s <= L: the distance from the axis is the norm of
// the radial part of p - tip, which is linear in p, so its minimum over the clipped
// polygon is 0 if the polygon's projection along the axis contains the axis, and
// otherwise the closest point of one of the projected edges.
double trianglePenetration(const std::array<Vec3, 3>& tri, const Cylinder& c);

struct Penetration {
  double depth = 0;       // mm, max over the candidates
  int64_t triangle = -1;  // the deepest triangle, -1 if depth == 0
};
Penetration cylinderPenetration(const TriangleMesh& mesh, const std::vector<uint32_t>& candidates,
                                const Cylinder& c);

// ---- Ray-cast gouge map -------------------------------------------------------------

struct GougeMapOptions {
  double tolerance = 1e-3;  // mm: machined below design by more than this is a gouge
  // Culling tile of the swept scene, mm; <= 0: R / 2. A flank cutter lies on its side,
  // so each swept segment covers about 2R x L: the simulate default (R / 8) would
  // give hundreds of tiles per segment.
  double tileSize = 0;
};

struct GougeMapStats {
  int64_t designCells = 0;     // cells where the mesh has a surface
  int64_t untouchedCells = 0;  // design cells the cutter never reaches
  int64_t overCutCells = 0;    // machined < design - tolerance (gouge)
  int64_t underCutCells = 0;   // reached, machined > design + tolerance (material left)
  double maxOverCut = 0;       // mm, vertical: largest design - machined over reached cells
  double meanOverCut = 0;      // mm, over the over-cut cells
  double maxUnderCut = 0;      // mm, largest machined - design over reached cells
  double meanUnderCut = 0;     // mm, over the under-cut cells
  size_t sweptSegments = 0;
};

struct GougeMap {
  ZMap design;    // upper envelope of the mesh at cell centres (NaN: no surface)
  ZMap machined;  // lowest swept height, or stockTop where untouched
  ZMap overCut;   // max(0, design - machined) where that exceeds the tolerance, else 0
  double stockTop = 0;
  GougeMapStats stats;
};

// Heights of the design surface (upper envelope, exact in double at every cell centre).
ZMap designHeights(const MeshIndex& index, const GridSpec& grid);

// Sweeps `path` with `cutter` over `grid` from a stock whose top is above the design
// surface and the cutter's reach, and compares with the design surface (vertical
// differences, as on any z-map).
GougeMap gougeMap(const MeshIndex& index, const Cutter& cutter, const ToolPath& path,
                  const GridSpec& grid, const GougeMapOptions& options = {});

}  // namespace scallop
