// The classical z-map method, kept as a reference and as the benchmark's baseline
// (`simulate --method stamp`, `bench`): the stationary cutter is stamped at discrete
// positions along every move and each cell keeps the lowest stamped height.
//
// Every stamp is a subset of the swept solid, so a stamped map is never below the
// exact one; it is above it by the scallop left between two stamps. The heights of
// one stamp are exact (cutterLowestPoint, double), only the sampling along the move is
// approximate.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "raycast/zmap.h"
#include "sweep/pose.h"
#include "sweep/swept_move.h"
#include "sweep/tool_path_sweep.h"

namespace scallop {

// Step between stamps along a move, mm, that keeps the scallop left between two
// stamps of a cutter with this axis at or below `tolerance` mm. Between stamps Delta
// apart the worst cell is half-way, where the stamped height exceeds the envelope by
// the sagitta Delta^2 kappa / 8 of the cutter's lower boundary, kappa being its
// curvature along the feed at the contact point:
//   ball: kappa = 1/R                -> Delta = sqrt(8 tol R)
//   bull: kappa <= 1/r (corner)      -> Delta = sqrt(8 tol r)
//   flat: a sharp rim. Tilted by alpha, the heel is a corner where the bottom rises
//         with slope tan(alpha): the error is linear, Delta tan(alpha) -> Delta =
//         tol / tan(alpha); with a vertical axis the rim circle gives sqrt(8 tol R).
// A vertical section through a steep part of the boundary is more curved than the
// normal section (Meusnier), so the result is halved for margin; the benchmark and
// tests check the actual error against the exact map.
double stampStepFor(const Cutter& cutter, const Vec3& axis, double tolerance);

struct StampOptions {
  double step = 0;          // mm between stamps; <= 0: stampStepFor(..., tolerance) per move
  double tolerance = 1e-4;  // mm, for the derived step
  int64_t tileCells = 64;   // cells per side of a parallel work item
  // Called from worker threads (serialised) with cells done so far and the total.
  std::function<void(int64_t done, int64_t total)> progress;
};

struct StampStats {
  int64_t cells = 0;
  uint64_t positions = 0;         // stamps that can reach below the initial map
  uint64_t exactEvaluations = 0;  // cutterLowestPoint calls
  double minStep = 0;             // smallest step used, mm
  double seconds = 0;
  double evaluationsPerCell() const { return cells ? double(exactEvaluations) / cells : 0; }
};

// Lowers every cell of `map` to the lowest height of the cutter stamped at evenly
// spaced poses of each move's pose curve (both ends included). Parallel over tiles of cells; each
// tile visits the stamps whose footprint overlaps it, so there are no races and the result does not
// depend on the number of threads.
StampStats stampZMap(const std::vector<SweptMove>& segments, ZMap& map,
                     const StampOptions& options = {});

struct StampSimulationResult {
  ZMap map;
  size_t segments = 0;  // swept moves the path became
  StampStats stamp;
};

// The stamping counterpart of simulate(): the same moves, stamped instead of swept.
StampSimulationResult simulateStamped(const Cutter& cutter, const ToolPath& path, const Box3& stock,
                                      const GridSpec& grid, const StampOptions& options = {});

}  // namespace scallop
