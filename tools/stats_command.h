// `scallop stats FILE.gsf|FILE.exr`: ISO 25178-2 height parameters of a height map
// (analysis/surface_metrology.h) over the whole map or a --region, with or without
// plane levelling, and optionally a --profile's roughness (analysis/profile_metrology.h).
// The same "surface_stats" block goes into every report.json of `simulate`.
#pragma once

#include <nlohmann/json.hpp>

#include "analysis/surface_metrology.h"
#include "raycast/zmap.h"

namespace scallop {

// The report block: {"standard", "levelling", "cells", "area_mm2", "Sa_mm", "Sq_mm",
// "Ssk", "Sku", "Sp_mm", "Sv_mm", "Sz_mm", "reference_plane": {...}, "notes"}.
// NaN parameters (Sa of a banded map) become null.
nlohmann::json surfaceStatsJson(const SurfaceStats& stats);

// The in-memory report's block: the whole map, plane levelled.
nlohmann::json mapSurfaceStatsJson(const ZMap& map);

}  // namespace scallop
