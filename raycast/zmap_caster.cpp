#include "raycast/zmap_caster.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <utility>
#include <vector>

#include "raycast/cell_tiles.h"

namespace scallop {

namespace {

// Heights of the cells [i0, i1) x [j0, j1), a square region of at most regionCells a
// side, with one candidate search for the whole region:
//  1. a move W: the last region's winner (next door), or where its cutter misses a
//     corner of this region, the winner at the region's centre (an exact query);
//  2. W's heights are at most those of one convex solid inside W's swept solid (the
//     whole solid for a constant axis; the cutter at the pose of W's answer at the
//     centre for a turning move), and over the rectangle of cell centres a convex
//     solid's heights are at most its largest corner value: no cell ends higher than
//     U = that (or than its current height), so only moves that can go below U
//     anywhere in the region can matter. Any W gives a valid U; the centre's winner the
//     lowest, its neighbour on the path one a little higher without the exact query
//     (B3: 1.5 % fewer instructions in all, B4 12 %). With teeth W's crossings are no
//     convex function: U is then the region's current heights;
//  3. one query of the tile grid collects those (each also gets the supporting plane of its
//     solid below the centre), and each cell takes the exact minimum among them
//     (lowestHeightAmong), which equals lowestHeight() cell by cell.
void castRegion(const SweptScene& scene, ZMap& map, int64_t i0, int64_t i1, int64_t j0, int64_t j1,
                std::vector<SweptScene::Candidate>& candidates, SweptScene::QueryCache& cache,
                uint32_t& previousWinner, uint64_t& evals) {
  const GridSpec& g = map.grid();
  const double x0 = g.cellCentreX(i0), x1 = g.cellCentreX(i1 - 1);
  const double y0 = g.cellCentreY(j0), y1 = g.cellCentreY(j1 - 1);
  double ceiling = -HUGE_VAL;
  for (int64_t j = j0; j < j1; ++j)
    for (int64_t i = i0; i < i1; ++i) ceiling = std::max(ceiling, map.at(i, j));

  // The cap U of step 2 from a move W: any move gives a valid one, the winner at the
  // centre the lowest. The last region's winner W (next door) is tried first; only where
  // its cap is no cap (its cutter misses a corner) is the centre's winner looked up.
  const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1);
  auto capFrom = [&](uint32_t winner) {
    if (winner == UINT32_MAX || scene.segments()[winner].teeth()) return HUGE_VAL;
    const SweptMove& w = scene.segments()[winner];
    double tCentre = 0;
    if (w.turning()) {
      tCentre = w.lowestPoint(cx, cy).t;
      ++evals;
    }
    double cornerMax = -HUGE_VAL;
    for (const auto& [x, y] : {std::pair{x0, y0}, {x1, y0}, {x0, y1}, {x1, y1}}) {
      const LowestPoint lp =
          w.turning() ? w.stationaryLowestPoint(tCentre, x, y) : w.lowestPoint(x, y);
      ++evals;
      cornerMax = std::max(cornerMax, lp.hit ? lp.z : HUGE_VAL);
    }
    return cornerMax;
  };
  double cap = capFrom(previousWinner);
  if (!(cap < ceiling)) {
    uint32_t winner = previousWinner;
    scene.lowestHeight(cx, cy, ceiling, evals, &cache, &winner);
    if (winner != UINT32_MAX && winner != previousWinner) cap = capFrom(winner);
    if (winner != UINT32_MAX) previousWinner = winner;
  }
  const double upper = std::min(ceiling, cap);
  scene.gatherCandidates(x0, y0, x1, y1, upper, candidates);
  // Many candidates (short moves): one exact evaluation each at the centre buys a tight
  // plane that saves many per cell. With few, the tile planes do.
  if (candidates.size() > 4)
    scene.tightenCandidates(candidates, 0.5 * (x0 + x1), 0.5 * (y0 + y1), evals, &cache);
  // Blocks of kBlockCells a side, each with the candidates in the order of their
  // bounds over the block: a cell stops looking at the first that cannot beat it. No
  // cell of the region ends above `upper`, so a block drops the candidates proven above
  // it over all of its lines (SweptScene::orderForBlock).
  // Neighbouring cells mostly share their winner: each cell tries its left neighbour's
  // (or, first in a block's row, the one below) first, whose height then prunes the
  // others. (16: on B3 0.9 % fewer instructions than 8 and 3 % fewer than 32.)
  constexpr int64_t kBlockCells = 16;
  thread_local std::vector<SweptScene::BlockEntry> block;
  uint32_t blockStart = UINT32_MAX;
  for (int64_t bj = j0; bj < j1; bj += kBlockCells) {
    for (int64_t bi = i0; bi < i1; bi += kBlockCells) {
      const int64_t bi1 = std::min(i1, bi + kBlockCells), bj1 = std::min(j1, bj + kBlockCells);
      scene.orderForBlock(candidates, g.cellCentreX(bi), g.cellCentreY(bj), g.cellCentreX(bi1 - 1),
                          g.cellCentreY(bj1 - 1), block, upper);
      uint32_t rowStart = blockStart;
      for (int64_t j = bj; j < bj1; ++j) {
        uint32_t hint = rowStart;
        for (int64_t i = bi; i < bi1; ++i) {
          const uint32_t tried = hint;
          map.at(i, j) =
              scene.lowestHeightAmong(candidates, block, g.cellCentreX(i), g.cellCentreY(j),
                                      map.at(i, j), evals, &cache, &hint);
          if (hint == UINT32_MAX) hint = tried;  // the ceiling held: keep the old guess
          if (i == bi) rowStart = hint;
        }
      }
      blockStart = rowStart;
    }
  }
  // The next region (to the right) starts its cap from this one's last winner.
  if (blockStart < candidates.size()) previousWinner = candidates[blockStart].segment;
}

}  // namespace

CastStats castZMap(const SweptScene& scene, ZMap& map, const CastOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  const GridSpec& g = map.grid();
  // Regions no wider than the scene was built for (a region of n cells
  // spans n - 1 spacings between its outer cell centres); 1 means cell by cell.
  const int64_t region = std::max<int64_t>(
      1, std::min(options.regionCells > 0 ? options.regionCells : INT64_MAX,
                  int64_t(std::floor(2 * scene.regionHalfSize() / g.spacing + 1e-9)) + 1));

  CastStats stats;
  const int64_t tileCells = options.tileCells > 0             ? options.tileCells
                            : g.cells() >= (int64_t(1) << 22) ? 128
                                                              : 64;
  std::atomic<uint64_t> unproven{0};
  stats.exactEvaluations = forEachCellTile(
      g, tileCells, options.progress, [&](int64_t i0, int64_t i1, int64_t j0, int64_t j1) {
        const unsigned long long unprovenBefore = SweptMove::unprovenSearchesOnThisThread();
        struct CountUnproven {
          std::atomic<uint64_t>& total;
          unsigned long long before;
          ~CountUnproven() { total += SweptMove::unprovenSearchesOnThisThread() - before; }
        } countUnproven{unproven, unprovenBefore};
        uint64_t evals = 0;
        SweptScene::QueryCache cache;
        thread_local std::vector<SweptScene::Candidate> candidates;
        uint32_t previousWinner = UINT32_MAX;  // the last region's centre winner
        // The tile is cut into equal regions (no thin leftover strips: each region
        // pays the same set-up whatever its size).
        const int64_t nx = (i1 - i0 + region - 1) / region, ny = (j1 - j0 + region - 1) / region;
        for (int64_t b = 0; b < ny; ++b) {
          for (int64_t a = 0; a < nx; ++a) {
            const int64_t ri = i0 + (i1 - i0) * a / nx, ri1 = i0 + (i1 - i0) * (a + 1) / nx;
            const int64_t rj = j0 + (j1 - j0) * b / ny, rj1 = j0 + (j1 - j0) * (b + 1) / ny;
            if (region == 1) {
              map.at(ri, rj) = scene.lowestHeight(g.cellCentreX(ri), g.cellCentreY(rj),
                                                  map.at(ri, rj), evals, &cache);
            } else {
              castRegion(scene, map, ri, ri1, rj, rj1, candidates, cache, previousWinner, evals);
            }
          }
        }
        return evals;
      });
  stats.cells = g.cells();
  stats.unprovenSearches = unproven.load();
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return stats;
}

}  // namespace scallop
