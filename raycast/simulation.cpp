#include "raycast/simulation.h"

namespace scallop {

SceneOptions sceneOptionsFor(const Box3& stock, double spacing, const SimulationOptions& options) {
  SceneOptions sceneOptions;
  sceneOptions.tileSize = options.tileSize;
  sceneOptions.stockTop = stock.max.z;
  // Candidate regions of options.cast.regionCells cells a side (zmap_caster.cpp).
  sceneOptions.regionHalfSize = 0.5 * double(options.cast.regionCells - 1) * spacing;
  return sceneOptions;
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
