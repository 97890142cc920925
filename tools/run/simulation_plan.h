// A simulation plan: everything a run decides before its long computation, made once
// from the job and the run settings. The grid, what the run would hold in memory and
// whether that fits, whether it runs in bands and their layout, the banner. The
// in-memory run (simulation_run.h) and the banded run (tiled_simulation.h) both execute
// a plan, so no part of the run makes the grid or judges memory again.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>

#include "raycast/zmap.h"
#include "tools/run/memory_limits.h"

namespace scallop {

struct Job;
struct RunSettings;

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

struct SimulationPlan {
  GridSpec grid;
  bool exact = true;        // --method exact (not the stamp baseline)
  bool bandsAsked = false;  // --tiled, --tile-rows or --bands
  RunMemory memory;         // the map and the scene, bytes, against what is available
  // In bands: asked for, or an exact run whose map or whole scene does not fit in memory.
  bool inBands = false;
  // The whole path's scene does not fit: each band builds the scene of the moves that
  // reach it (memory.largestBandBytes), bands halved until the largest one fits.
  bool sceneBands = false;
  // A scene a band of a path file (pathStreams in job_loader.h): each band re-reads the
  // file as a stream and sweeps it through its window, and the run frees the path's moves
  // once it has planned (releasePathMoves): none is resident beside a band's scene.
  bool streamPath = false;
  size_t pathMoves = 0;                      // the path's moves: what each re-read must count
  size_t cuttingMoves = 0;                   // its cutting moves
  double cellsPerMove = 0;                   // streamPath: programCellsPerMove of the whole path
  size_t streamPartMoves = size_t(1) << 16;  // moves a part of the stream holds
  BandLayout layout;                         // the bands (of settings.tileRows rows) when inBands
  int64_t firstBand = 0;                     // bands [firstBand, endBand) run here; --bands K:M
  int64_t endBand = 0;   // narrows them and writes band files instead of outputs
  bool partial = false;  // --bands K:M
  std::string banner;    // the run's first line on stderr, without "scallop: "

  int64_t cellsToCompute() const;
};

// The plan of `job` run as `settings` ask, against `availableBytes` of memory. Throws
// InputError for a malformed --bands; a plan that does not fit is still made (see
// memory.refusal) so that a caller can say so or choose bands.
SimulationPlan planSimulation(const Job& job, const RunSettings& settings,
                              double availableBytes = availableMemoryBytes());

}  // namespace scallop
