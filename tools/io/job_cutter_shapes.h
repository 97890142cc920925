// The job keys of the cutter shapes beyond ball, flat and bull (CONVENTIONS.md
// "Cutter shapes"): taper_ball, taper_bull, cone, barrel, taper_barrel, oval, lens,
// profile and apt. Parsed strictly (tools/io/job_fields.h), built by sweep/cutter_shapes.h
// and sweep/apt_cutter.h, echoed into report.json with their profile chain.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <set>
#include <string>

#include "sweep/cutter.h"

namespace scallop {

// The type names this file parses, in the order the docs list them.
const std::set<std::string>& shapedCutterTypeNames();

// The shape keys of type `typeName` (one of shapedCutterTypeNames()), read from `tool`
// at field path `field` ("tool", "tools.2"); the teeth keys are the caller's. Unknown
// keys are an error naming `field`.key; `teethKeys` are accepted.
Cutter parseShapedCutter(const nlohmann::json& tool, const std::string& typeName,
                         const std::set<std::string>& teethKeys, const std::string& field);

// [{"from": [rho, s], "to": [rho, s], "arc_radius": R, "centre": [rho, s]}, ...] (arc
// keys only for arcs): a profile's chain from the tip up, mm.
nlohmann::json profileSegmentsToJson(const CutterProfile& profile);

}  // namespace scallop
