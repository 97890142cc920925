// Height maps in any frame (raycast/grid_frame.h, CONVENTIONS.md "Frames"): the frame's
// checks, the stock seen in a frame against closed forms, and a tilted raster's frame
// map against the z-map of the same job level.
#include "raycast/grid_frame.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "base/constants.h"
#include "base/input_error.h"
#include "raycast/simulation.h"
#include "sweep/pose_curve.h"
#include "sweep/raster.h"

namespace scallop {
namespace {

std::string whereOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.where();
  }
  return "no error";
}

// A path moved into a frame moves its arcs too: every tip of an arc move (a helix about
// a tilted axis) is the world tip seen in the frame.
TEST(GridFrame, ArcsMoveIntoTheFrameWithTheirMoves) {
  const GridFrame frame =
      makeGridFrame({1, -2, 0.5}, normalize(Vec3{0.6, 0.8, 0}), normalize(Vec3{0.8, -0.6, 1}), 10,
                    10, HUGE_VAL, "grid.frame");
  ToolPath path;
  ArcMotion arc;
  arc.centre = {2, 1, -0.5};
  arc.u = normalize(Vec3{1, 0, 0.2});
  arc.v = normalize(cross(Vec3{0.1, 0, 1}, arc.u));
  arc.angle0 = 0.4, arc.sweep = -2.5, arc.radius0 = 3, arc.radius1 = 3.001, arc.rise = 0.7;
  path.arcs.push_back(arc);
  Move m;
  m.from = {arc.at(0), {0, 0, 1}};
  m.to = {arc.at(1), {0, 0, 1}};
  m.arc = 1;
  path.moves.push_back(m);
  const ToolPath inFrame = pathInFrame(path, frame);
  const PoseCurve world = PoseCurve::ofMove(path, path.moves[0]);
  const PoseCurve seen = PoseCurve::ofMove(inFrame, inFrame.moves[0]);
  for (int k = 0; k <= 16; ++k) {
    const double t = k / 16.0;
    const Vec3 want = frame.pointToFrame(world.tip(t)), got = seen.tip(t);
    EXPECT_LT(length(got - want), 1e-12) << "t = " << t;
  }
}

TEST(GridFrame, ZeroOrParallelVectorsAreErrorsNamingTheField) {
  const Vec3 o{0, 0, 0};
  EXPECT_EQ(whereOf([&] {
              makeGridFrame(o, {0, 0, 0}, {0, 0, 1}, 1, 1, HUGE_VAL, "grid.frame");
            }),
            "grid.frame.u");
  EXPECT_EQ(whereOf([&] {
              makeGridFrame(o, {1, 0, 0}, {0, 0, 0}, 1, 1, HUGE_VAL, "grid.frame");
            }),
            "grid.frame.normal");
  EXPECT_EQ(whereOf([&] {
              makeGridFrame(o, {1, 0, 0}, {2, 0, 0}, 1, 1, HUGE_VAL, "grid.frame");
            }),
            "grid.frame.normal");
  // 1e-8 off a right angle is refused, 1e-10 accepted.
  EXPECT_EQ(whereOf([&] {
              makeGridFrame(o, {1, 0, 1e-8}, {0, 0, 1}, 1, 1, HUGE_VAL, "grid.frame");
            }),
            "grid.frame.normal");
  EXPECT_EQ(whereOf([&] {
              makeGridFrame(o, {1, 0, 1e-10}, {0, 0, 1}, 1, 1, HUGE_VAL, "grid.frame");
            }),
            "no error");
}

TEST(GridFrame, VectorsAreNormalisedAndVIsNormalCrossU) {
  const GridFrame f = makeGridFrame({1, 2, 3}, {0, 2, 0}, {0, 0, 5}, 4, 3, HUGE_VAL, "f");
  EXPECT_EQ(f.u, (Vec3{0, 1, 0}));
  EXPECT_EQ(f.normal, (Vec3{0, 0, 1}));
  EXPECT_EQ(f.v, (Vec3{-1, 0, 0}));
  EXPECT_FALSE(f.translationOnly());
  const Vec3 p = f.pointToFrame({0, 7, 4});  // (p - o) = (-1, 5, 1)
  EXPECT_EQ(p, (Vec3{5, 1, 1}));
  const Vec3 back = f.pointFromFrame(p.x, p.y, p.z);
  EXPECT_EQ(back, (Vec3{0, 7, 4}));
  EXPECT_TRUE(
      makeGridFrame({1, 2, 3}, {1, 0, 0}, {0, 0, 1}, 4, 3, HUGE_VAL, "f").translationOnly());
}

// The box [0, 10]^2 x [-5, 0] seen along n = (0, -sin a, cos a) from (5, 5, -2): v = (0,
// cos a, sin a); the line of (x, y) leaves through the top at w = (2 - y sin a) / cos a.
TEST(GridFrame, StockExitHeightIsTheClosedForm) {
  const Box3 box{{0, 0, -5}, {10, 10, 0}};
  const double a = 0.4, s = std::sin(a), c = std::cos(a);
  const GridFrame f = makeGridFrame({5, 5, -2}, {1, 0, 0}, {0, -s, c}, 4, 4, HUGE_VAL, "f");
  for (const double y : {-1.0, 0.0, 0.5, 2.0}) {
    SCOPED_TRACE(y);
    EXPECT_NEAR(stockExitHeight(box, f, 1.5, y), (2 - y * s) / c, 1e-12);
  }
  // x = 6 puts the line at part x = 11, beside the box: no material.
  EXPECT_TRUE(std::isnan(stockExitHeight(box, f, 6, 0)));
  // Looking down at the box from 10 mm above it: its top is at w = -10, within a depth
  // of 20 mm, not within 1 mm.
  const GridFrame above = makeGridFrame({5, 5, 10}, {0, 1, 0}, {0, 0, 1}, 4, 4, 20, "f");
  EXPECT_DOUBLE_EQ(stockExitHeight(box, above, 0.5, 0.5), -10);
  GridFrame shallow = above;
  shallow.depth = 1;
  EXPECT_TRUE(std::isnan(stockExitHeight(box, shallow, 0.5, 0.5)));
  EXPECT_DOUBLE_EQ(stockTopInFrame(box, above), -10);
}

TEST(GridFrame, FinishingMakesVoidCellsNanAndClampsCutsBelowTheDepth) {
  GridFrame f;
  f.depth = 2;
  ZMap map(gridCovering(0, 0, 4, 1, 1), 0);
  map.at(0, 0) = kNoMaterial;
  map.at(1, 0) = -2.5;
  map.at(2, 0) = -2;  // exactly at the depth: not cut through
  map.at(3, 0) = -1;
  const FrameCellCounts counts = finishFrameMap(map, f);
  EXPECT_EQ(counts.voidCells, 1);
  EXPECT_EQ(counts.cutThroughCells, 1);
  EXPECT_TRUE(std::isnan(map.at(0, 0)));
  EXPECT_EQ(map.at(1, 0), -2);
  EXPECT_EQ(map.at(2, 0), -2);
  EXPECT_EQ(map.at(3, 0), -1);
  EXPECT_EQ(map.minHeight(), -2);
  EXPECT_EQ(map.maxHeight(), -1);
}

// Rodrigues' rotation of p by `angle` about the unit `axis`.
Vec3 rotate(const Vec3& p, const Vec3& axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return p * c + cross(axis, p) * s + axis * (dot(axis, p) * (1 - c));
}

// A raster with lead and tilt cut level on a box, and the same path turned by 35 deg
// about a skew axis and moved: the turned job's map in the frame that turns back with
// it equals the level z-map within 1e-9 mm in every cell (all cells are cut, so the
// stock's shape does not show).
TEST(GridFrame, TiltedRasterInItsFrameEqualsTheLevelZMap) {
  for (const CutterType type : {CutterType::Ball, CutterType::Bull, CutterType::Flat}) {
    SCOPED_TRACE(int(type));
    const Cutter cutter = Cutter::make(type, 2, type == CutterType::Bull ? 0.5 : 0);
    const Box3 level{{0, 0, -3}, {10, 8, 0}};
    RasterSpec spec;
    spec.stepOver = 1.5;
    spec.depth = 0.4;
    spec.leadDeg = 5;
    spec.tiltDeg = 3;
    const ToolPath path = makeRaster(cutter, level, spec);
    const double spacing = 0.1;
    const GridSpec grid = gridCovering(0, 0, 10, 8, spacing);
    const ZMap expected = simulate(cutter, path, level, grid).map;
    ASSERT_LT(expected.maxHeight(), -0.1);  // every cell cut

    const Vec3 axis = normalize(Vec3{1, 2, 0.5});
    const double angle = degToRad(35);
    const Vec3 shift{3, -2, 5};
    auto turn = [&](const Vec3& p) { return rotate(p, axis, angle) + shift; };
    ToolPath turned = path;
    Box3 stock;  // the box that holds the turned level box
    for (Move& m : turned.moves)
      for (Pose* pose : {&m.from, &m.to}) {
        pose->tip = turn(pose->tip);
        pose->axis = rotate(pose->axis, axis, angle);
      }
    for (int k = 0; k < 8; ++k)
      stock.extend(turn({k & 1 ? 10.0 : 0.0, k & 2 ? 8.0 : 0.0, k & 4 ? 0.0 : -3.0}));
    SimulationOptions options;
    options.frame = makeGridFrame(turn({0, 0, 0}), rotate({1, 0, 0}, axis, angle),
                                  rotate({0, 0, 1}, axis, angle), 10, 8, HUGE_VAL, "frame");
    const GridSpec frameGrid = options.frame->grid(spacing);
    ASSERT_EQ(frameGrid.nx, grid.nx);
    ASSERT_EQ(frameGrid.ny, grid.ny);
    const SimulationResult framed =
        simulate(cutter, pathInFrame(turned, *options.frame), stock, frameGrid, options);
    EXPECT_EQ(framed.frameCells.voidCells, 0);
    double worst = 0;
    for (int64_t j = 0; j < grid.ny; ++j)
      for (int64_t i = 0; i < grid.nx; ++i)
        worst = std::max(worst, std::fabs(framed.map.at(i, j) - expected.at(i, j)));
    EXPECT_LE(worst, 1e-9);
  }
}

}  // namespace
}  // namespace scallop
