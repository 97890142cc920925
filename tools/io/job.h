// Job: what `scallop simulate` runs, read from a JSON job file (CONVENTIONS.md "Job
// file"). Parsing is strict: unknown keys, missing keys and wrong types are errors that
// name the file, the line (for malformed JSON) or the field, and what was expected.
#pragma once

#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "analysis/triangle_mesh.h"
#include "raycast/zmap.h"
#include "sweep/cutter.h"
#include "sweep/pose.h"
#include "sweep/raster.h"
#include "sweep/vec3.h"
#include "tools/io/tool_path_file.h"

namespace scallop {

struct Job {
  std::string source;  // file name, or "built-in default job"
  Cutter cutter;
  Box3 stock;
  double spacing = 0;           // grid cell side, mm
  bool isRaster = false;
  RasterSpec raster;     // when isRaster
  std::string pathFile;  // when not: the tool-path file, resolved to a path
  ToolPath path;         // built from either
  // From a path file: its format, the file line of each move and the warnings
  // (unknown statements, rapids into the stock), echoed into report.json.
  std::string pathFormat;
  std::vector<int64_t> moveLines;
  PathWarnings pathWarnings;
  // "design": {"stl": FILE, "gouge_tolerance": mm}: the part the path should make.
  std::string designFile;                      // resolved; empty without a design
  std::shared_ptr<const TriangleMesh> design;  // read when the job is parsed
  double gougeTolerance = 1e-3;                // mm below the design that is a gouge

  GridSpec grid() const;
};

// The built-in default job: a bull cutter raster with lead (the README's main job).
const char* defaultJobJson();

// Parses and validates; `source` names the file in messages and resolves relative
// tool-path files. Throws InputError. Without `checkMemory` a grid too large to hold is
// accepted (the caller computes it in bands, tools/run/tiled_simulation.h).
// A non-empty `pathOverride` (simulate --path FILE) replaces the job's "path".
// "tool" may be left out when the path file defines the cutter (APT CUTTER/).
Job parseJob(const std::string& text, const std::string& source, bool checkMemory = true,
             const std::string& pathOverride = "");
Job loadJobFile(const std::string& path, bool checkMemory = true,
                const std::string& pathOverride = "");

// Refuses grids whose heights would not fit in memory, naming the size they need.
void checkGridFitsMemory(const GridSpec& grid, const std::string& field);

// Refuses a path whose exact simulation's culling scene would not fit in memory (an
// estimate from the moves' footprints, measured costs in job.cpp), naming the bytes.
void checkSceneFitsMemory(const Job& job);

// Refuses a path with a tip beyond +-1e6 mm (1 km) in x, y or z, as the job's own
// numbers are bounded: the geometry's squares and tile counts stay far from
// overflow. Names "file:line" from `lines` (ToolPathFile::moveLines) when given.
void checkPathMagnitudes(const ToolPath& path, const std::vector<int64_t>& lines,
                         const std::string& file);

// /proc/meminfo's MemAvailable, bytes (8 GiB when it cannot be read).
double availableMemoryBytes();

// The job as JSON (the inputs echoed into report.json).
nlohmann::json jobToJson(const Job& job);

}  // namespace scallop
