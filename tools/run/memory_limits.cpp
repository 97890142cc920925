#include "tools/run/memory_limits.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "base/input_error.h"
#include "raycast/simulation.h"
#include "tools/io/job.h"

namespace scallop {

double heightMapBytes(const GridSpec& grid) {
  return double(grid.nx) * double(grid.ny) * (sizeof(double) + sizeof(float));
}

namespace {

std::string mapRefusal(const GridSpec& grid, double need, double available) {
  std::ostringstream msg;
  msg.precision(3);
  msg << "a " << grid.nx << " x " << grid.ny << " grid needs " << need / double(1ull << 30)
      << " GiB (" << std::fixed << std::setprecision(0) << need << " bytes) of memory, but only "
      << std::defaultfloat << std::setprecision(3) << available / double(1ull << 30)
      << " GiB are available; use a larger spacing, a smaller stock, or --method exact with "
         "--tiled (bands of rows, bounded memory)";
  return msg.str();
}

std::string sceneRefusal(const RunMemory& memory, bool wholeMap) {
  const double need = memory.sceneBytes, available = memory.availableBytes;
  std::ostringstream msg;
  msg << "the exact simulation of " << memory.cuttingMoves << " cutting moves needs about "
      << std::setprecision(need < 1e15 ? 15 : 3) << need << " bytes (" << std::fixed
      << std::setprecision(1) << need / double(1ull << 30)
      << " GiB) of memory for its culling scene, but only " << available / double(1ull << 30)
      << " GiB are available; ";
  if (wholeMap || !(memory.largestBandBytes > 0))
    msg << "split the path into several jobs";
  else
    msg << "in bands of rows, each with the scene of the moves that reach it, the largest "
           "band still needs "
        << std::setprecision(1) << memory.largestBandBytes / double(1ull << 30)
        << " GiB; split the path into several jobs or use a larger grid.spacing";
  return msg.str();
}

}  // namespace

RunMemory estimateRunMemory(const Job& job, const GridSpec& grid, bool exact,
                            double availableBytes) {
  RunMemory memory;
  memory.mapBytes = heightMapBytes(grid);
  if (exact)
    // The same stock box the scene is built with (tiled_simulation.cpp), so the estimate
    // chooses its culling tiles alike.
    memory.sceneBytes = estimateSceneBytes(job.cutter, job.path, job.stock, grid.spacing,
                                           &memory.cuttingMoves, job.cutting);
  memory.availableBytes = availableBytes;
  return memory;
}

void requireRunFitsMemory(const Job& job, const GridSpec& grid, const RunMemory& memory,
                          bool wholeMap, const std::string& whyNotInBands) {
  // Held whole, the map has one scene; otherwise it may have one a band.
  if (wholeMap ? !memory.wholeSceneFits() : !memory.sceneFits())
    throw InputError(job.source + ": path", sceneRefusal(memory, wholeMap));
  if (wholeMap && !memory.mapFits())
    throw InputError(job.source + ": grid.spacing",
                     mapRefusal(grid, memory.mapBytes, memory.availableBytes) + whyNotInBands);
}

void checkGridFitsMemory(const GridSpec& grid, const std::string& field) {
  const double need = heightMapBytes(grid);
  const double available = availableMemoryBytes();
  if (need > 0.8 * available) throw InputError(field, mapRefusal(grid, need, available));
}

// makeRaster holds every move (up to its own limit of 5e7): refuse, before generating
// it, a raster whose moves alone would not fit in memory. Counts as sweep/raster.cpp
// does; invalid values are left to makeRaster's messages.
void checkRasterFitsMemory(const Job& job) {
  const RasterSpec& r = job.raster;
  if (!(r.stepOver > 0) || !(r.segmentLength >= 0)) return;
  const bool alongX = r.direction == 'x';
  const double cross =
      alongX ? job.stock.max.y - job.stock.min.y : job.stock.max.x - job.stock.min.x;
  const double feed =
      (alongX ? job.stock.max.x - job.stock.min.x : job.stock.max.y - job.stock.min.y) +
      2 * job.cutter.radius + 2;
  const double passes = std::floor(cross / r.stepOver + 1e-9) + 1;
  const double moves = passes * (r.segmentLength > 0 ? std::ceil(feed / r.segmentLength) + 1 : 2);
  const double need = moves * double(sizeof(Move));
  const double available = availableMemoryBytes();
  if (need > 0.8 * available) {
    std::ostringstream msg;
    msg << "gives " << moves << " moves, which need " << std::setprecision(15) << need
        << " bytes of memory, but only " << std::fixed << std::setprecision(1)
        << available / double(1ull << 30) << " GiB are available";
    throw InputError(r.segmentLength > 0 ? "path.raster.segment_length" : "path.raster.step_over",
                     msg.str());
  }
}

void checkSceneFitsMemory(const Job& job) {
  const RunMemory memory = estimateRunMemory(job, GridSpec(), true, availableMemoryBytes());
  requireRunFitsMemory(job, GridSpec(), memory, false);
}

}  // namespace scallop
