// TileGrid: which culling tiles a region of cells must look at, from a 2-D grid of
// buckets instead of a ray. Internal to raycast/ (swept_scene.cpp builds it,
// scene_queries.cpp asks it).
//
// Gathering a region's candidates (SweptScene::gatherCandidates) wants every tile whose
// grown box stands over the region's centre and whose planes can go below the region's
// cap: the ray that gathered them was never shortened, so it visited every box over the
// line with its bottom below the cap (B3: ~650, of which ~60 pass their planes). Here each
// tile is listed in the buckets its grown box overlaps, with a lower bound of its planes
// over every region whose centre lies in that bucket; a bucket's list is sorted by that
// bound, so a query reads only the tiles that can pass.
//
// Why the bound holds: a region R of half side g centred at c in bucket B, and a tile
// whose grown box G holds c. Every point of R lies in (B n G) grown by g, and each plane of
// the tile is a lower bound of its segment everywhere (scene_tiles.h), so the planes'
// bound over that rectangle is at most the segment's height anywhere in R. The tile's box
// bottom bounds its segment over the (ungrown) tile too; the larger of the two is kept.
#pragma once

#include <cstdint>
#include <vector>

#include "raycast/scene_tiles.h"

namespace scallop {
namespace scene_detail {

class TileGrid {
 public:
  // The most a tile costs the grid: 16 entries and 4 buckets (estimateSceneBytes).
  static constexpr double kMaxBytesPerTile = 16 * 8 + 4 * 8;

  // Lists `tiles` in buckets of about half a tile, for regions of half side up to
  // regionHalfSize (mm).
  void build(const TileStorage& tiles, double regionHalfSize);

  // Bytes the grid holds (its buckets and entries).
  size_t bytes() const {
    return first_.capacity() * sizeof(uint64_t) + entries_.capacity() * sizeof(Entry);
  }

  // Calls visit(tile) for every tile whose grown box holds (x, y) and whose bound over
  // the bucket of (x, y) is below zTop, in ascending order of that bound.
  template <class Visit>
  void forEachOver(const TileStorage& tiles, double x, double y, double zTop, Visit&& visit) const {
    const int64_t i = bucketOf(x, x0_, nx_), j = bucketOf(y, y0_, ny_);
    if (i < 0 || j < 0) return;
    const size_t b = size_t(j * nx_ + i);
    for (size_t e = first_[b]; e < first_[b + 1]; ++e) {
      if (!(double(entries_[e].bound) < zTop)) return;
      // Only tiles whose grown box holds the centre can overlap the region (a cheap test:
      // a tile let through would only be one candidate more, never a wrong one).
      const Rect r = grown(tiles[entries_[e].tile]);
      if (x >= r.x0 && x <= r.x1 && y >= r.y0 && y <= r.y1) visit(entries_[e].tile);
    }
  }

  // A point query: calls visit(tile) for every tile whose own box holds (x, y) and whose
  // bound over the bucket of (x, y) is below top(), in ascending order of that bound;
  // top() is read before each tile, so a visit that finds a lower height shortens the
  // rest, as a ray's far end is shortened.
  template <class Top, class Visit>
  void forEachUnder(const TileStorage& tiles, double x, double y, Top&& top, Visit&& visit) const {
    const int64_t i = bucketOf(x, x0_, nx_), j = bucketOf(y, y0_, ny_);
    if (i < 0 || j < 0) return;
    const size_t b = size_t(j * nx_ + i);
    for (size_t e = first_[b]; e < first_[b + 1]; ++e) {
      if (!(double(entries_[e].bound) < top())) return;
      const TileBox& t = tiles[entries_[e].tile];
      if (x >= t.lower[0] && x <= t.upper[0] && y >= t.lower[1] && y <= t.upper[1])
        visit(entries_[e].tile);
    }
  }

 private:
  // A tile's box grown by the regions' half side: where their centres can be for the
  // tile to overlap them.
  struct Rect {
    double x0, y0, x1, y1;
  };
  Rect grown(const TileBox& t) const {
    return {t.lower[0] - grow_, t.lower[1] - grow_, t.upper[0] + grow_, t.upper[1] + grow_};
  }
  struct Entry {
    float bound;  // mm, rounded down
    uint32_t tile;
  };
  // The bucket of a coordinate, or -1 outside the grid.
  int64_t bucketOf(double v, double origin, int64_t n) const {
    const double u = (v - origin) / side_;
    if (!(u >= 0 && u < double(n))) return -1;
    return int64_t(u);
  }
  double grow_ = 0;                    // the regions' half side, mm
  double x0_ = 0, y0_ = 0, side_ = 1;  // mm
  int64_t nx_ = 0, ny_ = 0;
  std::vector<uint64_t> first_;  // bucket b's entries are [first_[b], first_[b + 1])
  std::vector<Entry> entries_;
};

}  // namespace scene_detail
}  // namespace scallop
