// The culling scene's internals, shared by its two halves: building the tiles and their
// grid (swept_scene.cpp, tile_grid.cpp) and answering queries (scene_queries.cpp). Not part
// of the raycast library's API (swept_scene.h is).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "raycast/swept_scene.h"

namespace scallop {
namespace scene_detail {

// A culling tile: its box (world coordinates, float, rounded outwards), its segment, and the
// supporting planes found while bounding it. Each plane z = a + b x + c y lies below
// the whole swept solid, so max over planes at the exact cell centre is a lower bound
// that is much tighter than the box's (which holds for the whole tile): a candidate
// whose bound is not below the best height so far needs no exact evaluation.
struct TilePlane {
  double a, b, c;
};
constexpr int kPlanesPerTile = 5;
// Exact evaluations (centre first, then corners) that give each tile its planes.
constexpr int kSamplesPerTile = 5;
struct TileBox {
  float lower[3];
  float upper[3];
  uint32_t segment;
  uint32_t planes;
  TilePlane plane[kPlanesPerTile];
};

// The scene's tile storage: std::vector, but growing it leaves new tiles uninitialised
// (the build writes each tile it keeps once, into its segment's slice and then by the
// parallel copy that concatenates the slices; unused slots are never read), so that the
// tens of megabytes are first touched by those writes on every thread instead of
// zeroed by one.
template <class T>
struct UninitialisedAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = UninitialisedAllocator<U>;
  };
  UninitialisedAllocator() = default;
  template <class U>
  UninitialisedAllocator(const UninitialisedAllocator<U>&) {}
  template <class U>
  void construct(U* p) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};
using TileStorage = std::vector<TileBox, UninitialisedAllocator<TileBox>>;

// Slack that absorbs float rounding of a coordinate of magnitude |v| (mm): a few float
// ulps plus a nanometre. Culling must stay conservative after conversion to float.
inline float slack(double v) {
  return float(8.0 * std::fabs(v) * 0x1p-23 + 1e-6);
}
inline float roundDown(double v) {
  return std::nextafter(float(v), -HUGE_VALF) - slack(v);
}
inline float roundUp(double v) {
  return std::nextafter(float(v), HUGE_VALF) + slack(v);
}

// A cell's point query: the exact (double) cell centre and the best height so far.
struct CellContext {
  double x, y;  // exact cell centre, mm
  double best;  // lowest exact height found so far, mm
  uint64_t evaluations;
  SweptScene::QueryCache* cache;  // may be null
  uint32_t winner;                // segment of `best`, or UINT32_MAX
};

// One tile met by a cell's query: unless its planes keep it at or above the best height
// so far, its segment's exact height, kept if lower. True if it was.
bool tryTile(const SweptScene::Impl& impl, const TileBox& tile, CellContext& cell);

// The lower bound of a tile's planes at one point, or over a rectangle (each plane's
// minimum over a rectangle is at a corner).
inline double planeBoundAt(const TileBox& t, double x, double y) {
  double bound = -HUGE_VAL;
  for (uint32_t k = 0; k < t.planes; ++k)
    bound = std::max(bound, t.plane[k].a + t.plane[k].b * x + t.plane[k].c * y);
  return bound;
}
inline double planeMinOver(const TilePlane& p, double x0, double y0, double x1, double y1) {
  return p.a + std::min(p.b * x0, p.b * x1) + std::min(p.c * y0, p.c * y1);
}
inline double planeBoundOver(const TileBox& t, double x0, double y0, double x1, double y1) {
  double bound = -HUGE_VAL;
  for (uint32_t k = 0; k < t.planes; ++k)
    bound = std::max(bound, planeMinOver(t.plane[k], x0, y0, x1, y1));
  return bound;
}
// The plane N . p = h_C(N) below a swept solid C, as z >= a + b x + c y (N.z < 0): it
// bounds every height of C from below, everywhere.
TilePlane planeBelow(const SweptMove& seg, const Vec3& N);
// The plane to keep for a segment from its exact lowest point at (x, y) (swept_scene.cpp
// says which); false when none applies.
bool planeFrom(const SweptMove& seg, const LowestPoint& lp, double x, double y, TilePlane& plane);
// A normal of the swept solid's bottom near (x, y) without an exact evaluation, for a
// whole move's tile: see swept_scene.cpp. `hit` is false where (x, y) lies beyond the
// cutter's bottom (planeFrom then leans a steep plane outwards).
LowestPoint closedFormPlaneHint(const SweptMove& seg, double x, double y);

// The cutoff to evaluate a guessed winner with (a neighbour's). A turning move's search
// first tries to prove the move stays above its cutoff (ray clearance, swept_move.cpp
// step 4a), which a winner always fails: a guess, right 95 % of the time on B3, skips
// it. A constant-axis kernel (SweptMove::takesSectionMemo: a tip ball's too) prunes by
// its cutoff in closed form, so it keeps it. Heights do not depend on the cutoff, only
// whether a loser costs more.
inline double hintCutoff(const SweptMove& seg, double best) {
  return seg.turning() && !seg.teeth() && !seg.takesSectionMemo() ? HUGE_VAL : best;
}

// The section memo of a constant-axis kernel (SweptMove::takesSectionMemo) for the cell's
// row (null without a cache, and for a turning move, which keeps none: no hash for it).
inline SectionMemo* memoOf(SweptScene::QueryCache* cache, const SweptMove& move, uint32_t segment,
                           double y) {
  return cache && move.takesSectionMemo() ? cache->memoFor(segment, y) : nullptr;
}

// Plane values are exact up to double round-off; this margin (mm) absorbs it. (Steep
// planes have coefficients up to 1e3; their round-off stays below 1e-11 mm here.)
inline double planeSlack(double v) {
  return 1e-9 * (1 + std::fabs(v));
}

class TileGrid;  // tile_grid.h

}  // namespace scene_detail

struct SweptScene::Impl {
  std::vector<SweptMove> segments;
  scene_detail::TileStorage tiles;
  std::unique_ptr<scene_detail::TileGrid> grid;  // lists the tiles for every query
  SceneStats stats;
  bool turningMoves = false;  // some segment's axis turns (lowestHeight's first search)
  // Every segment's tiles, in segment order.
  void buildTiles(const SceneOptions& options);
};

}  // namespace scallop
