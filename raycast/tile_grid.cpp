#include "raycast/tile_grid.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>

namespace scallop {
namespace scene_detail {

namespace {

// Rounding of a region centre into its bucket is covered by widening every bucket by
// this much (mm) before its bounds are taken: far more than the round-off of (v - origin)
// / side, far less than anything the bounds could notice.
constexpr double kBucketMargin = 1e-6;

}  // namespace

void TileGrid::build(const TileStorage& tiles, double regionHalfSize) {
  first_.assign(1, 0);
  entries_.clear();
  nx_ = ny_ = 0;
  if (tiles.empty()) return;

  // --- The grid: over all grown boxes, buckets of half the median box side -------------
  // (a tile then sits in about 3 x 3 buckets; finer buckets would list each tile more
  // often for bounds little tighter), made coarser while there are more than four
  // buckets or sixteen entries a tile: at most kMaxBytesPerTile (tile_grid.h).
  grow_ = regionHalfSize;
  double minX = HUGE_VAL, minY = HUGE_VAL, maxX = -HUGE_VAL, maxY = -HUGE_VAL;
  std::vector<double> sides(tiles.size());
  for (size_t k = 0; k < tiles.size(); ++k) {
    const Rect r = grown(tiles[k]);
    minX = std::min(minX, r.x0), minY = std::min(minY, r.y0);
    maxX = std::max(maxX, r.x1), maxY = std::max(maxY, r.y1);
    sides[k] = std::max(r.x1 - r.x0, r.y1 - r.y0);
  }
  std::nth_element(sides.begin(), sides.begin() + std::ptrdiff_t(sides.size() / 2), sides.end());
  side_ = std::max(0.5 * sides[sides.size() / 2], 1e-6);
  const double width = maxX - minX, height = maxY - minY;
  x0_ = minX - 2 * kBucketMargin, y0_ = minY - 2 * kBucketMargin;
  // The buckets a tile's grown box overlaps (widened by the margin), clamped to the grid.
  auto range = [&](const TileBox& t, int64_t& i0, int64_t& i1, int64_t& j0, int64_t& j1) {
    const Rect r = grown(t);
    i0 = std::clamp<int64_t>(int64_t((r.x0 - kBucketMargin - x0_) / side_), 0, nx_ - 1);
    i1 = std::clamp<int64_t>(int64_t((r.x1 + kBucketMargin - x0_) / side_), 0, nx_ - 1);
    j0 = std::clamp<int64_t>(int64_t((r.y0 - kBucketMargin - y0_) / side_), 0, ny_ - 1);
    j1 = std::clamp<int64_t>(int64_t((r.y1 + kBucketMargin - y0_) / side_), 0, ny_ - 1);
  };
  for (;; side_ *= 1.5) {
    nx_ = int64_t((width + 4 * kBucketMargin) / side_) + 1;
    ny_ = int64_t((height + 4 * kBucketMargin) / side_) + 1;
    if (double(nx_) * double(ny_) > 4.0 * double(tiles.size())) continue;
    double entries = 0;
    for (const TileBox& t : tiles) {
      int64_t i0, i1, j0, j1;
      range(t, i0, i1, j0, j1);
      entries += double(i1 - i0 + 1) * double(j1 - j0 + 1);
    }
    if (entries <= 16.0 * double(tiles.size())) break;
  }

  // --- Counting, then filling each bucket's slice -------------------------------------
  const size_t buckets = size_t(nx_ * ny_);
  std::vector<uint64_t> count(buckets + 1, 0);
  for (const TileBox& t : tiles) {
    int64_t i0, i1, j0, j1;
    range(t, i0, i1, j0, j1);
    for (int64_t j = j0; j <= j1; ++j)
      for (int64_t i = i0; i <= i1; ++i) ++count[size_t(j * nx_ + i) + 1];
  }
  for (size_t b = 0; b < buckets; ++b) count[b + 1] += count[b];
  first_ = count;
  entries_.resize(first_.back());
  std::unique_ptr<std::atomic<uint64_t>[]> cursor(new std::atomic<uint64_t>[buckets]);
  for (size_t b = 0; b < buckets; ++b) cursor[b].store(first_[b], std::memory_order_relaxed);
  const double g = regionHalfSize + kBucketMargin;
  tbb::parallel_for(size_t(0), tiles.size(), [&](size_t k) {
    const TileBox& t = tiles[k];
    const Rect r = grown(t);
    int64_t i0, i1, j0, j1;
    range(t, i0, i1, j0, j1);
    for (int64_t j = j0; j <= j1; ++j) {
      for (int64_t i = i0; i <= i1; ++i) {
        // The centres this bucket can hold for this tile: the bucket (widened) within the
        // grown box; the regions round them reach g farther.
        const double bx0 = std::max(x0_ + double(i) * side_ - kBucketMargin, r.x0);
        const double bx1 = std::min(x0_ + double(i + 1) * side_ + kBucketMargin, r.x1);
        const double by0 = std::max(y0_ + double(j) * side_ - kBucketMargin, r.y0);
        const double by1 = std::min(y0_ + double(j + 1) * side_ + kBucketMargin, r.y1);
        double bound = planeBoundOver(t, bx0 - g, by0 - g, bx1 + g, by1 + g);
        bound = std::max(bound - planeSlack(bound), double(t.lower[2]));
        const uint64_t at = cursor[size_t(j * nx_ + i)].fetch_add(1, std::memory_order_relaxed);
        entries_[at] = {roundDown(bound), uint32_t(k)};
      }
    }
  });
  // Each bucket in ascending bound (ties by tile): the order a query reads them in, the
  // same whatever order the threads filled them.
  tbb::parallel_for(size_t(0), buckets, [&](size_t b) {
    std::sort(entries_.begin() + std::ptrdiff_t(first_[b]),
              entries_.begin() + std::ptrdiff_t(first_[b + 1]), [](const Entry& p, const Entry& q) {
                return p.bound != q.bound ? p.bound < q.bound : p.tile < q.tile;
              });
  });
}

}  // namespace scene_detail
}  // namespace scallop
