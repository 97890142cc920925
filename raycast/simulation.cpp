#include "raycast/simulation.h"

namespace scallop {

SimulationResult simulate(const Cutter& cutter, const ToolPath& path, const Box3& stock,
                          const GridSpec& grid, const SimulationOptions& options) {
  SceneOptions sceneOptions;
  sceneOptions.tileSize = options.tileSize;
  sceneOptions.stockTop = stock.max.z;
  // Candidate regions of options.cast.regionCells cells a side (zmap_caster.cpp).
  sceneOptions.regionHalfSize = 0.5 * double(options.cast.regionCells - 1) * grid.spacing;
  const SweptScene scene(sweepToolPath(cutter, path, options.sweep), sceneOptions);

  SimulationResult result;
  result.map = ZMap(grid, stock.max.z);
  result.cast = castZMap(scene, result.map, options.cast);
  result.scene = scene.stats();
  return result;
}

}  // namespace scallop
