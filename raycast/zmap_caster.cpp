#include "raycast/zmap_caster.h"

#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <vector>

namespace scallop {

CastStats castZMap(const SweptScene& scene, ZMap& map, const CastOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  const GridSpec& g = map.grid();
  const int64_t tile = std::max<int64_t>(1, options.tileCells);
  const int64_t tilesX = (g.nx + tile - 1) / tile, tilesY = (g.ny + tile - 1) / tile;

  // Each work item is one square tile of cells; its evaluation count lands in its own
  // slot, so the totals are summed in a fixed order afterwards.
  std::vector<uint64_t> evaluations(size_t(tilesX * tilesY), 0);
  std::atomic<int64_t> done{0};
  std::mutex progressMutex;

  tbb::parallel_for(
      tbb::blocked_range2d<int64_t>(0, tilesY, 1, 0, tilesX, 1),
      [&](const tbb::blocked_range2d<int64_t>& r) {
        for (int64_t ty = r.rows().begin(); ty < r.rows().end(); ++ty) {
          for (int64_t tx = r.cols().begin(); tx < r.cols().end(); ++tx) {
            uint64_t evals = 0;
            const int64_t j1 = std::min(g.ny, (ty + 1) * tile), i1 = std::min(g.nx, (tx + 1) * tile);
            for (int64_t j = ty * tile; j < j1; ++j)
              for (int64_t i = tx * tile; i < i1; ++i)
                map.at(i, j) = scene.lowestHeight(g.cellCentreX(i), g.cellCentreY(j), map.at(i, j), evals);
            evaluations[size_t(ty * tilesX + tx)] = evals;
            const int64_t cells = (j1 - ty * tile) * (i1 - tx * tile);
            const int64_t now = done.fetch_add(cells) + cells;
            if (options.progress) {
              std::lock_guard<std::mutex> lock(progressMutex);
              options.progress(now, g.cells());
            }
          }
        }
      },
      tbb::simple_partitioner());

  CastStats stats;
  stats.cells = g.cells();
  for (uint64_t e : evaluations) stats.exactEvaluations += e;
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return stats;
}

}  // namespace scallop
