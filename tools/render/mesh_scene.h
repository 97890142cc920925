// MeshScene: a triangle mesh (a design surface) in Embree for the rays of a picture
// (tools/render/deviation_view_png.h): the first facet along a ray, and whether a shadow
// ray meets any. Embree's BVH is built on one thread, so the same mesh gives the same
// BVH, and the same hits, whatever the thread count.
#pragma once

#include <cstdint>
#include <memory>

#include "analysis/triangle_mesh.h"

namespace scallop {

struct MeshHit {
  double t = HUGE_VAL;
  int64_t triangle = -1;
  double b1 = 0, b2 = 0;  // barycentric weights of corners 1 and 2
  bool found() const { return triangle >= 0; }
};

class MeshScene {
 public:
  explicit MeshScene(const TriangleMesh& mesh);
  ~MeshScene();
  MeshScene(const MeshScene&) = delete;
  MeshScene& operator=(const MeshScene&) = delete;

  // The first facet the ray o + t d meets for t in [tNear, tFar].
  MeshHit intersect(const Vec3& o, const Vec3& d, double tNear, double tFar) const;
  bool occluded(const Vec3& o, const Vec3& d, double tNear, double tFar) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace scallop
