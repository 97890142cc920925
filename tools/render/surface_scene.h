// SurfaceScene: the surface of a SurfaceGrid (tools/render/height_surface.h) in Embree,
// for the primary and shadow rays of a 3-D picture.
//
// No triangle mesh and no Embree grid (whose float vertices would be three times the
// heights): the grid's patches are cut into tiles of kTilePatches x kTilePatches, each
// tile one primitive of an Embree user geometry whose bounds are the tile's footprint
// and its heights' range (a min/max box), so Embree's BVH over the tiles is a min/max
// hierarchy of the height field. Inside a tile the callbacks walk its patches along the
// ray and intersect each bilinear patch exactly (firstHitInTile), in double. The memory
// is the tiles' table and Embree's BVH over them: a few bytes per patch.
//
// Deterministic: a ray's hit is the first along it, ties broken by patch index, whatever
// the order Embree visits the tiles in or the thread that traces it.
#pragma once

#include <memory>

#include "tools/render/height_surface.h"

namespace scallop {

class SurfaceScene {
 public:
  static constexpr int kTilePatches = 16;

  // Builds Embree's BVH over the surface's tiles (the surface must outlive the scene
  // and keep its exaggeration). Throws InternalError on an Embree failure.
  explicit SurfaceScene(const SurfaceGrid& surface);
  ~SurfaceScene();
  SurfaceScene(const SurfaceScene&) = delete;
  SurfaceScene& operator=(const SurfaceScene&) = delete;

  // The first hit of the ray o + t d (world frame), t in [tNear, tFar].
  PatchHit intersect(const Vec3& o, const Vec3& d, double tNear, double tFar) const;
  // Whether the surface meets the ray for t in [tNear, tFar].
  bool occluded(const Vec3& o, const Vec3& d, double tNear, double tFar) const;

  const SurfaceGrid& surface() const { return surface_; }
  // Tiles with at least one patch drawn (Embree primitives).
  size_t tiles() const;

 private:
  struct Impl;
  const SurfaceGrid& surface_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace scallop
