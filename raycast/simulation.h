// simulate(): tool path -> swept segments -> scene -> z-map, the whole exact pipeline.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "raycast/grid_frame.h"
#include "raycast/swept_scene.h"
#include "raycast/zmap.h"
#include "raycast/zmap_caster.h"
#include "sweep/cutter.h"
#include "sweep/pose.h"
#include "sweep/tool_path_sweep.h"

namespace scallop {

struct SimulationOptions {
  double tileSize = 0;  // scene culling tile, mm (SceneOptions::tileSize)
  CastOptions cast;
  CuttingModel cutting;  // envelope (default) or teeth
  // A map along any direction (raycast/grid_frame.h): the path is given in the frame's
  // coordinates, the stock (a box of the part) starts each cell at its exit height.
  std::optional<GridFrame> frame;
  // A stock of any shape (analysis/stock_solid.h), without a frame: sets every cell's
  // initial height, kNoMaterial where its line holds no material (NaN once cast).
  std::function<void(ZMap&)> fillStock;
};

struct SimulationResult {
  ZMap map;
  SceneStats scene;
  CastStats cast;
  FrameCellCounts frameCells;  // with a frame
};

// The scene options simulate() uses for cells of side `spacing` (mm) under `stock`.
SceneOptions sceneOptionsFor(const Box3& stock, double spacing, const SimulationOptions& options);

// The cells of a grid of side `spacing` (mm) over `stock` per cutting move of `path` that
// reaches below the stock top inside the stock's xy box (HUGE_VAL: none does):
// SceneOptions::cellsPerMove, from the moves alone, so that the scene and its estimate
// (estimateSceneBytes) choose the same culling tiles.
double programCellsPerMove(const Cutter& cutter, const ToolPath& path, const Box3& stock,
                           double spacing);

// Bytes the culling scene of `path` will hold, estimated before it is built from the
// moves alone: per cutting move that reaches below the stock top, the SweptMove (turning
// or constant-axis, SweptMove::bytesPerMove) and its culling tiles (cullingTileSide's
// grid over a box that holds the move, each tile counted as kept, ~310 bytes with the
// most the tile grid lists it); docs/performance-history.md ("Memory a move") has what
// it is per move. It errs high, never low: B3's path (22,960 turning moves of 0.05 mm)
// builds 6.8 KB a move for 12.7 KB estimated; a program of one tile a move (fewer than
// kCellsPerMoveForTiles cells a move) is estimated within 20 % (tests/raycast/
// scene_memory_test.cpp). `moves`, if given, receives the number of moves counted. With
// teeth (`cutting`) each move also holds a ToothSweep.
double estimateSceneBytes(const Cutter& cutter, const ToolPath& path, const Box3& stock,
                          double spacing, size_t* moves = nullptr,
                          const CuttingModel& cutting = {});

// estimateSceneBytes of the scene of each band of `bandRows` rows of `grid`, counted
// from its top row (j = ny - 1: image row 0, as the map's bands are written): the bytes
// of the moves whose reach meets the band's cell lines (a move near a band's edge counts
// in each band it meets).
std::vector<double> estimateBandSceneBytes(const Cutter& cutter, const ToolPath& path,
                                           const Box3& stock, const GridSpec& grid,
                                           int64_t bandRows, const CuttingModel& cutting = {});

// The window of `grid`'s cell lines (their centres' extent).
SweepWindow cellWindow(const GridSpec& grid);

// The culling scene of `path` for a grid of cells of side `spacing` (mm): built once,
// it serves any number of sub-grids (bands of a map too large to hold). With a
// `window`, the scene of the moves that may reach it only (sweepToolPath): it serves
// the sub-grids inside the window, with the same heights as the whole scene.
std::unique_ptr<SweptScene> buildScene(const Cutter& cutter, const ToolPath& path,
                                       const Box3& stock, double spacing,
                                       const SimulationOptions& options = {},
                                       const SweepWindow* window = nullptr);

// The culling scene of moves already swept (ToolPathSweeper: a path streamed from its
// file), `cellsPerMove` the whole program's programCellsPerMove: the scene buildScene
// makes of the same moves, with the same culling tiles.
std::unique_ptr<SweptScene> buildSceneOfMoves(std::vector<SweptMove> moves, const Box3& stock,
                                              double spacing, double cellsPerMove,
                                              const SimulationOptions& options = {});

// Heights of `stock` (its top is the initial height) after `path`, on `grid`. With
// options.frame, the frame's heights (cells start at the stock's exit height, those
// without material end NaN, those cut below -depth hold -depth).
SimulationResult simulate(const Cutter& cutter, const ToolPath& path, const Box3& stock,
                          const GridSpec& grid, const SimulationOptions& options = {});

}  // namespace scallop
