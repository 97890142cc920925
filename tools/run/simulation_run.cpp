#include "tools/run/simulation_run.h"

#include <fmt/core.h>

#include <cstdio>
#include <filesystem>

#include "raycast/simulation.h"
#include "raycast/stamp_caster.h"
#include "sweep/input_error.h"
#include "tools/io/atomic_file.h"
#include "tools/io/height_images.h"
#include "tools/io/job.h"
#include "tools/render/preview_png.h"
#include "tools/run/memory_limits.h"
#include "tools/run/path_report.h"
#include "tools/run/report.h"
#include "tools/run/stopwatch.h"
#include "tools/run/tiled_simulation.h"

namespace scallop {

using nlohmann::json;

namespace {

// The whole map in memory: heights, then the four outputs and the design comparison.
json runInMemory(const Job& job, const RunSettings& settings, Clock::time_point tStart) {
  const GridSpec grid = job.grid();
  const json pathFile = job.isRaster ? json() : pathFileReport(job, settings.quiet);
  if (!settings.quiet)
    std::fprintf(stderr,
                 "scallop: %s: %s cutter R=%g mm, %zu cutting moves, %lld x %lld cells of %g mm\n",
                 job.source.c_str(), toString(job.cutter.type), job.cutter.radius,
                 job.path.cuttingMoves(), (long long)grid.nx, (long long)grid.ny, grid.spacing);

  SimulationOptions options;
  options.cast.progress = settings.progress;
  SimulationResult sim;
  double stampStep = 0;  // mm, --method stamp only
  if (settings.method == "stamp") {
    // The classical z-map baseline (raycast/stamp_caster.h), reported in the same slots.
    StampOptions stamp;
    stamp.progress = options.cast.progress;
    StampSimulationResult st =
        simulateStamped(job.cutter, job.path, job.stock, grid, stamp);
    sim.map = std::move(st.map);
    sim.scene.segments = st.segments;
    sim.cast.cells = st.stamp.cells;
    sim.cast.exactEvaluations = st.stamp.exactEvaluations;
    sim.cast.seconds = st.stamp.seconds;
    stampStep = st.stamp.minStep;
  } else {
    sim = simulate(job.cutter, job.path, job.stock, grid, options);
  }
  if (settings.computed) settings.computed();

  // --- Outputs, each written to a temporary name and renamed when complete. ---------
  namespace fs = std::filesystem;
  const auto tWrite = Clock::now();
  const fs::path dir(settings.outDir);
  const std::string title = simulationTitle(job);
  writeHeightsExr(sim.map, (dir / "heights.exr").string());
  writeHeightsGsf(sim.map, (dir / "heights.gsf").string(), title);
  PreviewOptions preview;
  preview.title = title;
  writePreviewPng(sim.map, (dir / "preview.png").string(), preview);

  RunRecord run;
  run.design = job.design
                   ? designReport(job, sim.map, settings.outDir, settings.quiet)
                   : json();
  run.writeSeconds = secondsSince(tWrite);
  run.jobSource = job.source;
  run.inputs = jobToJson(job);
  run.grid = grid;
  run.method = settings.method;
  run.stampStepMm = stampStep;
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
  run.pathFile = pathFile;
  run.totalSeconds = secondsSince(tStart);
  const json report = simulationReport(run);
  writeReport(report, settings.outDir);
  return report;
}

}  // namespace

std::string simulationTitle(const Job& job) {
  return "scallop " + std::string(toString(job.cutter.type)) +
         " R=" + fmt::format("{:g}", job.cutter.radius) + " MM";
}

RunOutcome runSimulation(const Job& job, const RunSettings& settings) {
  const auto tStart = Clock::now();
  const bool exact = settings.method == "exact";
  const bool banded = settings.tiled || settings.tileRows > 0 || !settings.bands.empty();
  if (job.design && (!exact || banded))
    throw InputError(job.source + ": design",
                     "the design comparison needs --method exact and the whole map in memory "
                     "(not --tiled, --tile-rows or --bands)");
  // Fail before the long computation, not after it.
  if (exact) checkSceneFitsMemory(job);
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

}  // namespace scallop
