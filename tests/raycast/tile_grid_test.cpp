// The tile grid (raycast/tile_grid.h): a region's query must list every tile whose
// planes can go below the cap somewhere in the region, whatever the tiles' sizes.
#include "raycast/tile_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

namespace scallop {
namespace {

using namespace scene_detail;

// Tiles of sizes from 10 um to 5 mm (the grid's buckets follow the median: large tiles
// span many of them, and the entries' cap makes the buckets coarser), each with one to
// three random planes; the box's bottom is the planes' bound over the tile, as
// SweptScene builds it.
TileStorage randomTiles(std::mt19937& rng, int count) {
  std::uniform_real_distribution<double> pos(0, 10), logSide(std::log(0.01), std::log(5)),
      coef(-2, 2), level(-1, 1);
  TileStorage tiles(static_cast<size_t>(count));
  for (TileBox& t : tiles) {
    const double x0 = pos(rng), y0 = pos(rng);
    const double x1 = x0 + std::exp(logSide(rng)), y1 = y0 + std::exp(logSide(rng));
    t.planes = 1 + uint32_t(rng() % 3);
    for (uint32_t k = 0; k < t.planes; ++k) t.plane[k] = {level(rng), coef(rng), coef(rng)};
    t.lower[0] = roundDown(x0), t.lower[1] = roundDown(y0);
    t.upper[0] = roundUp(x1), t.upper[1] = roundUp(y1);
    t.lower[2] = roundDown(planeBoundOver(t, x0, y0, x1, y1));
    t.upper[2] = roundUp(10);
    t.segment = 0;
  }
  return tiles;
}

TEST(TileGrid, EveryTileThatCanBeLowInARegionIsListed) {
  std::mt19937 rng(20261203);
  const TileStorage tiles = randomTiles(rng, 3000);
  const double g = 0.05;  // the regions' largest half side, mm
  TileGrid grid;
  grid.build(tiles, g);
  std::uniform_real_distribution<double> pos(-0.5, 10.5), half(0, g), cap(-6, 2);
  int lowTiles = 0;
  for (int query = 0; query < 400; ++query) {
    const double cx = pos(rng), cy = pos(rng), h = half(rng), zTop = cap(rng);
    std::set<uint32_t> listed;
    grid.forEachOver(tiles, cx, cy, zTop, [&](uint32_t id) { listed.insert(id); });
    // By brute force: a tile that overlaps the region and whose planes (and bottom) lie
    // below the cap at a point of the overlap, sampled on a 9 x 9 lattice with its corners.
    for (uint32_t id = 0; id < tiles.size(); ++id) {
      const TileBox& t = tiles[id];
      const double ox0 = std::max(cx - h, double(t.lower[0])),
                   ox1 = std::min(cx + h, double(t.upper[0]));
      const double oy0 = std::max(cy - h, double(t.lower[1])),
                   oy1 = std::min(cy + h, double(t.upper[1]));
      if (!(ox0 <= ox1 && oy0 <= oy1)) continue;
      bool low = false;
      for (int a = 0; a <= 8 && !low; ++a) {
        for (int b = 0; b <= 8 && !low; ++b) {
          const double x = ox0 + (ox1 - ox0) * a / 8, y = oy0 + (oy1 - oy0) * b / 8;
          low = std::max(planeBoundAt(t, x, y), double(t.lower[2])) < zTop;
        }
      }
      if (!low) continue;
      ++lowTiles;
      EXPECT_TRUE(listed.count(id)) << "tile " << id << " missing at (" << cx << ", " << cy
                                    << ") half " << h << " cap " << zTop;
    }
  }
  // The queries met many tiles that matter, or the test would prove little.
  EXPECT_GT(lowTiles, 1000);
}

TEST(TileGrid, ListsOnlyTilesOverTheCentre) {
  std::mt19937 rng(7);
  const TileStorage tiles = randomTiles(rng, 500);
  const double g = 0.03;
  TileGrid grid;
  grid.build(tiles, g);
  for (int query = 0; query < 200; ++query) {
    const double cx = 10.0 * (rng() % 1000) / 1000, cy = 10.0 * (rng() % 1000) / 1000;
    grid.forEachOver(tiles, cx, cy, HUGE_VAL, [&](uint32_t id) {
      const TileBox& t = tiles[id];
      EXPECT_TRUE(cx >= t.lower[0] - g && cx <= t.upper[0] + g && cy >= t.lower[1] - g &&
                  cy <= t.upper[1] + g);
    });
  }
  // A point off the grid has no tiles.
  int seen = 0;
  grid.forEachOver(tiles, -100, -100, HUGE_VAL, [&](uint32_t) { ++seen; });
  EXPECT_EQ(seen, 0);
  // An empty scene lists nothing and does not fail.
  TileGrid empty;
  empty.build(TileStorage(), g);
  empty.forEachOver(TileStorage(), 1, 1, HUGE_VAL, [&](uint32_t) { ++seen; });
  EXPECT_EQ(seen, 0);
}

}  // namespace
}  // namespace scallop
