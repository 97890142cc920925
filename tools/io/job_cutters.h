// The sections of a job file that say what cuts and how (CONVENTIONS.md "Cutters",
// "Tools", docs/formats.md "Cutting model"): "tool", each entry of "tools", and
// "cutting". Parsed strictly, as every section (tools/io/job_fields.h), and echoed back
// into report.json.
#pragma once

#include <cstdint>
#include <map>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "sweep/cutter.h"
#include "sweep/cutting_model.h"

namespace scallop {

// {"type", "radius", "corner_radius", "flute_length", "flutes", "helix_deg",
// "runout_mm", "runout_phase_deg", "tooth_angles_deg", "tooth_offsets", "edge_span",
// "tooth_edge_spans"} at field path
// `field` ("tool", "tools.2"). The
// teeth keys default to CutterTeeth's (2 flutes, no helix, no runout) and are checked
// by CutterTeeth::make, whose messages name `field`.flutes and so on.
Cutter parseCutter(const nlohmann::json& tool, const std::string& field);

// "tools": {"1": {cutter}, "2": ...}: keys are tool numbers 1..999999999.
std::map<int64_t, Cutter> parseTools(const nlohmann::json& tools);

// "cutting": {"model": "envelope" | "teeth", "feed_per_tooth": fz (mm, > 0),
// "phase_deg": phi0 (degrees)}. The model defaults to envelope; feed_per_tooth may be
// left out (each move must then carry its own, e.g. G-code F / (S flutes): checked
// once the path is read, tools/run/job_loader.h).
CuttingModel parseCuttingModel(const nlohmann::json& cutting);

// The job's "spindle": "cw" (default, false) or "ccw" (true); InputError naming
// `spindle` otherwise.
bool parseSpindle(const nlohmann::json& doc);

const char* toString(CuttingModelKind kind);

nlohmann::json cutterToJson(const Cutter& cutter);
nlohmann::json cuttingModelToJson(const CuttingModel& cutting);

}  // namespace scallop
