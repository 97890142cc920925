// Memory limits: a run is refused, before its long computation, when what it would
// hold cannot fit in the memory available, with a message naming the bytes it needs.
#pragma once

#include <string>

#include "raycast/zmap.h"

namespace scallop {

struct Job;

// /proc/meminfo's MemAvailable, bytes (8 GiB when it cannot be read).
double availableMemoryBytes();

// Refuses grids whose heights would not fit in memory, naming the size they need.
void checkGridFitsMemory(const GridSpec& grid, const std::string& field);

// Refuses a raster whose moves alone would not fit in memory, before generating it.
void checkRasterFitsMemory(const Job& job);

// Refuses a path whose exact simulation's culling scene would not fit in memory (the
// scene's own estimate, estimateSceneBytes in raycast/simulation.h), naming the bytes.
void checkSceneFitsMemory(const Job& job);

}  // namespace scallop
