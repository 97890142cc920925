// The normal deviation's candidate search (analysis/normal_deviation.h): moves found
// through the index of their boxes (move_line_index.h) give the bits of trying every
// move, on a random design and random moves.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "analysis/normal_deviation.h"

namespace scallop {
namespace {

// A wavy patch (every vertex its own normal, searched through the BVH) and a tilted flat
// one with exact coordinates (one normal shared by its 100 inner vertices: the grid of
// the moves' shadows, the reuse of swept moves and sections), facets wound to face up.
TriangleMesh randomDesign(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  const double a = 0.4 * u(rng), phase = 3 * u(rng);
  const double slope = 0.0625 * double(1 + rng() % 3);  // exact: the facets' normals are equal
  std::vector<std::array<Vec3, 3>> soup;
  const auto addGrid = [&](int n, double x0, double step, auto height) {
    const auto at = [&](int i, int j) {
      const double x = x0 + i * step, y = j * step;
      return Vec3{x, y, height(x, y)};
    };
    for (int i = 0; i + 1 < n; ++i)
      for (int j = 0; j + 1 < n; ++j) {
        soup.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
        soup.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
  };
  addGrid(12, 0, 0.5, [&](double x, double y) { return a * std::sin(x + phase) * std::cos(y); });
  addGrid(12, 7, 0.5, [&](double x, double) { return slope * (x - 7) - 0.25; });
  return meshFromTriangles(soup);
}

// Cutting moves of three cutters over the design, a few with a turning axis, a few with
// the axis tilted past the horizontal (unresolved where they reach), and rapids.
ToolPath randomMoves(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  ToolPath path;
  path.cutters = {Cutter::make(CutterType::Ball, 1), Cutter::make(CutterType::Flat, 0.8),
                  Cutter::make(CutterType::Bull, 1.2, 0.4)};
  const auto axis = [&](double spread) {
    const Vec3 a{spread * u(rng), spread * u(rng), 1};
    return a / length(a);
  };
  for (int k = 0; k < 40; ++k) {
    Move m;
    m.tool = uint16_t(k % 3);
    m.rapid = k % 13 == 12;
    m.from.tip = {6.5 + 7.5 * u(rng), 2.75 + 3.5 * u(rng), 0.5 * u(rng)};
    m.to.tip = m.from.tip + Vec3{2 * u(rng), 2 * u(rng), 0.2 * u(rng)};
    m.from.axis = axis(k % 7 == 6 ? 3.0 : 0.5);
    m.to.axis = k % 4 == 3 ? axis(0.5) : m.from.axis;
    path.moves.push_back(m);
  }
  return path;
}

TEST(NormalDeviationSearch, TheIndexGivesTheBitsOfTryingEveryMove) {
  std::mt19937_64 rng(20261204);
  for (int round = 0; round < 3; ++round) {
    const TriangleMesh design = randomDesign(rng);
    const ToolPath path = randomMoves(rng);
    const Box3 stock{{-1, -1, -1}, {14, 7, 1}};
    const Cutter unused = Cutter::make(CutterType::Ball, 1);
    const NormalDeviation indexed =
        normalDeviation(unused, path, stock, design, 0.5, CandidateSearch::kIndexed);
    const NormalDeviation all =
        normalDeviation(unused, path, stock, design, 0.5, CandidateSearch::kAllMoves);
    ASSERT_EQ(indexed.deviation.size(), design.vertices.size());
    ASSERT_EQ(all.deviation.size(), design.vertices.size());
    int measured = 0;
    for (size_t v = 0; v < design.vertices.size(); ++v) {
      EXPECT_EQ(std::memcmp(&indexed.deviation[v], &all.deviation[v], sizeof(double)), 0)
          << "round " << round << " vertex " << v << ": " << indexed.deviation[v] << " vs "
          << all.deviation[v];
      EXPECT_EQ(indexed.status[v], all.status[v]) << v;
      measured += indexed.status[v] == VertexDeviation::kMeasured && indexed.deviation[v] < 0.5;
    }
    // The same (vertex, move) pairs survive the exact bounds, and the kernel is asked
    // about the same ones.
    EXPECT_EQ(indexed.candidates, all.candidates);
    EXPECT_EQ(indexed.exactEvaluations, all.exactEvaluations);
    // The case is not vacuous: moves cut many lines, and some reach one from behind.
    EXPECT_GT(measured, 30) << round;
    EXPECT_GT(indexed.exactEvaluations, design.vertices.size() / 2) << round;
    EXPECT_GT(indexed.unresolved + indexed.cutThrough, 0) << round;
  }
}

}  // namespace
}  // namespace scallop
