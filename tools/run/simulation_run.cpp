#include "tools/run/simulation_run.h"

#include <fmt/core.h>

#include <cstdio>
#include <filesystem>
#include <optional>
#include <utility>

#include "base/input_error.h"
#include "raycast/simulation.h"
#include "raycast/stamp_caster.h"
#include "tools/io/atomic_file.h"
#include "tools/io/height_formats.h"
#include "tools/io/height_images.h"
#include "tools/io/job.h"
#include "tools/render/preview_png.h"
#include "tools/render/render_png.h"
#include "tools/run/feed_mark_report.h"
#include "tools/run/memory_limits.h"
#include "tools/run/normal_deviation_report.h"
#include "tools/run/path_report.h"
#include "tools/run/report.h"
#include "tools/run/simulation_plan.h"
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

InMemoryHeights computeHeights(const Job& job, const SimulationPlan& plan,
                               const RunSettings& settings) {
  const GridSpec& grid = plan.grid;
  InMemoryHeights out;
  out.pathFile = job.isRaster ? json() : pathFileReport(job, settings.quiet);
  if (!settings.quiet) std::fprintf(stderr, "scallop: %s\n", plan.banner.c_str());

  SimulationOptions options;
  options.cast.progress = settings.progress;
  options.cutting = job.cutting;
  options.frame = job.frame;
  if (job.shapedStock()) {
    if (settings.method == "stamp")
      throw InputError("stock", "the stamp method starts from a box; use a box stock");
    options.fillStock = [&job](ZMap& map) { job.fillStockHeights(map); };
  }
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
RunRecord inMemoryRecord(const Job& job, const SimulationPlan& plan, const RunSettings& settings,
                         const InMemoryHeights& h) {
  const SimulationResult& sim = h.sim;
  RunRecord run;
  run.jobSource = job.source;
  run.inputs = jobToJson(job);
  run.grid = plan.grid;
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
  run.unprovenSearches = int64_t(sim.cast.unprovenSearches);
  if (sim.cast.unprovenSearches > 0)
    std::fprintf(stderr,
                 "scallop: warning: %llu cells hold a height whose proof did not close (a turning "
                 "move's certified search ran out of samples): a real point of the swept solid, "
                 "possibly above its lowest (docs/algorithm.md \"Open holes\")\n",
                 (unsigned long long)sim.cast.unprovenSearches);
  // The raster's floor and scallops are measured vertically in the part frame.
  if (job.isRaster && !job.frame) run.raster = rasterMeasurements(job, sim.map);
  if (job.frame || job.shapedStock()) run.frameCells = frameCellsJson(sim.frameCells);
  run.surfaceStats = mapSurfaceStatsJson(sim.map);
  run.pathFile = h.pathFile;
  run.feedMarks = feedMarksReport(job, sim.map);
  return run;
}

// The whole map in memory: heights, then the four outputs and the design comparison.
json runInMemory(const Job& job, const SimulationPlan& plan, const RunSettings& settings,
                 Clock::time_point tStart) {
  const InMemoryHeights h = computeHeights(job, plan, settings);
  const ZMap& map = h.sim.map;

  // --- Outputs, each written to a temporary name and renamed when complete. ---------
  namespace fs = std::filesystem;
  const auto tWrite = Clock::now();
  const fs::path dir(settings.outDir);
  const std::string title = simulationTitle(job);
  const std::string frame = job.frame ? job.frame->describe() : "";
  for (const char* name : {"heights.exr", "heights.gsf"}) {
    const std::string path = (dir / name).string();
    heightFormatOf(path, false).write(map, path, title, frame);
  }
  PreviewOptions preview;
  preview.title = previewTitle(title);
  preview.uncutHeight = job.stockTop();  // the map's initial height (raycast/simulation.h)
  // A stock of any shape starts each cell at its own height: the preview tells the cells
  // still there from the cut ones by them (one more map of the grid while it is drawn).
  std::optional<ZMap> stockHeights;
  if (job.shapedStock()) {
    stockHeights.emplace(map.grid(), job.stock.max.z);
    job.fillStockHeights(*stockHeights);
    preview.stockHeights = &*stockHeights;
  }
  writePreviewPng(map, (dir / "preview.png").string(), preview);
  if (settings.view) {
    RenderOptions view;
    view.title = preview.title;
    view.uncutHeight = preview.uncutHeight;
    writeRenderPng(map, wholeMap(map.grid()), (dir / "view.png").string(), view, "--view");
  }
  stockHeights.reset();

  RunRecord run = inMemoryRecord(job, plan, settings, h);
  run.design = job.design ? designReport(job, map, settings.outDir, settings.quiet) : json();
  if (job.normalDeviation)
    run.design["normal_deviation"] = normalDeviationReport(job, settings.outDir, settings.quiet);
  run.writeSeconds = secondsSince(tWrite);
  run.totalSeconds = secondsSince(tStart);
  json report = simulationReport(run);
  if (settings.view) report["outputs"].push_back("view.png");
  writeReport(report, settings.outDir);
  return report;
}

// What runSimulation refuses before the long computation, whatever the outputs and
// the memory.
void checkRunnable(const Job& job, bool exact, bool banded) {
  if (job.cutting.teeth() && !exact)
    throw InputError("--method",
                     "stamp: the stamping baseline stamps the solid of revolution "
                     "and has no cutting edges; the job's cutting.model \"teeth\" "
                     "needs --method exact");
  if (job.frame && !exact)
    throw InputError("--method",
                     "stamp: the stamping baseline has no frames; grid.frame needs --method exact");
  if (job.design && (!exact || banded))
    throw InputError(job.source + ": design",
                     "the design comparison needs --method exact and the whole map in memory "
                     "(not --tiled, --tile-rows or --bands)");
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

RunOutcome runSimulation(Job job, const RunSettings& settings) {
  const auto tStart = Clock::now();
  const bool exact = settings.method == "exact";
  const bool banded = settings.tiled || settings.tileRows > 0 || !settings.bands.empty();
  // Fail before the long computation, not after it.
  checkRunnable(job, exact, banded);
  if (!exact && banded)
    throw InputError("--method", "bands (--tiled, --tile-rows, --bands) need --method exact");
  const SimulationPlan plan = planSimulation(job, settings);
  requireRunFitsMemory(job, plan.grid, plan.memory, false);
  ensureWritableDirectory(settings.outDir);

  if (plan.inBands && !plan.bandsAsked) {
    if (job.design)
      throw InputError(job.source + ": design",
                       plan.sceneBands
                           ? "the path's culling scene does not fit in memory whole, which the "
                             "design comparison needs; split the path into several jobs"
                           : "the map does not fit in memory, which the design comparison needs; "
                             "use a larger grid.spacing");
    requireBandsFitDisk(job, plan, settings.outDir);
  }
  if (plan.inBands && settings.view)
    throw InputError("--view", "needs the whole map in memory, and this run is in bands (--tiled, "
                               "--tile-rows, --bands, or a map too large); render its heights "
                               "afterwards with `scallop render DIR/heights.exr -o view.png`");
  if (plan.inBands) return runTiledSimulation(std::move(job), plan, settings);
  return {RunOutcome::Kind::kInMemory, runInMemory(job, plan, settings, tStart)};
}

ComputedSimulation computeSimulation(const Job& job, const RunSettings& settings) {
  const auto tStart = Clock::now();
  checkRunnable(job, settings.method == "exact", false);
  // The whole map in memory, whatever bands the settings ask for.
  RunSettings whole = settings;
  whole.tiled = false;
  whole.tileRows = 0;
  whole.bands.clear();
  const SimulationPlan plan = planSimulation(job, whole);
  requireRunFitsMemory(job, plan.grid, plan.memory, true);
  InMemoryHeights h = computeHeights(job, plan, settings);
  RunRecord run = inMemoryRecord(job, plan, settings, h);
  // No outDir: the comparison without its picture.
  run.design = job.design ? designReport(job, h.sim.map, "", settings.quiet) : json();
  if (job.normalDeviation)
    run.design["normal_deviation"] = normalDeviationReport(job, "", settings.quiet);
  run.totalSeconds = secondsSince(tStart);
  json report = simulationReport(run);
  report["outputs"] = json::array();
  return {std::move(h.sim.map), std::move(report)};
}

}  // namespace scallop
