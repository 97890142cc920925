// ScallopProfile: a cross-feed line of heights taken from a z-map, and the scallop
// (cusp) measurements made on it.
#pragma once

#include <cstdint>
#include <vector>

#include "raycast/zmap.h"

namespace scallop {

struct ScallopProfile {
  std::vector<double> position;  // cross-feed coordinate of each sample, mm
  std::vector<double> height;    // absolute height, mm
};

// The column of cells at index i (a line along y; a raster fed along x is crossed).
ScallopProfile columnProfile(const ZMap& map, int64_t i);

// Highest height minus the floor over samples with position in [from, to], mm:
// the scallop (cusp) height left between passes whose floor is at `floorZ`.
double cuspHeight(const ScallopProfile& profile, double from, double to, double floorZ);

}  // namespace scallop
