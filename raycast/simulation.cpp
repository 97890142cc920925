#include "raycast/simulation.h"

#include <cmath>

namespace scallop {

SceneOptions sceneOptionsFor(const Box3& stock, double spacing, const SimulationOptions& options) {
  SceneOptions sceneOptions;
  sceneOptions.tileSize = options.tileSize;
  sceneOptions.stockTop = stock.max.z;
  // Candidate regions of options.cast.regionCells cells a side (zmap_caster.cpp).
  sceneOptions.regionHalfSize = 0.5 * double(options.cast.regionCells - 1) * spacing;
  return sceneOptions;
}

double estimateSceneBytes(const Cutter& cutter, const ToolPath& path, double stockTop,
                          size_t* moves) {
  constexpr double kBytesPerTile = 500;  // TileBox (152) + Embree's BVH share, measured
  const double R = cutter.radius, flute = cutter.fluteLength;
  double need = 0;
  size_t counted = 0;
  for (const Move& m : path.moves) {
    if (m.rapid || std::fmin(m.from.tip.z, m.to.tip.z) - R - flute >= stockTop) continue;
    // A box that holds the cutter at every pose of the move: the tips' box grown by the
    // cutter's widest horizontal reach at the more leaning end (slerp between axes with
    // k >= 0 never leans more than its ends).
    const auto lean = [](const Vec3& a) { return std::hypot(a.x, a.y) / length(a); };
    const double reach = 2 * (R + flute * std::fmax(lean(m.from.axis), lean(m.to.axis)));
    const double w = std::fabs(m.to.tip.x - m.from.tip.x) + reach;
    const double h = std::fabs(m.to.tip.y - m.from.tip.y) + reach;
    const double T = cullingTileSide(R, length(m.to.tip - m.from.tip), w * h, SceneOptions());
    const bool turning = PoseCurve::turns(m.from.axis, m.to.axis);
    need += double(SweptMove::bytesPerMove(turning)) +
            kBytesPerTile * std::ceil(w / T) * std::ceil(h / T);
    ++counted;
  }
  if (moves) *moves = counted;
  return need;
}

std::unique_ptr<SweptScene> buildScene(const Cutter& cutter, const ToolPath& path,
                                       const Box3& stock, double spacing,
                                       const SimulationOptions& options) {
  return std::make_unique<SweptScene>(sweepToolPath(cutter, path),
                                      sceneOptionsFor(stock, spacing, options));
}

SimulationResult simulate(const Cutter& cutter, const ToolPath& path, const Box3& stock,
                          const GridSpec& grid, const SimulationOptions& options) {
  const std::unique_ptr<SweptScene> scene = buildScene(cutter, path, stock, grid.spacing, options);
  SimulationResult result;
  result.map = ZMap(grid, stock.max.z);
  result.cast = castZMap(*scene, result.map, options.cast);
  result.scene = scene->stats();
  return result;
}

}  // namespace scallop
