#include "analysis/scallop_profile.h"

#include <algorithm>
#include <cmath>

namespace scallop {

ScallopProfile columnProfile(const ZMap& map, int64_t i) {
  ScallopProfile p;
  for (int64_t j = 0; j < map.ny(); ++j) {
    p.position.push_back(map.grid().cellCentreY(j));
    p.height.push_back(map.at(i, j));
  }
  return p;
}

double cuspHeight(const ScallopProfile& profile, double from, double to, double floorZ) {
  double top = -HUGE_VAL;
  for (size_t k = 0; k < profile.position.size(); ++k)
    if (profile.position[k] >= from && profile.position[k] <= to)
      top = std::max(top, profile.height[k]);
  return top - floorZ;
}

}  // namespace scallop
