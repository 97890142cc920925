// Tiled simulation: maps larger than memory, computed band by band.
//
// A band is a run of whole image rows (full width), counted from the top (image row 0,
// the largest y) so that rows reach the writers in file order. One culling scene of
// the whole path serves every band; each band is a ZMap over grid.rows(j0, j1), whose
// cell centres are the full grid's to the bit, so a tiled map equals the in-memory one.
// Memory: the scene, one band (<= 256 MB of doubles by default) and its float copy.
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
#include "tools/run/simulation_run.h"

namespace scallop {

struct Job;

struct BandLayout {
  int64_t bandRows = 0;  // image rows per band; the last band may have fewer
  int64_t bands = 0;
  int tileHeight = 0;  // OpenEXR tile rows; bandRows is a multiple of it

  int64_t firstRow(int64_t band) const { return band * bandRows; }
  int64_t endRow(int64_t band, const GridSpec& g) const {
    return std::min(g.ny, (band + 1) * bandRows);
  }
  // The band's rows as a sub-grid of `g` (ZMap order: j = 0 is its smallest y).
  GridSpec bandGrid(int64_t band, const GridSpec& g) const {
    return g.rows(g.ny - endRow(band, g), g.ny - firstRow(band));
  }
};

// Bands of `requestedRows` rows (0: as many as fit in 256 MB of doubles), rounded
// down to a whole number of OpenEXR tiles of at most 256 rows.
BandLayout bandLayout(const GridSpec& grid, int64_t requestedRows);

// True when the job's map fits in memory. Otherwise checks that the tiled outputs fit
// on the disk holding `outDir` (throwing the memory refusal, with the disk numbers
// added, when they do not), says on stderr that the map is computed in bands, and
// returns false.
bool gridFitsMemory(const Job& job, const std::string& outDir);

// A simulation run in bands: all of them into the usual outputs, or with
// settings.bands = "K:M" only bands K..M-1 into band files.
RunOutcome runTiledSimulation(const Job& job, const RunSettings& settings);

// Streams bands, in order, into DIR/heights.exr, heights.gsf, preview.png and
// report.json. `run` describes the run (band files carry it, see tiled_simulation.cpp);
// each band comes with its statistics, and finish() returns report.json's content.
class TiledOutput {
 public:
  TiledOutput(const nlohmann::json& run, const std::string& dir);
  void add(const ZMap& band, const nlohmann::json& bandStats);
  nlohmann::json finish(double sceneSeconds, double totalSeconds, int threads);
  // Before finish(): the report's "path_file" section (pathFileReport), if any.
  void setPathFile(const nlohmann::json& pathFile) { pathFile_ = pathFile; }

 private:
  nlohmann::json run_;
  std::string dir_;
  GridSpec grid_;
  HeightStreamWriter writer_;
  ZMap preview_;  // min-pooled heights, at most PreviewOptions::maxPixels a side
  int64_t poolFactor_ = 1;
  double zMin_ = HUGE_VAL, zMax_ = -HUGE_VAL, castSeconds_ = 0, writeSeconds_ = 0;
  double evaluations_ = 0;
  nlohmann::json raster_, pathFile_;
  HeightMoments moments_;  // raw heights of the bands so far, merged in band order
  std::unique_ptr<FeedMarkSampler> feedMarks_;  // a teeth run's (feed_mark_report.h)
};

}  // namespace scallop
