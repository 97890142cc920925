#include "raycast/frame_depth.h"

#include <tbb/parallel_for.h>

#include <atomic>
#include <cmath>
#include <vector>

namespace scallop {

namespace {

// The highest point of `move`'s solid on the line (x, y): minus its mirror's lowest.
double highestPoint(const SweptMove& move, double x, double y) {
  PoseCurve mirrored;
  if (!move.curve().mirroredZ(&mirrored)) return HUGE_VAL;  // machines: refused in frames
  const LowestPoint low = SweptMove(move.cutter(), mirrored).lowestPoint(x, y);
  return low.hit ? -low.z : -HUGE_VAL;
}

double heightAboveFloor(const SweptScene& scene, double x, double y, double exit, double floor) {
  std::vector<SweptScene::Candidate> candidates;
  scene.gatherCandidates(x, y, x, y, exit, candidates);
  double best = exit;
  for (const SweptScene::Candidate& c : candidates) {
    const SweptMove& move = scene.segments()[c.segment];
    const LowestPoint low = move.lowestPoint(x, y);
    if (!low.hit || low.z >= best) continue;
    if (low.z >= floor) {
      best = low.z;
    } else if (highestPoint(move, x, y) >= floor) {
      return low.z;  // cut through: finishFrameMap clamps it to -depth and counts it
    }
  }
  return best;
}

}  // namespace

int64_t cutToFrameDepth(const SweptScene& scene, ZMap& map, const Box3& stock,
                        const GridFrame& frame) {
  if (!std::isfinite(frame.depth)) return 0;
  const GridSpec& g = map.grid();
  const double floor = -frame.depth;
  std::atomic<int64_t> changed{0};
  tbb::parallel_for(int64_t(0), g.ny, [&](int64_t j) {
    for (int64_t i = 0; i < g.nx; ++i) {
      double& h = map.at(i, j);
      if (h == kNoMaterial || !(h < floor)) continue;
      const double x = g.cellCentreX(i), y = g.cellCentreY(j);
      const double exit = stockExitHeight(stock, frame, x, y);
      // The lowest point at or above -depth, or (cut through) one below it.
      const double kept = heightAboveFloor(scene, x, y, exit, floor);
      if (kept != h) changed.fetch_add(1, std::memory_order_relaxed);
      h = kept;
    }
  });
  return changed.load();
}

}  // namespace scallop
