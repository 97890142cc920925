// Job: what `scallop simulate` runs, read from a JSON job file (CONVENTIONS.md "Job
// file"). Parsing is strict: unknown keys, missing keys and wrong types are errors that
// name the file, the line (for malformed JSON) or the field, and what was expected.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>

#include "raycast/zmap.h"
#include "sweep/cutter.h"
#include "sweep/pose.h"
#include "sweep/raster.h"
#include "sweep/vec3.h"

namespace scallop {

struct Job {
  std::string source;  // file name, or "built-in default job"
  Cutter cutter;
  Box3 stock;
  double spacing = 0;           // grid cell side, mm
  double axisTolerance = 1e-4;  // mm, see SweepOptions
  bool isRaster = false;
  RasterSpec raster;     // when isRaster
  std::string pathFile;  // when not: the tool-path file, resolved to a path
  ToolPath path;         // built from either

  GridSpec grid() const;
};

// The built-in default job: a bull cutter raster with lead (the README's main job).
const char* defaultJobJson();

// Parses and validates; `source` names the file in messages and resolves relative
// tool-path files. Throws InputError. Without `checkMemory` a grid too large to hold is
// accepted (the caller computes it in bands, tools/tiled_simulation.h).
Job parseJob(const std::string& text, const std::string& source, bool checkMemory = true);
Job loadJobFile(const std::string& path, bool checkMemory = true);

// Refuses grids whose heights would not fit in memory, naming the size they need.
void checkGridFitsMemory(const GridSpec& grid, const std::string& field);

// The job as JSON (the inputs echoed into report.json).
nlohmann::json jobToJson(const Job& job);

}  // namespace scallop
