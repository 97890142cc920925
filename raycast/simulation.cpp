#include "raycast/simulation.h"

namespace scallop {

SimulationResult simulate(const Cutter& cutter, const ToolPath& path, const Box3& stock,
                          const GridSpec& grid, const SimulationOptions& options) {
  SceneOptions sceneOptions;
  sceneOptions.tileSize = options.tileSize;
  sceneOptions.stockTop = stock.max.z;
  const SweptScene scene(sweepToolPath(cutter, path, options.sweep), sceneOptions);

  SimulationResult result;
  result.map = ZMap(grid, stock.max.z);
  result.cast = castZMap(scene, result.map, options.cast);
  result.scene = scene.stats();
  return result;
}

}  // namespace scallop
