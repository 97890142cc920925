// `scallop simulate`: runs a job and writes heights.exr, heights.gsf, preview.png and
// report.json into an output folder (CONVENTIONS.md "Height images").
#pragma once

#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "raycast/zmap.h"

namespace scallop {

struct Job;

struct SimulateArgs {
  std::string jobFile;  // empty: the built-in default job
  std::string pathFile;  // --path: replaces the job's path (tools/tool_path_file.h)
  std::string outDir = "scallop-out";
  int threads = 0;               // 0: all cores
  bool json = false;             // print report.json on stdout
  std::string method = "exact";  // "exact" or "stamp" (raycast/stamp_caster.h)
  // Bands of rows (tools/tiled_simulation.h); also chosen when the map cannot be held.
  bool tiled = false;
  int64_t tileRows = 0;  // rows per band, 0: bands of <= 256 MB
  std::string bands;     // "K:M": only bands K..M-1, written as DIR/band-K.raw for merge
};

// For a raster job: floor_z and the largest scallop between the first and the last
// pass on `map` (report.json "measurements"); a band of a map gives its own share.
nlohmann::json rasterMeasurements(const Job& job, const ZMap& map);

// Returns the process exit status; throws InputError for bad input.
int runSimulate(const SimulateArgs& args);

}  // namespace scallop
