#include "raycast/cell_tiles.h"

#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <mutex>
#include <vector>

namespace scallop {

uint64_t forEachCellTile(const GridSpec& g, int64_t tileCells,
                         const std::function<void(int64_t, int64_t)>& progress,
                         const CellTileWork& work) {
  const int64_t tile = std::max<int64_t>(1, tileCells);
  const int64_t tilesX = (g.nx + tile - 1) / tile, tilesY = (g.ny + tile - 1) / tile;
  std::vector<uint64_t> evaluations(size_t(tilesX * tilesY), 0);
  std::atomic<int64_t> done{0};
  std::mutex progressMutex;
  tbb::parallel_for(
      tbb::blocked_range2d<int64_t>(0, tilesY, 1, 0, tilesX, 1),
      [&](const tbb::blocked_range2d<int64_t>& r) {
        for (int64_t ty = r.rows().begin(); ty < r.rows().end(); ++ty) {
          for (int64_t tx = r.cols().begin(); tx < r.cols().end(); ++tx) {
            const int64_t i0 = tx * tile, i1 = std::min(g.nx, i0 + tile);
            const int64_t j0 = ty * tile, j1 = std::min(g.ny, j0 + tile);
            evaluations[size_t(ty * tilesX + tx)] = work(i0, i1, j0, j1);
            const int64_t cells = (j1 - j0) * (i1 - i0);
            const int64_t now = done.fetch_add(cells) + cells;
            if (progress) {
              std::lock_guard<std::mutex> lock(progressMutex);
              progress(now, g.cells());
            }
          }
        }
      },
      tbb::simple_partitioner());
  uint64_t total = 0;
  for (uint64_t e : evaluations) total += e;
  return total;
}

}  // namespace scallop
