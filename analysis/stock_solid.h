// StockSolid: a stock of any shape given as a closed triangulated solid (a turned or cast
// blank, CONVENTIONS.md "Stock"). Each cell of a z-map starts at the solid's highest exit
// on its vertical line: the top of the mesh there, computed in double from the facet's
// plane (MeshIndex::topHeight); a line that misses the solid holds no material.
#pragma once

#include <memory>
#include <string>

#include "analysis/triangle_mesh.h"
#include "raycast/zmap.h"

namespace scallop {

// Throws InputError naming `field` and the 1-based facet (or the edge's two vertices)
// unless every edge of `mesh` is shared by exactly two facets that run along it in
// opposite directions (a closed, consistently oriented surface).
void checkClosedSolid(const TriangleMesh& mesh, const std::string& field);

class StockSolid {
 public:
  explicit StockSolid(TriangleMesh mesh);

  const TriangleMesh& mesh() const { return mesh_; }
  Box3 bounds() const { return mesh_.bounds(); }

  // The solid's highest point on the vertical line through (x, y), mm; NaN if the line
  // misses it.
  double topAt(double x, double y) const;

  // Every cell of `map` set to topAt its centre, kNoMaterial (raycast/grid_frame.h)
  // where the line misses the solid.
  void fillHeights(ZMap& map) const;

  // Whether some point of the solid higher than `z` (mm) lies within horizontal
  // distance `reach` (mm) of the segment a-b seen from above (a, b's z ignored). Exact
  // in double: each facet is clipped to z > `z` and its distance to the segment in xy
  // computed, no sampling. `highest` receives the highest point of the solid within
  // `reach` of a-b (seen from above; its crossings with the reach's boundary found by
  // bisection to 1e-12 of a facet's edge): what a rapid there meets, and how high.
  bool reachesAbove(const Vec3& a, const Vec3& b, double reach, double z,
                    Vec3* highest = nullptr) const;

 private:
  TriangleMesh mesh_;
  std::unique_ptr<MeshIndex> index_;
};

}  // namespace scallop
