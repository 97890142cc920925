// The report.json sections of a simulation that come from the job's path file and
// design surface: path-file warnings, and the design comparison with its
// picture DIR/deviation.png.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>

#include "raycast/zmap.h"
#include "sweep/tool_path_sweep.h"

namespace scallop {

struct Job;

// {"format", "warnings": [...first 100...], "warnings_total", "ignored_words": [{"word",
// "meaning", "count", "lines": [first 20]}], and for a multi-tool file "tools":
// [{"number", "tool", "cutting_moves", "first_line", "last_line"}]} for a path file, and
// the same warnings on stderr (the first 20 and a count) unless `quiet`.
nlohmann::json pathFileReport(const Job& job, bool quiet);

// Compares `map` with job.design (analysis/design_deviation.h), writes
// DIR/deviation.png atomically (not when `outDir` is empty; nor are the section's
// "image" and "image_colour_range_mm" then) and returns the "design" section: deviation
// statistics (machined - design, mm), over-cut and under-cut areas, and the deepest
// gouges (at most 100) with the moves, and file lines, that made them. Prints a
// summary on stderr unless `quiet`.
nlohmann::json designReport(const Job& job, const ZMap& map, const std::string& outDir, bool quiet);

}  // namespace scallop
