// A stock given as a previous run's height map (CONVENTIONS.md "Stock of any shape"): the
// material under it. A new map's cells start at its heights.
#pragma once

#include "raycast/zmap.h"

namespace scallop {

// Every cell of `map` set to the height of `stock` under its centre, kNoMaterial
// (raycast/grid_frame.h) where `stock` is void (NaN). Where the grids coincide (same
// spacing and origin) a cell takes its value as it is; otherwise the bilinear
// interpolation between the four nearest cell centres of `stock` (clamped to its outermost
// centres at the border), void if any of the four is void.
void fillFromHeightMap(ZMap& map, const ZMap& stock);

}  // namespace scallop
