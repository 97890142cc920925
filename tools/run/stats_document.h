// The areal part of `scallop stats --json`: ISO 25178-2 parameters of a height map over
// a region, with or without plane levelling, and where the region lies. One owner for
// the stats command (tools/cli/stats_command.cpp) and the Python module's stats()
// (tools/python), so both give the same numbers and the same "surface_stats" block.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis/surface_metrology.h"
#include "raycast/zmap.h"

namespace scallop {

// "plane" or "none"; anything else is an InputError naming `field`.
Levelling parseLevelling(const std::string& level, const char* field);

// The cells of `grid` whose centres lie in `rectangle` = {x0, y0, x1, y1} (mm), or the
// whole map when it is empty; InputError naming `field` for another count of numbers,
// an unordered rectangle or one that holds no cell centre.
CellRegion statsRegion(const GridSpec& grid, const std::vector<double>& rectangle,
                       const char* field);

// {"grid", "region_cells", "region_mm", "surface_stats"} of `map` over `region`;
// `stats`, if given, receives the parameters as numbers.
nlohmann::json surfaceStatsDocument(const ZMap& map, const CellRegion& region, Levelling levelling,
                                    SurfaceStats* stats = nullptr);

}  // namespace scallop
