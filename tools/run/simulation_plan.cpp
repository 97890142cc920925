#include "tools/run/simulation_plan.h"

#include <fmt/core.h>

#include <algorithm>
#include <cstdio>
#include <tuple>
#include <utility>

#include "base/input_error.h"
#include "raycast/simulation.h"
#include "tools/io/job.h"
#include "tools/run/job_loader.h"
#include "tools/run/simulation_run.h"

namespace scallop {

namespace {

constexpr double kBandBytes = 256.0 * (1 << 20);
constexpr int64_t kMaxTileRows = 256;

// Bands [first, end) from "K:M".
std::pair<int64_t, int64_t> parseBands(const std::string& text, const BandLayout& layout) {
  long long k = -1, m = -1;
  char tail = 0;
  const std::string expected =
      fmt::format("expected K:M with 0 <= K < M <= {} (this job has {} bands of {} rows)",
                  layout.bands, layout.bands, layout.bandRows);
  if (std::sscanf(text.c_str(), "%lld:%lld%c", &k, &m, &tail) != 2 || k < 0 || m <= k ||
      m > layout.bands)
    throw InputError("--bands", "'" + text + "': " + expected);
  return {k, m};
}

std::string bannerOf(const Job& job, const SimulationPlan& plan) {
  const GridSpec& g = plan.grid;
  std::string line = fmt::format(
      "{}: {} cutter R={:g} mm, {} cutting moves, {} x {} cells of {:g} mm", job.source,
      toString(job.cutter.type), job.cutter.radius, plan.cuttingMoves, g.nx, g.ny, g.spacing);
  if (plan.inBands)
    return line + fmt::format(", bands {}..{} of {} ({} rows each)", plan.firstBand,
                              plan.endBand - 1, plan.layout.bands, plan.layout.bandRows);
  return line + (job.cutting.teeth() ? ", teeth" : "");
}

// Bands small enough that each one's scene and rows of the map fit (RunMemory::
// largestBandBytes): halving the rows from bandLayout's until they do, or down to one row
// (then memory.sceneFits() stays false and the run is refused, naming the bytes).
BandLayout sceneBandLayout(const Job& job, SimulationPlan& plan, int64_t requestedRows) {
  BandLayout layout = bandLayout(plan.grid, requestedRows);
  for (;;) {
    const std::vector<double> scenes = estimateBandSceneBytes(
        job.cutter, job.path, job.stock, plan.grid, layout.bandRows, job.cutting);
    double largest = 0;
    for (int64_t b = 0; b < layout.bands; ++b)
      largest =
          std::max(largest, scenes[size_t(b)] + heightMapBytes(layout.bandGrid(b, plan.grid)));
    plan.memory.largestBandBytes = std::max(largest, 1.0);
    if (plan.memory.sceneFits() || requestedRows > 0 || layout.bandRows == 1) return layout;
    layout = bandLayout(plan.grid, std::max<int64_t>(1, layout.bandRows / 2));
  }
}

}  // namespace

BandLayout bandLayout(const GridSpec& grid, int64_t requestedRows) {
  int64_t rows = requestedRows > 0
                     ? requestedRows
                     : std::max<int64_t>(1, int64_t(kBandBytes / (8.0 * double(grid.nx))));
  BandLayout layout;
  layout.tileHeight = int(std::min(kMaxTileRows, rows));
  rows = rows / layout.tileHeight * layout.tileHeight;
  layout.bandRows = std::min(rows, std::max<int64_t>(1, grid.ny));
  layout.bands = (grid.ny + layout.bandRows - 1) / layout.bandRows;
  return layout;
}

int64_t SimulationPlan::cellsToCompute() const {
  if (!inBands) return grid.cells();
  int64_t cells = 0;
  for (int64_t b = firstBand; b < endBand; ++b) cells += layout.bandGrid(b, grid).cells();
  return cells;
}

SimulationPlan planSimulation(const Job& job, const RunSettings& settings, double availableBytes) {
  SimulationPlan plan;
  plan.grid = job.grid();
  plan.exact = settings.method == "exact";
  plan.bandsAsked = settings.tiled || settings.tileRows > 0 || !settings.bands.empty();
  plan.memory = estimateRunMemory(job, plan.grid, plan.exact, availableBytes);
  // A path whose whole scene does not fit runs in bands, each with the scene of the moves
  // that reach it (tiled_simulation.h).
  plan.sceneBands = plan.exact && !plan.memory.wholeSceneFits();
  // Every move of the file: what a re-read as a stream (which keeps them all) counts.
  plan.pathMoves = job.pathFile.empty() || job.movesRead == 0 ? job.path.moves.size() : job.movesRead;
  plan.cuttingMoves = job.path.cuttingMoves();
  plan.streamPath = plan.sceneBands && pathStreams(job);
  if (plan.streamPath)
    plan.cellsPerMove = programCellsPerMove(job.cutter, job.path, job.stock, plan.grid.spacing);
  // The stamp baseline holds the whole map (its bands are refused by the run).
  plan.inBands = plan.bandsAsked || plan.sceneBands || (plan.exact && !plan.memory.mapFits());
  if (plan.inBands) {
    plan.layout = plan.sceneBands ? sceneBandLayout(job, plan, settings.tileRows)
                                  : bandLayout(plan.grid, settings.tileRows);
    plan.partial = !settings.bands.empty();
    plan.endBand = plan.layout.bands;
    if (plan.partial)
      std::tie(plan.firstBand, plan.endBand) = parseBands(settings.bands, plan.layout);
  }
  plan.banner = bannerOf(job, plan);
  return plan;
}

}  // namespace scallop
