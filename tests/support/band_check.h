// Band-by-band casting against a whole map: the scene cast into bands of `rowsPerBand`
// rows (each starting at `stockTopZ`, mm) gives the bits of `whole`, cell for cell.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>

#include "raycast/zmap.h"
#include "raycast/zmap_caster.h"

namespace scallop {

inline void expectBandsEqualWhole(const SweptScene& scene, const ZMap& whole, int64_t rowsPerBand,
                                  double stockTopZ) {
  const GridSpec& grid = whole.grid();
  for (int64_t j0 = 0; j0 < grid.ny; j0 += rowsPerBand) {
    const int64_t j1 = std::min(grid.ny, j0 + rowsPerBand);
    ZMap band(grid.rows(j0, j1), stockTopZ);
    castZMap(scene, band);
    for (int64_t j = j0; j < j1; ++j)
      for (int64_t i = 0; i < grid.nx; ++i)
        ASSERT_EQ(band.at(i, j - j0), whole.at(i, j)) << i << " " << j;
  }
}

}  // namespace scallop
