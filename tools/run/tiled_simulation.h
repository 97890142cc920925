// Tiled simulation: maps larger than memory, computed band by band.
//
// A band is a run of whole image rows (full width), counted from the top (image row 0,
// the largest y) so that rows reach the writers in file order. One culling scene of
// the whole path serves every band, or, when that scene does not fit in memory
// (SimulationPlan::sceneBands), each band builds the scene of the moves that reach it
// (sweepToolPath's window: the same moves, so the same heights), a path file then read
// again for each band rather than held (SimulationPlan::streamPath); each band is a ZMap over
// grid.rows(j0, j1), whose cell centres are the full grid's to the bit, so a tiled map equals the
// in-memory one. Memory: the scene (or a band's), one band (<= 256 MB of doubles by default) and
// its float copy.
//
// Bands are independent, so a range of them can run in another process
// (`simulate --bands K:M` writes DIR/band-K.raw + band-K.json) and `scallop merge DIR`
// assembles the same outputs later. The layout depends only on the job and --tile-rows,
// never on the machine, so every process agrees on it.
#pragma once

#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "analysis/surface_metrology.h"
#include "raycast/zmap.h"
#include "tools/io/height_images.h"
#include "tools/run/feed_mark_report.h"
#include "tools/run/report.h"
#include "tools/run/simulation_plan.h"
#include "tools/run/simulation_run.h"

namespace scallop {

struct Job;

// Checks, for a run in bands that were not asked for (its map does not fit in memory),
// that the outputs fit on the disk holding `outDir`, throwing the memory refusal with
// the disk numbers added when they do not, and says on stderr that the map is computed
// in bands.
void requireBandsFitDisk(const Job& job, const SimulationPlan& plan, const std::string& outDir);

// A simulation run in bands: all of them into the usual outputs, or with
// settings.bands = "K:M" only bands K..M-1 into band files. The job is the run's own:
// with plan.streamPath its moves are freed once the outputs' descriptions are made, and
// each band re-reads the path file.
RunOutcome runTiledSimulation(Job job, const SimulationPlan& plan, const RunSettings& settings);

// What TiledOutput needs of a run besides its bands: made from the plan by the run
// itself, or by merge from the "run" description that band files carry.
struct TiledRun {
  // The report's description of the run: jobSource, inputs, grid, cuttingMoves,
  // sweptSegments, cullingTiles and tiled ({"bands", "band_rows", "exr_tile_rows"}).
  RunRecord record;
  std::string title;             // simulationTitle
  int exrTileRows = 0;           // BandLayout::tileHeight
  double uncutHeight = 0;        // the stock's top, mm: the preview's uncut grey
  nlohmann::json feedMarksPlan;  // a teeth run's feedMarkPlan, else null
  std::string frame;             // GridFrame::describe() of a map in a frame, else empty
};

// The TiledRun of a band file's "run" description (merge).
TiledRun tiledRunFromBands(const nlohmann::json& run);

// Streams bands, in order, into DIR/heights.exr, heights.gsf, preview.png and
// report.json. Each band comes with its statistics, and finish() returns report.json's
// content.
class TiledOutput {
 public:
  TiledOutput(const TiledRun& run, const std::string& dir);
  void add(const ZMap& band, const nlohmann::json& bandStats);
  nlohmann::json finish(double sceneSeconds, double totalSeconds, int threads);
  // Before finish(): the report's "path_file" section (pathFileReport), if any.
  void setPathFile(const nlohmann::json& pathFile) { pathFile_ = pathFile; }

 private:
  TiledRun run_;
  std::string dir_;
  GridSpec grid_;
  HeightStreamWriter writer_;
  ZMap preview_;  // min-pooled heights, at most PreviewOptions::maxPixels a side
  int64_t poolFactor_ = 1;
  double zMin_ = HUGE_VAL, zMax_ = -HUGE_VAL, castSeconds_ = 0, writeSeconds_ = 0;
  double evaluations_ = 0;
  nlohmann::json raster_, pathFile_;
  FrameCellCounts frameCells_;  // a frame's void and cut-through cells, summed
  // A scene a band (SimulationPlan::sceneBands): the bands' scenes, summed (a move that
  // reaches two bands is in both), their build times summed, the largest one's bytes.
  bool sceneBands_ = false;
  int64_t bandSegments_ = 0, bandTiles_ = 0;
  double bandSceneSeconds_ = 0, largestBandSceneBytes_ = 0;
  bool hasFrame_ = false;
  HeightMoments moments_;  // raw heights of the bands so far, merged in band order
  std::unique_ptr<FeedMarkSampler> feedMarks_;  // a teeth run's (feed_mark_report.h)
};

}  // namespace scallop
