// The mount_rush check: OpenCAMLib's drop-cutter paths over a real
// STL relief (tests/data/mount_rush, README there), simulated exactly and compared
// with the design's upper envelope. Every gouge the simulation finds must be chordal:
// the linear move between two contact points dips below the height at which the
// cutter would touch the mesh. For each move that makes a gouge cell, an independent
// drop-cutter (analysis/drop_cutter.h, no swept-solid code) finds the largest dip
// along the move and its contact point q; the simulated depth at q (q.z minus the
// move's exact swept height there) must equal that dip within 1e-4 mm, and no gouge
// cell may be deeper than the dips of the moves that made it.
#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <mutex>

#include "analysis/design_deviation.h"
#include "analysis/drop_cutter.h"
#include "analysis/gouge_check.h"
#include "raycast/simulation.h"
#include "tools/io/stl_io.h"
#include "tools/io/tool_path_file.h"

namespace scallop {
namespace {

const std::string kDir = std::string(SCALLOP_SOURCE_DIR) + "/tests/data/mount_rush/";

// Largest chord dip (drop-cutter height minus chord height) along a move: 21 samples,
// then golden-section search around the best one. Returns the dip and its contact.
std::pair<double, DropContact> largestDip(const DropCutter& dc, const Move& mv) {
  auto dip = [&](double t, DropContact* contact) {
    const Vec3 p = mv.from.tip + (mv.to.tip - mv.from.tip) * t;
    const DropContact c = dc.drop(p.x, p.y);
    if (contact) *contact = c;
    return c.hit ? c.tipZ - p.z : -HUGE_VAL;
  };
  constexpr int kSamples = 20;
  int bestK = 0;
  double best = -HUGE_VAL;
  for (int k = 0; k <= kSamples; ++k) {
    const double d = dip(double(k) / kSamples, nullptr);
    if (d > best) best = d, bestK = k;
  }
  double lo = std::max(0, bestK - 1) / double(kSamples);
  double hi = std::min(kSamples, bestK + 1) / double(kSamples);
  const double g = (std::sqrt(5.0) - 1) / 2;
  double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
  double fa = dip(a, nullptr), fb = dip(b, nullptr);
  for (int it = 0; it < 60; ++it) {
    if (fa >= fb) {
      hi = b, b = a, fb = fa, a = hi - g * (hi - lo), fa = dip(a, nullptr);
    } else {
      lo = a, a = b, fa = fb, b = lo + g * (hi - lo), fb = dip(b, nullptr);
    }
  }
  double tBest = bestK / double(kSamples);
  for (double t : {a, b})
    if (dip(t, nullptr) > best) best = dip(t, nullptr), tBest = t;
  DropContact contact;
  dip(tBest, &contact);
  return {best, contact};
}

void checkPath(const std::string& file, const Cutter& cutter, double spacing) {
  const auto t0 = std::chrono::steady_clock::now();
  const TriangleMesh mesh = readStl(kDir + "mount_rush.stl");
  const ToolPathFile path = readToolPathFile(kDir + file);
  const DropCutter dc(cutter, mesh);

  // 1. The file's own locations are drop-cutter contacts (validates the reference
  //    against OpenCAMLib): equal heights, or the floor where the cutter misses.
  std::vector<Vec3> locations{path.path.moves.front().from.tip};
  for (const Move& mv : path.path.moves) locations.push_back(mv.to.tip);
  std::atomic<int> misses{0}, mismatches{0};
  tbb::parallel_for(size_t(0), locations.size(), [&](size_t k) {
    const DropContact c = dc.drop(locations[k].x, locations[k].y);
    if (!c.hit)
      ++misses;
    else if (std::fabs(c.tipZ - locations[k].z) > 1e-6)
      ++mismatches;
  });
  EXPECT_EQ(mismatches.load(), 0) << file;
  EXPECT_EQ(misses.load(), 3036) << file;  // the README's count of floor points

  // 2. Simulate over the relief and compare with the design's upper envelope.
  const Box3 stock({-41, -25, -27}, {45, 18.5, 2});
  const GridSpec grid = gridCovering(stock.min.x, stock.min.y, stock.max.x, stock.max.y, spacing);
  SimulationOptions options;
  options.tileSize = cutter.radius;  // coarse culling tiles: the test's time is the scene's
  const ZMap map = simulate(cutter, path.path, stock, grid, options).map;
  const MeshIndex index(mesh);
  const ZMap design = designHeights(index, grid);

  // 3. Gouge cells (deeper than 1e-6 mm below the design) and the moves that made them.
  std::vector<int64_t> gougeCells;
  std::vector<Box3> areas;
  for (int64_t k = 0; k < grid.cells(); ++k) {
    const double d = design.heights()[size_t(k)];
    if (!std::isnan(d) && d - map.heights()[size_t(k)] > 1e-6) {
      gougeCells.push_back(k);
      const double x = grid.cellCentreX(k % grid.nx), y = grid.cellCentreY(k / grid.nx);
      Box3 b;
      b.extend({x, y, 0});
      areas.push_back(b);
    }
  }
  const MoveFinder finder(cutter, path.path, areas);
  std::vector<std::vector<size_t>> makers(gougeCells.size());
  std::vector<char> offending(path.path.moves.size(), 0);
  tbb::parallel_for(size_t(0), gougeCells.size(), [&](size_t n) {
    const int64_t k = gougeCells[n];
    makers[n] = finder.movesAt(grid.cellCentreX(k % grid.nx), grid.cellCentreY(k / grid.nx),
                               map.heights()[size_t(k)], 1e-7);
    for (size_t m : makers[n]) offending[m] = 1;
  });

  // 4. Each offending move: the drop-cutter's largest dip equals the simulated depth at
  //    its contact point.
  std::vector<double> dips(path.path.moves.size(), -HUGE_VAL);
  std::mutex lock;
  double worst = 0, deepest = 0;
  int moves = 0;
  tbb::parallel_for(size_t(0), offending.size(), [&](size_t m) {
    if (!offending[m]) return;
    const auto [dip, q] = largestDip(dc, path.path.moves[m]);
    dips[m] = dip;
    const double simulated = q.point.z - finder.moveHeight(m, q.point.x, q.point.y);
    std::lock_guard<std::mutex> guard(lock);
    ++moves;
    worst = std::max(worst, std::fabs(simulated - dip));
    deepest = std::max(deepest, dip);
    EXPECT_GT(dip, 0) << file << ":" << path.moveLines[m];
    EXPECT_NEAR(simulated, dip, 1e-4) << file << ":" << path.moveLines[m];
  });

  // 5. Every gouge cell is explained: made by moves, none deeper than their dips.
  int unexplained = 0;
  double deepestCell = 0;
  for (size_t n = 0; n < gougeCells.size(); ++n) {
    const int64_t k = gougeCells[n];
    const double depth = design.heights()[size_t(k)] - map.heights()[size_t(k)];
    deepestCell = std::max(deepestCell, depth);
    double dip = -HUGE_VAL;
    for (size_t m : makers[n]) dip = std::max(dip, dips[m]);
    if (makers[n].empty() || depth > dip + 1e-6) ++unexplained;
  }
  EXPECT_EQ(unexplained, 0) << file;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf(
      "%s: %zu gouge cells of %lld (deepest %.4f mm), %d offending moves, largest dip "
      "%.4f mm, |simulated - dip| <= %.2e mm, %.1f s\n",
      file.c_str(), gougeCells.size(), (long long)grid.cells(), deepestCell, moves, deepest, worst,
      seconds);
}

TEST(MountRush, BallPathGougesAreChordDips) {
  checkPath("ball_raster.cl.txt", Cutter::make(CutterType::Ball, 3.0), 0.1);
}

TEST(MountRush, BullPathGougesAreChordDips) {
  checkPath("bull_raster.cl.txt", Cutter::make(CutterType::Bull, 3.0, 1.0), 0.1);
}

}  // namespace
}  // namespace scallop
