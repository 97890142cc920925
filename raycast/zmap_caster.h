// Casting a ZMap: one exact height per cell, computed in parallel over tiles of cells.
#pragma once

#include <cstdint>
#include <functional>

#include "raycast/swept_scene.h"
#include "raycast/zmap.h"

namespace scallop {

struct CastOptions {
  // Cells per side of a parallel work item; 0: 128 on grids of 4 M cells or more, else
  // 64. Each item starts its regions with no winner to carry (zmap_caster.cpp, step 1)
  // and pays an exact query for one: 128 (B3 and B1: 1.4 % and 2.8 % fewer instructions
  // than 64) still leaves a full B3 6 100 items, while a small grid needs the smaller
  // items to keep every thread busy. (The grid's size decides, never the thread count:
  // the work done, like the heights, does not depend on it.)
  int64_t tileCells = 0;
  // Cells per side of a candidate region (one candidate search each); 0: as many as the
  // scene was built for (sceneOptionsFor: about 64 um a side, 8 to 32 cells).
  int64_t regionCells = 0;
  // Called from worker threads (serialised) with cells done so far and the total;
  // simulate() (and the banded run, tools/run) also call it with 0 done after each phase
  // before the cast. It may throw to stop the run (tools/cli/interrupt.h): the exception
  // leaves the cast.
  std::function<void(int64_t done, int64_t total)> progress;
};

struct CastStats {
  int64_t cells = 0;
  uint64_t exactEvaluations = 0;
  // Cells whose turning move's certified search ran out of samples before its proof
  // closed (sweep/certified_search.h): their height is a real point of the solid, not
  // proven lowest. Expected none; the report warns otherwise.
  uint64_t unprovenSearches = 0;
  double seconds = 0;
  double evaluationsPerCell() const { return cells ? double(exactEvaluations) / cells : 0; }
};

// Lowers every cell of `map` to the lowest swept height at its centre. The result does
// not depend on the number of threads: each cell is an independent minimum.
CastStats castZMap(const SweptScene& scene, ZMap& map, const CastOptions& options = {});

}  // namespace scallop
