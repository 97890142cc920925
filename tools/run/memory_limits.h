// Memory limits: a run is refused, before its long computation, when what it would
// hold cannot fit in the memory available, with a message naming the bytes it needs.
#pragma once

#include <string>

#include "base/available_memory.h"
#include "raycast/zmap.h"

namespace scallop {

struct Job;

// The bytes a map on `grid` takes while a run holds it: its heights in double, plus
// their float32 copy while writing.
double heightMapBytes(const GridSpec& grid);

// What a run would hold in memory, bytes, and what is available; a part fits when it
// takes at most 80 % of the available memory.
struct RunMemory {
  double mapBytes = 0;    // the heights in double, plus their float32 copy while writing
  double sceneBytes = 0;  // the exact run's culling scene (0 for the stamp baseline)
  size_t cuttingMoves = 0;
  double availableBytes = 0;
  // A scene per band (the whole scene does not fit): the most that one band holds, its
  // scene and its rows of the map, bytes (0: one scene for the whole map).
  double largestBandBytes = 0;
  bool mapFits() const { return mapBytes <= 0.8 * availableBytes; }
  bool sceneFits() const {
    return (largestBandBytes > 0 ? largestBandBytes : sceneBytes) <= 0.8 * availableBytes;
  }
  bool wholeSceneFits() const { return sceneBytes <= 0.8 * availableBytes; }
};

// The map's bytes on `grid` and, for an exact run, the scene's (its own estimate,
// estimateSceneBytes in raycast/simulation.h: it errs high, never low).
RunMemory estimateRunMemory(const Job& job, const GridSpec& grid, bool exact,
                            double availableBytes);

// Throws the one refusal of a run that does not fit, naming the field: the scene
// ("JOB: path"), else, when the map must be held whole, the grid ("JOB: grid.spacing"),
// its message followed by `whyNotInBands` when that is given.
void requireRunFitsMemory(const Job& job, const GridSpec& grid, const RunMemory& memory,
                          bool wholeMap, const std::string& whyNotInBands = "");

// Refuses grids whose heights would not fit in memory, naming the size they need (the
// job loader's check, before a stamp run's path is made).
void checkGridFitsMemory(const GridSpec& grid, const std::string& field);

// Refuses a raster whose moves alone would not fit in memory, before generating it.
void checkRasterFitsMemory(const Job& job);

// Refuses a path whose exact simulation's culling scene would not fit in memory,
// naming the bytes (requireRunFitsMemory for the scene alone).
void checkSceneFitsMemory(const Job& job);

}  // namespace scallop
