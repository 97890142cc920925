#include "tools/run/simulation_run.h"

#include <fmt/core.h>

#include <cstdio>
#include <filesystem>

#include "base/input_error.h"
#include "raycast/simulation.h"
#include "raycast/stamp_caster.h"
#include "tools/io/atomic_file.h"
#include "tools/io/height_images.h"
#include "tools/io/job.h"
#include "tools/render/preview_png.h"
#include "tools/run/feed_mark_report.h"
#include "tools/run/memory_limits.h"
#include "tools/run/path_report.h"
#include "tools/run/report.h"
#include "tools/run/stopwatch.h"
#include "tools/run/tiled_simulation.h"

namespace scallop {

using nlohmann::json;

namespace {

// The heights of the whole map in memory, by the exact sweep or the stamp baseline.
struct InMemoryHeights {
  SimulationResult sim;
  double stampStepMm = 0;  // --method stamp only
  json pathFile;           // pathFileReport() for a job with a path file
};

InMemoryHeights computeHeights(const Job& job, const RunSettings& settings) {
  const GridSpec grid = job.grid();
  InMemoryHeights out;
  out.pathFile = job.isRaster ? json() : pathFileReport(job, settings.quiet);
  if (!settings.quiet)
    std::fprintf(stderr,
                 "scallop: %s: %s cutter R=%g mm, %zu cutting moves, %lld x %lld cells of %g "
                 "mm%s\n",
                 job.source.c_str(), toString(job.cutter.type), job.cutter.radius,
                 job.path.cuttingMoves(), (long long)grid.nx, (long long)grid.ny, grid.spacing,
                 job.cutting.teeth() ? ", teeth" : "");

  SimulationOptions options;
  options.cast.progress = settings.progress;
  options.cutting = job.cutting;
  if (settings.method == "stamp") {
    // The classical z-map baseline (raycast/stamp_caster.h), reported in the same slots.
    StampOptions stamp;
    stamp.progress = options.cast.progress;
    StampSimulationResult st = simulateStamped(job.cutter, job.path, job.stock, grid, stamp);
    out.sim.map = std::move(st.map);
    out.sim.scene.segments = st.segments;
    out.sim.cast.cells = st.stamp.cells;
    out.sim.cast.exactEvaluations = st.stamp.exactEvaluations;
    out.sim.cast.seconds = st.stamp.seconds;
    out.stampStepMm = st.stamp.minStep;
  } else {
    out.sim = simulate(job.cutter, job.path, job.stock, grid, options);
  }
  if (settings.computed) settings.computed();
  return out;
}

// The record of an in-memory run, but for the design section and the timings of
// writing and in all.
RunRecord inMemoryRecord(const Job& job, const RunSettings& settings, const InMemoryHeights& h) {
  const SimulationResult& sim = h.sim;
  RunRecord run;
  run.jobSource = job.source;
  run.inputs = jobToJson(job);
  run.grid = job.grid();
  run.method = settings.method;
  run.stampStepMm = h.stampStepMm;
  run.cuttingMoves = int64_t(job.path.cuttingMoves());
  run.sweptSegments = int64_t(sim.scene.segments);
  run.cullingTiles = int64_t(sim.scene.tiles);
  run.requestedThreads = settings.threads;
  run.sceneSeconds = sim.scene.buildSeconds;
  run.castSeconds = sim.cast.seconds;
  run.minHeight = sim.map.minHeight();
  run.maxHeight = sim.map.maxHeight();
  run.exactEvaluations = double(sim.cast.exactEvaluations);
  if (job.isRaster) run.raster = rasterMeasurements(job, sim.map);
  run.surfaceStats = mapSurfaceStatsJson(sim.map);
  run.pathFile = h.pathFile;
  run.feedMarks = feedMarksReport(job, sim.map);
  return run;
}

// The whole map in memory: heights, then the four outputs and the design comparison.
json runInMemory(const Job& job, const RunSettings& settings, Clock::time_point tStart) {
  const InMemoryHeights h = computeHeights(job, settings);
  const ZMap& map = h.sim.map;

  // --- Outputs, each written to a temporary name and renamed when complete. ---------
  namespace fs = std::filesystem;
  const auto tWrite = Clock::now();
  const fs::path dir(settings.outDir);
  const std::string title = simulationTitle(job);
  writeHeightsExr(map, (dir / "heights.exr").string());
  writeHeightsGsf(map, (dir / "heights.gsf").string(), title);
  PreviewOptions preview;
  preview.title = previewTitle(title);
  preview.uncutHeight = job.stock.max.z;  // the map's initial height (raycast/simulation.h)
  writePreviewPng(map, (dir / "preview.png").string(), preview);

  RunRecord run = inMemoryRecord(job, settings, h);
  run.design = job.design ? designReport(job, map, settings.outDir, settings.quiet) : json();
  run.writeSeconds = secondsSince(tWrite);
  run.totalSeconds = secondsSince(tStart);
  const json report = simulationReport(run);
  writeReport(report, settings.outDir);
  return report;
}

// What runSimulation refuses before the long computation, whatever the outputs.
void checkRunnable(const Job& job, bool exact, bool banded) {
  if (job.cutting.teeth() && !exact)
    throw InputError("--method",
                     "stamp: the stamping baseline stamps the solid of revolution "
                     "and has no cutting edges; the job's cutting.model \"teeth\" "
                     "needs --method exact");
  if (job.design && (!exact || banded))
    throw InputError(job.source + ": design",
                     "the design comparison needs --method exact and the whole map in memory "
                     "(not --tiled, --tile-rows or --bands)");
  if (exact) checkSceneFitsMemory(job);
}

}  // namespace

std::string simulationTitle(const Job& job) {
  return "scallop " + std::string(toString(job.cutter.type)) +
         " R=" + fmt::format("{:g}", job.cutter.radius) + " MM";
}

std::string previewTitle(const std::string& simulationTitle) {
  const std::string upper = " MM";
  const size_t n = simulationTitle.size();
  if (n < upper.size() || simulationTitle.compare(n - upper.size(), upper.size(), upper) != 0)
    return simulationTitle;
  return simulationTitle.substr(0, n - upper.size()) + " mm";
}

RunOutcome runSimulation(const Job& job, const RunSettings& settings) {
  const auto tStart = Clock::now();
  const bool exact = settings.method == "exact";
  const bool banded = settings.tiled || settings.tileRows > 0 || !settings.bands.empty();
  // Fail before the long computation, not after it.
  checkRunnable(job, exact, banded);
  ensureWritableDirectory(settings.outDir);

  if (!exact && banded)
    throw InputError("--method", "bands (--tiled, --tile-rows, --bands) need --method exact");
  if (banded) return runTiledSimulation(job, settings);
  if (exact && !gridFitsMemory(job, settings.outDir)) {
    if (job.design)
      throw InputError(job.source + ": design",
                       "the map does not fit in memory, which the design comparison needs; use a "
                       "larger grid.spacing");
    return runTiledSimulation(job, settings);
  }
  return {RunOutcome::Kind::kInMemory, runInMemory(job, settings, tStart)};
}

ComputedSimulation computeSimulation(const Job& job, const RunSettings& settings) {
  const auto tStart = Clock::now();
  checkRunnable(job, settings.method == "exact", false);
  checkGridFitsMemory(job.grid(), job.source + ": grid.spacing");
  InMemoryHeights h = computeHeights(job, settings);
  RunRecord run = inMemoryRecord(job, settings, h);
  // No outDir: the comparison without its picture.
  run.design = job.design ? designReport(job, h.sim.map, "", settings.quiet) : json();
  run.totalSeconds = secondsSince(tStart);
  json report = simulationReport(run);
  report["outputs"] = json::array();
  return {std::move(h.sim.map), std::move(report)};
}

}  // namespace scallop
