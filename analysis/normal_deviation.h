// Normal deviation on a design surface (CONVENTIONS.md "Normal deviation on a design
// surface"): at every design vertex, the height w along its outward normal of the
// machined surface on the line through the vertex, as a one-cell frame
// (raycast/grid_frame.h) with its origin at the vertex and `depth` the gouge depth.
//
// Exact like every height: each move that can reach the line is moved into the line's
// frame (a rotation taking the normal to +Z) and asked for the lowest point of its swept
// solid on the vertical line there, by the same kernel as the z-map (SweptMove). Which
// moves can reach a line is decided by proven bounds only: the move's box and its
// support function (SweptMove::support) in the four directions across the line and
// along it; the moves left are visited in the order of their lower bounds along the
// line and the visit stops at the first that cannot beat the lowest point found.
#pragma once

#include <cstdint>
#include <vector>

#include "analysis/triangle_mesh.h"
#include "sweep/cutter.h"
#include "sweep/pose.h"

namespace scallop {

enum class VertexDeviation : uint8_t {
  kMeasured,    // a height of the machined surface (or the stock's boundary)
  kCutThrough,  // cut below -gouge depth: holds -gouge depth
  kNoMaterial,  // the line misses the stock (or meets it only below -gouge depth): NaN
  kUnresolved,  // a move that can reach the line points its axis away from the normal
                // (k < 0 in the line's frame), or the vertex has no normal: NaN
};

struct NormalDeviation {
  std::vector<Vec3> normals;      // per vertex, unit (zero: none)
  std::vector<double> deviation;  // per vertex, mm; NaN unless measured or cut through
  std::vector<VertexDeviation> status;
  // Per vertex, the index in path.moves of the move whose swept solid made its value
  // (the first in the visit's order to reach the lowest point); -1 where the value is
  // the stock's surface or there is none.
  std::vector<int64_t> lowestMove;
  int64_t cutThrough = 0, noMaterial = 0, unresolved = 0;
  uint64_t candidates = 0;        // (vertex, move) pairs the bounds could not rule out
  uint64_t exactEvaluations = 0;  // of those, the ones the kernel was asked about
};

// The deviation of every vertex of `design` (facets wound counter-clockwise seen from
// outside; see requireConsistentOrientation) after `path` cut `stock` with `cutter`
// (path.cutters instead where the path has its own). Every cutting move is swept on
// its own. `gougeDepth` > 0 (mm). Rotary machine moves are not supported (their
// curves are machine angles of the part frame): the caller refuses them. Parallel over
// vertices; the result does not depend on the number of threads.
//
// The moves that can reach a line are found through an index of their boxes (an Embree
// BVH, rays along the lines; move_line_index.h) or, for tests, by trying every move: the
// deviations are the same bits either way.
enum class CandidateSearch { kIndexed, kAllMoves };
NormalDeviation normalDeviation(const Cutter& cutter, const ToolPath& path, const Box3& stock,
                                const TriangleMesh& design, double gougeDepth,
                                CandidateSearch search = CandidateSearch::kIndexed);

}  // namespace scallop
