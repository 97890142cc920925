// Drop-cutter: how low a vertical cutter at (x, y) can go before it touches a
// triangle mesh, the way CAM kernels (OpenCAMLib's drop-cutter) compute 3-axis
// cutter locations. An independent reference for the simulation's gouge reports: it
// shares nothing with the swept-solid code (sweep/swept_segment.h).
//
// With the tip at (x, y, z) a mesh point p at horizontal distance d <= R from the
// axis touches the cutter when z = p.z - h(d), h being the cutter's lower profile
//     h(d) = 0                                  d <= Rb = R - r  (flat bottom)
//     h(d) = r - sqrt(r^2 - (d - Rb)^2)         Rb < d <= R      (corner / ball)
// so the contact height is the maximum of p.z - h(d(p)) over the mesh. On one triangle
// this function is concave (p.z is linear, h increasing and convex, d convex), so its
// maximum is either the facet case (the point where the triangle's plane touches the
// cutter, closed form: the cutter point with normal -n) or lies on an edge (a 1-D
// concave maximum, found by bisection on the derivative; vertices are edge ends).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "analysis/triangle_mesh.h"
#include "sweep/cutter.h"

namespace scallop {

struct DropContact {
  bool hit = false;  // false: no mesh point within R of the axis
  double tipZ = 0;   // highest tip height touching the mesh, mm
  Vec3 point;        // the contact point on the mesh
};

// The contact of a vertical cutter at (x, y) with one triangle.
DropContact dropOnTriangle(const Cutter& cutter, const std::array<Vec3, 3>& triangle, double x,
                           double y);

// Drop-cutter over a whole mesh, with its own uniform xy buckets of triangles.
// Thread-safe for queries.
class DropCutter {
 public:
  DropCutter(const Cutter& cutter, const TriangleMesh& mesh);
  DropContact drop(double x, double y) const;

 private:
  Cutter cutter_;
  const TriangleMesh& mesh_;
  std::vector<double> topZ_;  // per triangle: highest vertex, bounds its contact
  double x0_ = 0, y0_ = 0, cell_ = 1;
  int64_t nx_ = 0, ny_ = 0;
  std::vector<std::vector<uint32_t>> buckets_;
};

}  // namespace scallop
