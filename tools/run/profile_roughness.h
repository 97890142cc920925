// A line profile of a height map and its roughness, for `scallop stats --profile` (the
// "profile" block of its JSON and its text) and `scallop export --profile` (the CSV's
// roughness column, tools/run/map_export.h): one owner, so that the two commands sample
// and filter a line the same way.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "analysis/profile_metrology.h"
#include "raycast/zmap.h"

namespace scallop {

struct ProfileRoughness {
  Profile profile;
  RoughnessStats roughness;
};

// The profile of `map` along `line` = {x0, y0, x1, y1} (mm), a sample every `stepMm` (0:
// the grid spacing); InputError naming `lineField` for a line off the map or not of 4
// numbers.
Profile lineProfile(const ZMap& map, const std::vector<double>& line, double stepMm,
                    const char* lineField);

// That profile and its roughness with `filter` (analysis/profile_metrology.h). InputError
// naming `lineField` for a line off the map or of the wrong size, `filterField` for
// filters the profile is too short for or that do not fit its sampling.
ProfileRoughness profileRoughness(const ZMap& map, const std::vector<double>& line, double stepMm,
                                  const RoughnessFilter& filter, const char* lineField,
                                  const char* filterField);

// The "profile" block of `scallop stats --json`.
nlohmann::json profileRoughnessDocument(const ProfileRoughness& p);

}  // namespace scallop
