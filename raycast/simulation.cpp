#include "raycast/simulation.h"

#include <algorithm>
#include <cmath>

#include "raycast/frame_depth.h"
#include "raycast/tile_grid.h"
#include "sweep/contact_knots.h"
#include "sweep/tip_ball.h"

namespace scallop {

SceneOptions sceneOptionsFor(const Box3& stock, double spacing, const SimulationOptions& options) {
  SceneOptions sceneOptions;
  sceneOptions.tileSize = options.tileSize;
  sceneOptions.stockTop = options.frame ? stockTopInFrame(stock, *options.frame) : stock.max.z;
  // Candidate regions of options.cast.regionCells cells a side (zmap_caster.cpp), by
  // default about 64 um but 8 to 32 cells: a region's candidates are the moves that may
  // be lowest anywhere in it, so a wide region keeps more of them for every cell, while
  // each region pays a gathering query and an evaluation per candidate. Measured (exact
  // evaluations a cell): B3's turning path at 10 um, 7.7 with 32 cells, 5.0 with 8; at
  // 20 um 16.5 with 32, 6.7 with 8, 13.3 with 3; B1 at 1 um and B3 at 2 um keep 32.
  const int64_t cells = options.cast.regionCells > 0
                            ? options.cast.regionCells
                            : std::clamp<int64_t>(int64_t(0.064 / spacing + 1e-9), 8, 32);
  sceneOptions.regionHalfSize = 0.5 * double(cells - 1) * spacing;
  // Knots about 8 cells apart, none for coarse cells (contact_knots.h): on B3 at 20 um
  // cells, fixed 16 um knots cost twice what they saved (every cell located its own four).
  sceneOptions.contactKnotSpacing = contactKnotSpacingFor(spacing);
  return sceneOptions;
}

namespace {

// A box that holds the cutter at every pose of a move (xy only; z from the tips'
// lower end down by nothing, up by R + flute): the tips' box grown by the cutter's widest
// horizontal reach at the more leaning end (slerp between axes with k >= 0 never leans
// more than its ends). `R` is the cutter's radius with runout.
struct MoveReach {
  double x0, y0, x1, y1;
};
// The box of a move's tips: its ends, or the whole arc's (path.arcs) for an arc.
Box3 tipsBox(const ToolPath& path, const Move& m) {
  if (m.arc > 0 && m.arc <= path.arcs.size()) return path.arcs[m.arc - 1].bounds();
  Box3 tips;
  tips.extend(m.from.tip);
  tips.extend(m.to.tip);
  return tips;
}

MoveReach moveReach(const ToolPath& path, const Move& m, double R, double flute) {
  const auto lean = [](const Vec3& a) { return std::hypot(a.x, a.y) / length(a); };
  const double reach = R + flute * std::fmax(lean(m.from.axis), lean(m.to.axis));
  const Box3 tips = tipsBox(path, m);
  return {tips.min.x - reach, tips.min.y - reach, tips.max.x + reach, tips.max.y + reach};
}

// The R and flute of the reach above: the spindle envelope's (runout and outward tooth
// offsets, Cutter::spindleEnvelope), its flutes longer by the teeth that reach below the
// tip (the envelope is swept that much lower, sweepToolPath).
struct EnvelopeSize {
  double R, flute;
};
EnvelopeSize envelopeSize(const Cutter& cutter) {
  return {cutter.radius + cutter.teeth.runout + cutter.teeth.radialReach(),
          cutter.fluteLength + cutter.teeth.axialReach()};
}

// A move that can cut: not a rapid, and its lowest tip within R + flute of the stock top.
bool mayCut(const ToolPath& path, const Move& m, double R, double flute, double stockTop) {
  return !m.rapid && tipsBox(path, m).min.z - R - flute < stockTop;
}

}  // namespace

double programCellsPerMove(const Cutter& cutter, const ToolPath& path, const Box3& stock,
                           double spacing) {
  const auto [R, flute] = envelopeSize(cutter);
  size_t reaching = 0;
  for (const Move& m : path.moves) {
    if (!mayCut(path, m, R, flute, stock.max.z)) continue;
    const MoveReach r = moveReach(path, m, R, flute);
    reaching +=
        r.x1 >= stock.min.x && r.x0 <= stock.max.x && r.y1 >= stock.min.y && r.y0 <= stock.max.y;
  }
  if (reaching == 0 || !(spacing > 0)) return HUGE_VAL;
  const double cells =
      (stock.max.x - stock.min.x) * (stock.max.y - stock.min.y) / (spacing * spacing);
  return cells / double(reaching);
}

namespace {

// What estimateSceneBytes counts for each cutting move that may reach below the stock
// top: its xy reach and its bytes (the SweptMove and its culling tiles).
template <class Visit>
size_t visitMoveSceneBytes(const Cutter& cutter, const ToolPath& path, const Box3& stock,
                           double spacing, const CuttingModel& cutting, Visit visit) {
  // The tile itself + the most the tile grid takes a tile.
  constexpr double kBytesPerTile =
      sizeof(scene_detail::TileBox) + scene_detail::TileGrid::kMaxBytesPerTile;
  const auto [R, flute] = envelopeSize(cutter);
  SceneOptions tiling;
  tiling.cellsPerMove = programCellsPerMove(cutter, path, stock, spacing);
  // A general cutter with a ball tip holds the hemisphere's move beside its own.
  const bool tipBall = cutter.general() && tipBallOf(cutter).valid;
  size_t counted = 0;
  for (const Move& m : path.moves) {
    if (!mayCut(path, m, R, flute, stock.max.z)) continue;
    const MoveReach r = moveReach(path, m, R, flute);
    const double w = r.x1 - r.x0, h = r.y1 - r.y0;
    const bool arc = m.arc > 0 && m.arc <= path.arcs.size();
    const double len =
        arc ? PoseCurve::ofMove(path, m).pathLength() : length(m.to.tip - m.from.tip);
    const double T = cullingTileSide(R, len, w * h, tiling);
    const bool turning = arc || PoseCurve::turns(m.from.axis, m.to.axis);
    const bool ccw = m.spindle != 0 ? m.spindle < 0 : cutting.counterClockwise;
    visit(r, double(SweptMove::bytesPerMove(turning, cutting.teeth(), tipBall, ccw)) +
                 kBytesPerTile * std::fmax(1, std::ceil(w / T)) * std::fmax(1, std::ceil(h / T)));
    ++counted;
  }
  return counted;
}

}  // namespace

double estimateSceneBytes(const Cutter& cutter, const ToolPath& path, const Box3& stock,
                          double spacing, size_t* moves, const CuttingModel& cutting) {
  double need = 0;
  const size_t counted =
      visitMoveSceneBytes(cutter, path, stock, spacing, cutting,
                          [&](const MoveReach&, double bytes) { need += bytes; });
  if (moves) *moves = counted;
  return need;
}

std::vector<double> estimateBandSceneBytes(const Cutter& cutter, const ToolPath& path,
                                           const Box3& stock, const GridSpec& grid,
                                           int64_t bandRows, const CuttingModel& cutting) {
  const int64_t bands = (grid.ny + bandRows - 1) / bandRows;
  // Each move adds its bytes to the bands [first, last] its reach meets: +bytes at first,
  // -bytes after last, summed once at the end (the cost does not grow with the bands).
  std::vector<double> delta(size_t(bands) + 1, 0.0);
  // Image row r holds the cells j = ny - 1 - r, whose lines lie at y = cellCentreY(j).
  const auto bandOfJ = [&](int64_t j) { return (grid.ny - 1 - j) / bandRows; };
  visitMoveSceneBytes(cutter, path, stock, grid.spacing, cutting,
                      [&](const MoveReach& r, double bytes) {
                        if (r.x1 < grid.cellCentreX(0) || r.x0 > grid.cellCentreX(grid.nx - 1))
                          return;
                        // The rows whose centre lines lie in [y0, y1].
                        const double jLo = std::ceil((r.y0 - grid.cellCentreY(0)) / grid.spacing);
                        const double jHi = std::floor((r.y1 - grid.cellCentreY(0)) / grid.spacing);
                        // One row of margin each side for the rounding of the divisions.
                        const int64_t j0 = int64_t(std::fmax(0.0, jLo - 1));
                        const int64_t j1 = int64_t(std::fmin(double(grid.ny - 1), jHi + 1));
                        if (j0 > j1) return;
                        delta[size_t(bandOfJ(j1))] += bytes;
                        delta[size_t(bandOfJ(j0)) + 1] -= bytes;
                      });
  std::vector<double> need(size_t(bands), 0.0);
  double running = 0;
  for (size_t b = 0; b < need.size(); ++b) need[b] = running += delta[b];
  return need;
}

SweepWindow cellWindow(const GridSpec& grid) {
  SweepWindow w;
  w.x0 = grid.cellCentreX(0), w.x1 = grid.cellCentreX(grid.nx - 1);
  w.y0 = grid.cellCentreY(0), w.y1 = grid.cellCentreY(grid.ny - 1);
  return w;
}

std::unique_ptr<SweptScene> buildScene(const Cutter& cutter, const ToolPath& path,
                                       const Box3& stock, double spacing,
                                       const SimulationOptions& options,
                                       const SweepWindow* window) {
  // The whole program's cells a move, also for a window's scene: the same culling tiles.
  return buildSceneOfMoves(sweepToolPath(cutter, path, options.cutting, window), stock, spacing,
                           programCellsPerMove(cutter, path, stock, spacing), options);
}

std::unique_ptr<SweptScene> buildSceneOfMoves(std::vector<SweptMove> moves, const Box3& stock,
                                              double spacing, double cellsPerMove,
                                              const SimulationOptions& options) {
  SceneOptions sceneOptions = sceneOptionsFor(stock, spacing, options);
  sceneOptions.cellsPerMove = cellsPerMove;
  return std::make_unique<SweptScene>(std::move(moves), sceneOptions);
}

SimulationResult simulate(const Cutter& cutter, const ToolPath& path, const Box3& stock,
                          const GridSpec& grid, const SimulationOptions& options) {
  // The progress callback is also where the caller stops a run (a Ctrl-C throws there):
  // it hears of the scene and of the map's first touch too, neither of which polls
  // inside (seconds on a large 5-axis path or a map of gigabytes).
  const auto phaseDone = [&] {
    if (options.cast.progress) options.cast.progress(0, grid.cells());
  };
  // Only the moves that may reach the grid's cell lines are swept: a window of a large
  // program builds the scene of its own moves (judged after merging, so the heights are
  // the whole scene's, bit for bit, as for a band: tools/run/tiled_simulation.h).
  const SweepWindow window = cellWindow(grid);
  const std::unique_ptr<SweptScene> scene =
      buildScene(cutter, path, stock, grid.spacing, options, &window);
  phaseDone();
  SimulationResult result;
  result.map = ZMap(grid, stock.max.z);
  if (options.frame) fillFrameStock(result.map, stock, *options.frame);
  if (options.fillStock) options.fillStock(result.map);
  phaseDone();
  result.cast = castZMap(*scene, result.map, options.cast);
  if (options.frame) {
    cutToFrameDepth(*scene, result.map, stock, *options.frame);
    result.frameCells = finishFrameMap(result.map, *options.frame);
  }
  if (options.fillStock) result.frameCells = finishStockMap(result.map);
  result.scene = scene->stats();
  return result;
}

}  // namespace scallop
