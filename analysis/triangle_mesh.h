// TriangleMesh and MeshIndex: the faceted surface of seed 004 ("Each test surface
// model ... contains (1) the coordinates of the triangle vertices; (2) the group of
// vertex coordinates ...; (3) the normal vector of each triangle", §2) and an Embree
// BVH over it.
//
// The seed indexes facets with hand-written buckets (§2.1, Figure 4); scallop asks
// Embree instead: rtcPointQuery returns every triangle whose (float) bounding box
// meets a query sphere, and a top-down ray finds the upper envelope of the mesh.
// Embree only culls: every distance and height that reaches a result is recomputed in
// double from the triangle's vertices (CONVENTIONS.md "Units and frames").
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "base/vec3.h"

namespace scallop {

struct TriangleMesh {
  std::vector<Vec3> vertices;                      // welded: each position once, mm
  std::vector<std::array<uint32_t, 3>> triangles;  // counter-clockwise about `normals`
  std::vector<Vec3> normals;                       // unit facet normals, one per triangle

  Box3 bounds() const;
  std::array<Vec3, 3> corners(size_t t) const {
    const auto& f = triangles[t];
    return {vertices[f[0]], vertices[f[1]], vertices[f[2]]};
  }
};

// What building a mesh from a triangle soup changed (documented repairs).
struct MeshRepairs {
  size_t inputTriangles = 0;
  size_t degenerateDropped = 0;         // zero area (after welding), not used
  std::vector<size_t> firstDegenerate;  // 1-based input numbers, at most 10
  size_t flippedUp = 0;                 // facets turned over by orientNormalsUp
};

// Welds exactly equal positions (STL stores each vertex once per facet) and computes
// each normal from the winding, (b - a) x (c - a). Facets whose normal has zero length
// after welding are dropped and counted in `repairs`.
TriangleMesh meshFromTriangles(const std::vector<std::array<Vec3, 3>>& soup,
                               MeshRepairs* repairs = nullptr);

// Turns every facet with a downward normal over (normal.z < 0), so that a surface
// milled from above has its normals on the tool side whatever the file's winding.
// Returns how many facets were turned. Vertical facets (normal.z == 0) are kept.
size_t orientNormalsUp(TriangleMesh& mesh);

// Embree BVH over a mesh's triangles. Thread-safe for queries.
class MeshIndex {
 public:
  explicit MeshIndex(const TriangleMesh& mesh);
  ~MeshIndex();
  MeshIndex(const MeshIndex&) = delete;
  MeshIndex& operator=(const MeshIndex&) = delete;

  const TriangleMesh& mesh() const { return mesh_; }

  // Every triangle whose bounds meet the ball (centre, radius), sorted and unique, in
  // `out` (cleared first). A superset of the triangles within `radius` of `centre`:
  // the radius is widened by the float rounding of Embree's boxes.
  void trianglesNear(const Vec3& centre, double radius, std::vector<uint32_t>& out) const;

  // The highest point of the mesh on the vertical line through (x, y): true and its
  // height `z` (double, from the triangle's plane at exactly (x, y)) and `triangle`,
  // or false if the line misses the mesh.
  bool topHeight(double x, double y, double& z, uint32_t& triangle) const;

 private:
  struct Impl;
  const TriangleMesh& mesh_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace scallop
