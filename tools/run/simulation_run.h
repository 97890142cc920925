// A simulation run: a job's exact heights computed and written into an output folder
// as heights.exr, heights.gsf, preview.png and report.json (CONVENTIONS.md "Height
// images"), with the whole map in memory or band by band (tools/run/tiled_simulation.h)
// when it does not fit or bands are asked for. `scallop simulate` is this plus its
// command line (tools/cli/simulate_command.cpp); the Python module's simulate() is
// computeSimulation(), the same in-memory run without the files.
#pragma once

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "raycast/zmap.h"

namespace scallop {

struct Job;

struct RunSettings {
  std::string outDir = "scallop-out";
  int threads = 0;               // as given to --threads (0: all cores), for the report
  bool quiet = false;            // nothing on stderr but warnings (simulate --json)
  std::string method = "exact";  // "exact" or "stamp" (raycast/stamp_caster.h)
  // Bands of rows (tools/run/tiled_simulation.h); also chosen when the map cannot be held.
  bool tiled = false;
  int64_t tileRows = 0;  // rows per band, 0: bands of <= 256 MB
  std::string bands;     // "K:M": only bands K..M-1, written as DIR/band-K.raw for merge
  // Also DIR/view.png, the ray-traced 3-D picture of `scallop render` with its defaults
  // (tools/render/render_png.h); the whole map in memory only.
  bool view = false;

  // Called after every tile of cells with the cells done and in all. It may throw to
  // cancel the run (the CLI's Ctrl-C, tools/cli/interrupt.h); nothing is written then.
  std::function<void(int64_t done, int64_t total)> progress;
  // Called once when every height is computed, before any output is written.
  std::function<void()> computed;
};

struct RunOutcome {
  enum class Kind { kInMemory, kTiled, kBands } kind = Kind::kInMemory;
  // report.json's content; for kBands, the summary of the band files written.
  nlohmann::json document;
};

// Runs `job` (the run's own: a run in bands may free its moves, runTiledSimulation) as
// `settings` ask. Throws InputError for a run that cannot be done (the
// design comparison in bands, a map or scene larger than memory and disk allow, an
// output folder that cannot be written).
RunOutcome runSimulation(Job job, const RunSettings& settings);

// The heights of a run held in memory, and its report.json document.
struct ComputedSimulation {
  ZMap map;
  nlohmann::json report;
};

// The in-memory run of runSimulation without writing anything (settings.outDir,
// tiled, tileRows and bands are not used): the heights, and the report runSimulation
// would write, with "outputs" empty and the design section (if any) without its
// picture ("image", "image_colour_range_mm"). Throws InputError for a job whose map or
// scene does not fit in memory.
ComputedSimulation computeSimulation(const Job& job, const RunSettings& settings);

// The title of a run's height images, e.g. "scallop bull R=3 MM". The capitals date
// from the first preview's bitmap font, which had no lower case; heights.gsf and the
// band files keep that spelling, since scripts/example-heights.md5 pins the GSF's bytes.
std::string simulationTitle(const Job& job);
// preview.png's caption: a simulationTitle with its unit spelt "mm".
std::string previewTitle(const std::string& simulationTitle);

}  // namespace scallop
