// forEachCellTile: the parallel loop both z-map casters share. The grid is cut into
// square tiles of cells; each tile is one task, so no two tasks write the same cell, and
// each tile's work count lands in its own slot and is summed in a fixed order, so
// totals do not depend on the thread count either.
#pragma once

#include <cstdint>
#include <functional>

#include "raycast/zmap.h"

namespace scallop {

// Cells [i0, i1) x [j0, j1) of one tile; returns the exact evaluations it made.
using CellTileWork = std::function<uint64_t(int64_t i0, int64_t i1, int64_t j0, int64_t j1)>;

// Runs `work` on every tile (tileCells a side) in parallel and returns the total count.
// `progress`, when set, is called (serialised) with cells done so far and the total.
uint64_t forEachCellTile(const GridSpec& grid, int64_t tileCells,
                         const std::function<void(int64_t done, int64_t total)>& progress,
                         const CellTileWork& work);

}  // namespace scallop
