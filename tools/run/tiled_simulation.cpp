// Tiled simulation (tiled_simulation.h); `simulate --bands` writes band files
// (band_files.h) whose "run" description is identical in every band of one run (scallop
// version, job echo, grid, layout, scene stats), and merge refuses bands whose
// fingerprint of it differs.
#include "tools/run/tiled_simulation.h"

#include <fmt/core.h>
#include <sys/statvfs.h>
#include <tbb/info.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "base/input_error.h"
#include "base/version.h"
#include "raycast/frame_depth.h"
#include "raycast/simulation.h"
#include "tools/io/atomic_file.h"
#include "tools/io/job.h"
#include "tools/io/md5.h"
#include "tools/render/preview_png.h"
#include "tools/run/band_files.h"
#include "tools/run/feed_mark_report.h"
#include "tools/run/job_loader.h"
#include "tools/run/memory_limits.h"
#include "tools/run/path_report.h"
#include "tools/run/report.h"
#include "tools/run/stopwatch.h"

namespace scallop {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

constexpr double kGiB = double(1ull << 30);

// The MD5 of a tool-path file, so that bands of one job agree on its content too.
std::string fileMd5(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot read the tool-path file");
  Md5 md5;
  std::vector<char> chunk(1 << 20);
  while (in.read(chunk.data(), std::streamsize(chunk.size())) || in.gcount() > 0)
    md5.update(chunk.data(), size_t(in.gcount()));
  return md5.hexDigest();
}

// The scene of the moves that may reach `window`, swept from the path file re-read as a
// stream: the entries buildScene makes of the whole path with that window, bit for bit
// (ToolPathSweeper), with the whole program's culling tiles (plan.cellsPerMove).
std::unique_ptr<SweptScene> streamedBandScene(const Job& job, const SimulationPlan& plan,
                                              const SimulationOptions& options,
                                              const SweepWindow& window) {
  ToolPathSweeper sweeper(
      job.path.cutters.empty() ? std::vector<Cutter>{job.cutter} : job.path.cutters,
      options.cutting, &window, plan.cuttingMoves);
  const size_t moves =
      streamJobPath(job, plan.streamPartMoves, [&](const ToolPath& part) { sweeper.add(part); });
  if (moves != plan.pathMoves)
    throw InputError(job.pathFile,
                     fmt::format("changed while it was being simulated: {} moves read again, {} "
                                 "the first time; run the job again",
                                 moves, plan.pathMoves));
  return buildSceneOfMoves(sweeper.finish(), job.stock, plan.grid.spacing, plan.cellsPerMove,
                           options);
}

}  // namespace

void requireBandsFitDisk(const Job& job, const SimulationPlan& plan, const std::string& outDir) {
  const GridSpec& grid = plan.grid;
  // heights.gsf takes 4 bytes a cell; zip-compressed float32 EXR at most about as much.
  const double need = 8.0 * double(grid.nx) * double(grid.ny);
  struct statvfs fsInfo {};
  const double free = ::statvfs(outDir.c_str(), &fsInfo) == 0
                          ? double(fsInfo.f_bavail) * double(fsInfo.f_frsize)
                          : 0.0;
  const bool imageSized = grid.nx <= INT32_MAX && grid.ny <= INT32_MAX;
  if (need > free || !imageSized) {
    requireRunFitsMemory(
        job, grid, plan.memory, true,
        fmt::format(
            "; in bands it would need {:.3g} GiB of disk in {}, where {:.3g} GiB are free{}",
            need / kGiB, outDir, free / kGiB,
            imageSized ? "" : ", and more rows or columns than an image"));
  }
  if (plan.sceneBands)
    std::fprintf(stderr,
                 "scallop: the culling scene of %zu cutting moves (%.1f GiB) does not fit in "
                 "memory; computing the map in %lld bands of %lld rows, each with the scene of "
                 "the moves that reach it (at most %.1f GiB a band)%s\n",
                 plan.memory.cuttingMoves, plan.memory.sceneBytes / kGiB,
                 (long long)plan.layout.bands, (long long)plan.layout.bandRows,
                 plan.memory.largestBandBytes / kGiB,
                 plan.streamPath ? ", reading the path file again for each band" : "");
  else
    std::fprintf(stderr,
                 "scallop: the %lld x %lld map does not fit in memory; computing it in %lld "
                 "bands of %lld rows (--tiled)\n",
                 (long long)grid.nx, (long long)grid.ny, (long long)plan.layout.bands,
                 (long long)plan.layout.bandRows);
}

RunOutcome runTiledSimulation(Job job, const SimulationPlan& plan, const RunSettings& settings) {
  const auto tStart = Clock::now();
  const GridSpec& grid = plan.grid;
  const BandLayout& layout = plan.layout;
  const bool partial = plan.partial;
  const int64_t first = plan.firstBand, end = plan.endBand;
  if (!settings.quiet) std::fprintf(stderr, "scallop: %s\n", plan.banner.c_str());

  // Before the computation: a leftover as large as a band could keep this run's own
  // band from fitting on the disk (band_files.h says why removing them is safe).
  if (partial)
    for (const std::string& leftover : removeBandTemporaries(settings.outDir, first, end))
      if (!settings.quiet)
        std::fprintf(stderr, "scallop: removed %s, left by a run of its band that was killed\n",
                     leftover.c_str());

  const int64_t totalCells = plan.cellsToCompute();
  int64_t doneCells = 0;
  SimulationOptions options;
  options.cutting = job.cutting;
  options.frame = job.frame;
  options.cast.progress = [&](int64_t done, int64_t) {
    if (settings.progress) settings.progress(doneCells + done, totalCells);
  };
  // One scene for every band, or (plan.sceneBands) one a band, of the moves that reach
  // it, built when the band starts: the same heights (sweepToolPath's window).
  std::unique_ptr<SweptScene> scene;
  if (!plan.sceneBands) {
    scene = buildScene(job.cutter, job.path, job.stock, grid.spacing, options);
    options.cast.progress(0, 0);  // a Ctrl-C during the build stops here (as in simulate())
  }
  const SceneStats sceneStats = scene ? scene->stats() : SceneStats();

  std::unique_ptr<TiledOutput> output;
  json run;
  if (partial) {
    // Everything a band file must agree on with the other bands of its run.
    run = {{"scallop_version", kScallopVersion},
           {"job_source", job.source},
           {"inputs", jobToJson(job)},
           {"title", simulationTitle(job)},
           {"grid", gridToJson(grid)},
           {"band_rows", layout.bandRows},
           {"bands", layout.bands},
           {"exr_tile_rows", layout.tileHeight},
           {"cutting_moves", plan.cuttingMoves}};
    // Per-band scenes differ from band to band: their sizes go with each band's stats.
    if (plan.sceneBands)
      run["scene_bands"] = true;
    else
      run["swept_segments"] = sceneStats.segments, run["culling_tiles"] = sceneStats.tiles;
    if (!job.isRaster) run["path_file_md5"] = fileMd5(job.pathFile);
    if (job.cutting.teeth()) run["feed_marks_plan"] = feedMarkPlan(job, grid);
    if (job.frame) run["frame"] = job.frame->describe(), run["uncut_height"] = job.stockTop();
  } else {
    TiledRun whole;
    whole.record.jobSource = job.source;
    whole.record.inputs = jobToJson(job);
    whole.record.grid = grid;
    whole.record.cuttingMoves = int64_t(plan.cuttingMoves);
    whole.record.sweptSegments = int64_t(sceneStats.segments);
    whole.record.cullingTiles = int64_t(sceneStats.tiles);
    whole.record.tiled = {{"bands", layout.bands},
                          {"band_rows", layout.bandRows},
                          {"exr_tile_rows", layout.tileHeight}};
    whole.title = simulationTitle(job);
    whole.exrTileRows = layout.tileHeight;
    whole.uncutHeight = job.stockTop();
    if (job.frame) whole.frame = job.frame->describe();
    if (job.cutting.teeth()) whole.feedMarksPlan = feedMarkPlan(job, grid);
    output = std::make_unique<TiledOutput>(whole, settings.outDir);
    if (!job.isRaster) output->setPathFile(pathFileReport(job, settings.quiet));
  }

  // Everything above that reads the moves is made: from here a streamed path is re-read
  // from its file, a band at a time.
  if (plan.streamPath) releasePathMoves(job);

  std::vector<std::string> written;
  const int threads = settings.threads > 0 ? settings.threads : tbb::info::default_concurrency();
  for (int64_t b = first; b < end; ++b) {
    ZMap band(layout.bandGrid(b, grid), job.stock.max.z);
    SceneStats bandScene = sceneStats;
    if (plan.sceneBands) {
      scene.reset();  // the last band's scene goes before this band's is built
      const SweepWindow window = cellWindow(band.grid());
      scene = plan.streamPath
                  ? streamedBandScene(job, plan, options, window)
                  : buildScene(job.cutter, job.path, job.stock, grid.spacing, options, &window);
      options.cast.progress(0, 0);
      bandScene = scene->stats();
    }
    if (job.frame) fillFrameStock(band, job.stock, *job.frame);
    if (job.shapedStock()) job.fillStockHeights(band);
    const CastStats cast = castZMap(*scene, band, options.cast);
    FrameCellCounts frameCells;
    if (job.frame) {
      cutToFrameDepth(*scene, band, job.stock, *job.frame);
      frameCells = finishFrameMap(band, *job.frame);
    }
    if (job.shapedStock()) frameCells = finishStockMap(band);
    doneCells += band.grid().cells();
    json stats = {{"rows", {layout.firstRow(b), layout.endRow(b, grid)}},
                  {"cells", cast.cells},
                  {"exact_evaluations", cast.exactEvaluations},
                  {"unproven_cells", cast.unprovenSearches},
                  {"cast_seconds", cast.seconds},
                  {"scene_build_seconds", bandScene.buildSeconds},
                  {"min_height", band.minHeight()},
                  {"max_height", band.maxHeight()},
                  {"threads", threads}};
    if (plan.sceneBands)
      stats["scene"] = {{"swept_segments", bandScene.segments},
                        {"culling_tiles", bandScene.tiles},
                        {"bytes", bandScene.bytes()}};
    if (job.isRaster && !job.frame) stats["raster"] = rasterMeasurements(job, band);
    if (job.frame || job.shapedStock()) stats["frame"] = frameCellsJson(frameCells);
    if (output) {
      output->add(band, stats);
    } else {
      writeBandFiles(settings.outDir, b, band, run, settings.tileRows, stats);
      written.push_back(fmt::format("band-{}.raw", b));
    }
  }
  if (settings.computed) settings.computed();

  if (partial) {
    const json summary = {{"bands", {first, end}},
                          {"of", layout.bands},
                          {"band_rows", layout.bandRows},
                          {"files", written},
                          {"seconds", secondsSince(tStart)}};
    return {RunOutcome::Kind::kBands, summary};
  }
  return {RunOutcome::Kind::kTiled,
          output->finish(sceneStats.buildSeconds, secondsSince(tStart), threads)};
}

TiledRun tiledRunFromBands(const json& run) {
  TiledRun out;
  out.record.jobSource = run.at("job_source").get<std::string>();
  out.record.inputs = run.at("inputs");
  out.record.grid = gridFromJson(run.at("grid"));
  out.record.cuttingMoves = run.at("cutting_moves").get<int64_t>();
  // Absent with a scene a band: the bands' stats carry theirs (TiledOutput::add).
  out.record.sweptSegments = run.value("swept_segments", int64_t(0));
  out.record.cullingTiles = run.value("culling_tiles", int64_t(0));
  out.record.tiled = {{"bands", run.at("bands")},
                      {"band_rows", run.at("band_rows")},
                      {"exr_tile_rows", run.at("exr_tile_rows")}};
  out.title = run.at("title").get<std::string>();
  out.exrTileRows = run.at("exr_tile_rows").get<int>();
  out.uncutHeight = out.record.inputs.at("stock").at("max").at(2).get<double>();
  if (run.contains("feed_marks_plan")) out.feedMarksPlan = run.at("feed_marks_plan");
  if (run.contains("frame")) out.frame = run.at("frame").get<std::string>();
  if (run.contains("uncut_height")) out.uncutHeight = run.at("uncut_height").get<double>();
  return out;
}

TiledOutput::TiledOutput(const TiledRun& run, const std::string& dir)
    : run_(run),
      dir_(dir),
      grid_(run.record.grid),
      writer_(grid_, (fs::path(dir) / "heights.exr").string(),
              (fs::path(dir) / "heights.gsf").string(), run.title, run.exrTileRows, run.frame) {
  // The same reduction as writePreviewPng's for the whole map: blocks of k x k cells
  // aligned at cell (0, 0), each keeping its minimum.
  const int64_t longSide = std::max(grid_.nx, grid_.ny);
  const int64_t maxPixels = std::max(16, PreviewOptions().maxPixels);
  poolFactor_ = (longSide + maxPixels - 1) / maxPixels;
  GridSpec pooled = grid_;
  pooled.spacing = grid_.spacing * double(poolFactor_);
  pooled.nx = (grid_.nx + poolFactor_ - 1) / poolFactor_;
  pooled.ny = (grid_.ny + poolFactor_ - 1) / poolFactor_;
  preview_ = ZMap(pooled, HUGE_VAL);
  if (!run.feedMarksPlan.is_null())
    feedMarks_ = std::make_unique<FeedMarkSampler>(run.feedMarksPlan, grid_);
}

void TiledOutput::add(const ZMap& band, const json& stats) {
  const auto t0 = Clock::now();
  writer_.append(band);
  if (feedMarks_) feedMarks_->add(band);
  const int64_t j0 = band.grid().offsetJ;
  for (int64_t j = 0; j < band.ny(); ++j)
    for (int64_t i = 0; i < band.nx(); ++i) {
      double& z = preview_.at(i / poolFactor_, (j0 + j) / poolFactor_);
      z = std::min(z, band.at(i, j));
    }
  moments_.add(residualMoments(band, wholeMap(band.grid()), LevelPlane()));
  writeSeconds_ += secondsSince(t0);
  // A band of a frame's map may hold no height at all (NaN min and max: JSON null).
  if (stats.at("min_height").is_number()) {
    zMin_ = std::min(zMin_, stats.at("min_height").get<double>());
    zMax_ = std::max(zMax_, stats.at("max_height").get<double>());
  }
  if (stats.contains("frame")) {
    const json& f = stats["frame"];
    frameCells_.voidCells += f.at("void_cells").get<int64_t>();
    frameCells_.cutThroughCells += f.at("cut_through_cells").get<int64_t>();
    hasFrame_ = true;
  }
  castSeconds_ += stats.at("cast_seconds").get<double>();
  if (stats.contains("scene")) {
    const json& scene = stats["scene"];
    sceneBands_ = true;
    bandSegments_ += scene.at("swept_segments").get<int64_t>();
    bandTiles_ += scene.at("culling_tiles").get<int64_t>();
    bandSceneSeconds_ += stats.at("scene_build_seconds").get<double>();
    largestBandSceneBytes_ = std::max(largestBandSceneBytes_, scene.at("bytes").get<double>());
  }
  evaluations_ += stats.at("exact_evaluations").get<double>();
  if (stats.contains("raster")) {
    const json& r = stats["raster"];
    raster_["floor_z"] = r.at("floor_z");
    // The procedures' predictions depend on the job only, the same in every band.
    for (const char* key :
         {"predicted_scallop_height", "predicted_scallop_height_effective_radius"})
      if (r.contains(key)) raster_[key] = r[key];
    // A band without cells between the first and last pass has no scallop (-inf,
    // stored as null); the map's largest scallop is the largest of the bands'.
    if (r.contains("max_scallop_height")) {
      const double h =
          r["max_scallop_height"].is_number() ? r["max_scallop_height"].get<double>() : -HUGE_VAL;
      raster_["max_scallop_height"] = raster_.contains("max_scallop_height")
                                          ? std::max(raster_["max_scallop_height"].get<double>(), h)
                                          : h;
    }
  }
}

json TiledOutput::finish(double sceneSeconds, double totalSeconds, int threads) {
  const auto t0 = Clock::now();
  writer_.close();
  PreviewOptions preview;
  preview.title = previewTitle(run_.title);
  preview.uncutHeight = run_.uncutHeight;
  writePreviewPng(preview_, (fs::path(dir_) / "preview.png").string(), preview);
  writeSeconds_ += secondsSince(t0);

  RunRecord record = run_.record;
  if (sceneBands_) {
    record.sweptSegments = bandSegments_;
    record.cullingTiles = bandTiles_;
    record.tiled["scene_per_band"] = {{"largest_scene_bytes", largestBandSceneBytes_},
                                      {"swept_segments_summed_over_bands", bandSegments_}};
    sceneSeconds = bandSceneSeconds_;
  }
  record.requestedThreads = threads;
  record.sceneSeconds = sceneSeconds;
  record.castSeconds = castSeconds_;
  record.writeSeconds = writeSeconds_;
  record.minHeight = zMin_;
  record.maxHeight = zMax_;
  record.exactEvaluations = evaluations_;
  record.raster = raster_;
  if (hasFrame_) record.frameCells = frameCellsJson(frameCells_);
  // Bands cannot be read twice: unlevelled (heights from the mean), and without Sa,
  // which needs the mean before the pass (analysis/surface_metrology.h).
  SurfaceStats surface =
      statsFromMoments(moments_, LevelPlane(), grid_.spacing * grid_.spacing, false);
  surface.levelling = Levelling::kNone;
  record.surfaceStats = surfaceStatsJson(surface);
  record.surfaceStats["notes"] =
      record.surfaceStats["notes"].get<std::string>() +
      "; computed band by band: heights from the mean (no plane levelling) and no Sa. "
      "`scallop stats heights.gsf` gives all of them from the file";
  record.pathFile = pathFile_;
  if (feedMarks_) record.feedMarks = feedMarks_->report();
  record.totalSeconds = totalSeconds + secondsSince(t0);
  const json r = simulationReport(record);
  writeReport(r, dir_);
  return r;
}

}  // namespace scallop
