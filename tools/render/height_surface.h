// The surface a 3-D picture traces (tools/render/surface_scene.h): heights at the nodes
// of a regular grid and, between each four neighbouring nodes, the bilinear patch
// through them,
//   z(u, v) = z00 (1 - u)(1 - v) + z10 u (1 - v) + z01 (1 - u) v + z11 u v,  u, v in [0, 1],
// continuous across patches (neighbours share an edge's two nodes). A patch with a node
// without height (NaN: no material) is left out, a hole in the surface.
//
// The nodes are a map's cell centres, or a coarser level of the map whose nodes are the
// means of k x k blocks of cells smoothed by [1 2 1] / 4 along x and y (mip-mapping with
// a prefilter): a picture traced from the level whose nodes are about a pixel apart does
// not alias marks finer than a pixel into moiré, and the surface it traces is a few
// pixels' worth of nodes however large the map.
//
// World frame (tools/render/render_camera.h): x, y as the map's, z = zScale (height -
// zOrigin), the height exaggerated about zOrigin.
#pragma once

#include <cstdint>
#include <vector>

#include "analysis/surface_metrology.h"
#include "base/vec3.h"
#include "raycast/zmap.h"

namespace scallop {

class SurfaceGrid {
 public:
  // The level of `region` of `map` with nodes the means of k x k blocks of cells (the
  // heights there that are not NaN; NaN when all are), then for k > 1 smoothed by
  // [1 2 1] / 4 along x and along y (NaN nodes left out), node (0, 0) the block at the
  // region's smallest x and y; the last fewer than k columns and rows of the region
  // are left out. k = 1 views the map's heights in place, without a copy, so the map
  // must outlive the surface. Throws InputError(where, ...) when k leaves fewer than
  // two nodes a side (the region is too narrow to draw).
  SurfaceGrid(const ZMap& map, const CellRegion& region, int k, const char* where);

  int64_t nx() const { return nx_; }
  int64_t ny() const { return ny_; }
  double step() const { return step_; }  // between nodes, mm
  double nodeX(int64_t i) const { return x0_ + double(i) * step_; }
  double nodeY(int64_t j) const { return y0_ + double(j) * step_; }
  int blockCells() const { return k_; }  // k
  // Height of node (i, j), mm.
  double height(int64_t i, int64_t j) const { return z_[j * stride_ + i]; }

  // The vertical exaggeration of the world frame.
  void setExaggeration(double zScale, double zOrigin) { zScale_ = zScale, zOrigin_ = zOrigin; }
  double zScale() const { return zScale_; }
  double zOrigin() const { return zOrigin_; }
  double worldZ(double heightMm) const { return zScale_ * (heightMm - zOrigin_); }
  double heightOf(double worldZ) const { return zOrigin_ + worldZ / zScale_; }

  // The smallest and largest node height, mm (NaN nodes left out; NaN when all are).
  std::pair<double, double> heightRange() const;

 private:
  void smoothBinomial();

  int64_t nx_ = 0, ny_ = 0, stride_ = 0;
  double x0_ = 0, y0_ = 0, step_ = 1;
  int k_ = 1;
  const double* z_ = nullptr;
  std::vector<double> owned_;
  double zScale_ = 1, zOrigin_ = 0;
};

// Where a ray meets the surface: its parameter, the patch (i, j) (between nodes i, i+1
// and j, j+1) and the point's place (u, v) in [0, 1]^2 in it.
struct PatchHit {
  double t = HUGE_VAL;
  int64_t i = -1, j = -1;
  double u = 0, v = 0;
  bool found() const { return i >= 0; }
  // The order of two hits at once: the smaller t, then the smaller patch (j, i), so that
  // ties are broken the same way whatever order the patches were tried in.
  bool before(const PatchHit& o) const {
    return t != o.t ? t < o.t : (j != o.j ? j < o.j : i < o.i);
  }
};

// The first point of patches [i0, i1) x [j0, j1) (a tile) on the ray o + t d with t in
// [tNear, tFar], walking its patches in the ray's order (a 2-D DDA) and solving, in each
// patch the ray crosses, the quadratic that the height along the ray minus the ray's
// height is; `anyHit` stops at the first hit found (shadow rays). World frame.
PatchHit firstHitInTile(const SurfaceGrid& s, int64_t i0, int64_t j0, int64_t i1, int64_t j1,
                        const Vec3& o, const Vec3& d, double tNear, double tFar, bool anyHit);

// The height (mm) and the world-frame unit normal (z > 0) of the surface at a hit.
double heightAt(const SurfaceGrid& s, const PatchHit& h);
Vec3 normalAt(const SurfaceGrid& s, const PatchHit& h);

}  // namespace scallop
