#include "tools/simulate_command.h"

#include <fmt/core.h>
#include <tbb/info.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "analysis/scallop_profile.h"
#include "raycast/simulation.h"
#include "raycast/stamp_caster.h"
#include "sweep/input_error.h"
#include "tools/atomic_file.h"
#include "tools/command.h"
#include "tools/height_images.h"
#include "tools/interrupt.h"
#include "tools/job.h"
#include "tools/path_report.h"
#include "tools/progress.h"
#include "tools/stats_command.h"
#include "tools/tiled_simulation.h"

namespace scallop {

using nlohmann::json;

namespace {

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

// For a raster: the highest point left above the floor between the first and the last
// pass (where both neighbours have cut), i.e. the largest scallop on the map, mm.
json rasterMeasurements(const Job& job, const ZMap& map) {
  json m;
  const double floorZ = job.stock.max.z - job.raster.depth;
  m["floor_z"] = floorZ;
  const bool alongX = job.raster.direction == 'x';
  const double crossMin = alongX ? job.stock.min.y : job.stock.min.x;
  const double crossMax = alongX ? job.stock.max.y : job.stock.max.x;
  const int passes = int(std::floor((crossMax - crossMin) / job.raster.stepOver + 1e-9)) + 1;
  if (passes < 2) return m;
  const double lastPass = crossMin + (passes - 1) * job.raster.stepOver;
  double top = -HUGE_VAL;
  const GridSpec& g = map.grid();
  for (int64_t j = 0; j < g.ny; ++j) {
    for (int64_t i = 0; i < g.nx; ++i) {
      const double c = alongX ? g.cellCentreY(j) : g.cellCentreX(i);
      if (c >= crossMin && c <= lastPass) top = std::max(top, map.at(i, j));
    }
  }
  m["max_scallop_height"] = top - floorZ;
  return m;
}

int runSimulate(const SimulateArgs& args) {
  const auto tStart = std::chrono::steady_clock::now();
  // A grid too large to hold is computed in bands instead (tools/tiled_simulation.h).
  const bool exact = args.method == "exact";
  if (!args.pathFile.empty() && args.jobFile.empty())
    throw InputError("--path",
                     "needs a JOB file for the tool (unless the path has CUTTER/), "
                     "stock and grid");
  Job job = args.jobFile.empty() ? parseJob(defaultJobJson(), "built-in default job", !exact)
                                 : loadJobFile(args.jobFile, !exact, args.pathFile);
  if (job.design && (!exact || args.tiled || args.tileRows > 0 || !args.bands.empty()))
    throw InputError(job.source + ": design",
                     "the design comparison needs --method exact and the whole map in memory "
                     "(not --tiled, --tile-rows or --bands)");
  // Fail before the long computation, not after it.
  if (exact) checkSceneFitsMemory(job);
  ensureWritableDirectory(args.outDir);

  const GridSpec grid = job.grid();
  if (!exact && (args.tiled || args.tileRows > 0 || !args.bands.empty()))
    throw InputError("--method", "bands (--tiled, --tile-rows, --bands) need --method exact");
  if (args.tiled || args.tileRows > 0 || !args.bands.empty()) return runTiledSimulate(args, job);
  if (exact && !gridFitsMemory(job, args.outDir)) {
    if (job.design)
      throw InputError(job.source + ": design",
                       "the map does not fit in memory, which the design comparison needs; use a "
                       "larger grid.spacing");
    return runTiledSimulate(args, job);
  }
  const json pathFile = job.isRaster ? json() : pathFileReport(job, args.json);
  if (!args.json)
    std::fprintf(stderr,
                 "scallop: %s: %s cutter R=%g mm, %zu cutting moves, %lld x %lld cells of %g mm\n",
                 job.source.c_str(), toString(job.cutter.type), job.cutter.radius,
                 job.path.cuttingMoves(), (long long)grid.nx, (long long)grid.ny, grid.spacing);

  SimulationOptions options;
  ProgressBar bar("simulating");
  options.cast.progress = [&bar](int64_t done, int64_t total) { bar.update(done, total); };
  SimulationResult sim;
  double stampStep = 0;  // mm, --method stamp only
  if (args.method == "stamp") {
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
  bar.finish();
  throwIfInterrupted();  // a Ctrl-C during the last tiles: write nothing

  // --- Outputs, each written to a temporary name and renamed when complete. ---------
  namespace fs = std::filesystem;
  const auto tWrite = std::chrono::steady_clock::now();
  const std::string title = "scallop " + std::string(toString(job.cutter.type)) +
                            " R=" + fmt::format("{:g}", job.cutter.radius) + " MM";
  const std::string exr = (fs::path(args.outDir) / "heights.exr").string();
  const std::string gsf = (fs::path(args.outDir) / "heights.gsf").string();
  const std::string png = (fs::path(args.outDir) / "preview.png").string();
  const std::string report = (fs::path(args.outDir) / "report.json").string();
  writeHeightsExr(sim.map, exr);
  writeHeightsGsf(sim.map, gsf, title);
  PreviewOptions preview;
  preview.title = title;
  writePreviewPng(sim.map, png, preview);
  const json design =
      job.design ? designReport(job, sim.map, args.outDir, args.json) : json();
  const double writeSeconds = secondsSince(tWrite);

  json r;
  r["scallop_version"] = "0.1.0";
  r["job_source"] = job.source;
  r["inputs"] = jobToJson(job);
  r["grid"] = {{"origin", {grid.originX, grid.originY}},
               {"spacing", grid.spacing},
               {"nx", grid.nx},
               {"ny", grid.ny},
               {"cell_centre", "origin + (index + 1/2) * spacing"},
               {"units", "mm"}};
  r["method"] = args.method;
  if (args.method == "stamp") r["stamp_step_mm"] = stampStep;
  r["sweep"] = {{"cutting_moves", job.path.cuttingMoves()},
                {"swept_segments", sim.scene.segments},
                {"culling_tiles", sim.scene.tiles}};
  r["timings_s"] = {{"scene_build", sim.scene.buildSeconds},
                    {"cast", sim.cast.seconds},
                    {"write", writeSeconds},
                    {"total", secondsSince(tStart)}};
  r["threads"] = args.threads > 0 ? args.threads : tbb::info::default_concurrency();
  json meas = {
      {"min_height", sim.map.minHeight()},
      {"max_height", sim.map.maxHeight()},
      {"exact_evaluations_per_cell", sim.cast.evaluationsPerCell()},
      {"mcells_per_s", sim.cast.seconds > 0 ? sim.cast.cells / sim.cast.seconds / 1e6 : 0.0}};
  if (job.isRaster) meas.update(rasterMeasurements(job, sim.map));
  r["measurements"] = meas;
  r["surface_stats"] = mapSurfaceStatsJson(sim.map);
  r["outputs"] = {"heights.exr", "heights.gsf", "preview.png", "report.json"};
  if (!pathFile.is_null()) r["path_file"] = pathFile;
  if (!design.is_null()) r["design"] = design, r["outputs"].push_back("deviation.png");
  const std::string reportText = r.dump(2) + "\n";
  writeFileAtomically(report, [&](const std::string& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << reportText;
    if (!out.flush()) throw InputError(report, "cannot write the report");
  });

  if (args.json) {
    std::fputs(reportText.c_str(), stdout);
  } else {
    std::printf(
        "heights: %lld x %lld cells, z in [%.6f, %.6f] mm, %.2f exact evaluations per cell, %.2f "
        "s\n",
        (long long)grid.nx, (long long)grid.ny, sim.map.minHeight(), sim.map.maxHeight(),
        sim.cast.evaluationsPerCell(), sim.cast.seconds);
    if (meas.contains("max_scallop_height"))
      std::printf("largest scallop between passes: %.6f mm\n",
                  meas["max_scallop_height"].get<double>());
    std::printf("wrote %s\n      %s\n      %s\n      %s\n", exr.c_str(), gsf.c_str(), png.c_str(),
                report.c_str());
  }
  return 0;
}

namespace {

constexpr const char* kSimulateHelp =
    "Simulate a job file and write DIR/heights.exr (float32 channel Z, mm), DIR/heights.gsf\n"
    "(Gwyddion, metres), DIR/preview.png (shaded colour map with scale) and\n"
    "DIR/report.json (inputs, grid, timings, measurements).\n"
    "Without JOB, runs the built-in default job (see --print-default-job):\n"
    "a bull cutter R=3 r=1 raster over 20x20 mm, lead 5 deg, step-over 2.884 mm.\n"
    "Job file keys: tool{type,radius,corner_radius,flute_length}, stock{min,max},\n"
    "grid{spacing}, path{raster{direction,step_over,depth,lead_deg,tilt_deg,zigzag,\n"
    "segment_length} | file},\n"
    "design{stl, gouge_tolerance (mm, default 0.001)}: adds machined - design statistics,\n"
    "gouges with the moves (file lines) that made them, and DIR/deviation.png.\n"
    "Path files by extension: .cl .apt .cls (APT CL data: GOTO, CUTTER, RAPID, ...),\n"
    ".nc .ngc .gcode .tap (G-code G0-G3, G17-G21, G90/G91), .txt (x y z [i j k] lines).\n"
    "Without \"tool\", an APT CUTTER/ statement defines the cutter.";

}  // namespace

void addThreadsOption(CLI::App& command, CommonOptions& common) {
  command
      .add_option("--threads", common.threads,
                  "Worker threads (default: all cores); results do not depend on it")
      ->check(CLI::Range(0, 1 << 16));
}

Command addSimulateCommand(CLI::App& parent, CommonOptions& common) {
  auto args = std::make_shared<SimulateArgs>();
  auto printDefault = std::make_shared<bool>(false);
  CLI::App* app = parent.add_subcommand("simulate", kSimulateHelp);
  app->add_option("JOB", args->jobFile, "Job file (JSON); omit for the built-in default job");
  app->add_option("-o,--output", args->outDir,
                  "Output folder, created if missing; other files in it are left alone")
      ->capture_default_str();
  app->add_option("--path", args->pathFile,
                  "Tool-path file that replaces the job's path (format from the extension;\n"
                  "needs JOB for the stock and grid)");
  addThreadsOption(*app, common);
  app->add_flag("--json", args->json, "Print report.json on stdout (and nothing else there)");
  app->add_option("--method", args->method,
                  "exact: exact swept-solid heights (default); stamp: classical z-map baseline,\n"
                  "the cutter stamped along each move at a step whose scallop is <= 1e-4 mm")
      ->check(CLI::IsMember({"exact", "stamp"}))
      ->capture_default_str();
  app->add_flag("--tiled", args->tiled,
                "Compute and write the map in bands of rows with bounded memory (tiled\n"
                "OpenEXR, streamed GSF); chosen by itself when the map does not fit in memory");
  app->add_option("--tile-rows", args->tileRows,
                  "Rows per band (default: bands of <= 256 MB of heights); implies --tiled")
      ->check(CLI::PositiveNumber);
  app->add_option("--bands", args->bands,
                  "K:M: compute only bands K..M-1 and write DIR/band-K.raw (float64 mm) and\n"
                  "DIR/band-K.json; `scallop merge DIR` assembles the outputs when all exist");
  app->add_flag("--print-default-job", *printDefault,
                "Print the built-in default job file and exit");
  return {app, [args, printDefault, &common]() {
            if (*printDefault) {
              std::puts(defaultJobJson());
              return 0;
            }
            args->threads = common.threads;
            return runSimulate(*args);
          }};
}

}  // namespace scallop
