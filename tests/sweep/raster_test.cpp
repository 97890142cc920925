#include "sweep/raster.h"

#include <gtest/gtest.h>

#include <cmath>

#include "base/constants.h"
#include "base/input_error.h"
#include "sweep/swept_segment.h"

namespace scallop {
namespace {

TEST(Raster, LeadOnlyIsAPlainRotationTowardsTheFeed) {
  const Vec3 a = leadTiltAxis({1, 0, 0}, 5, 0);
  EXPECT_NEAR(a.x, std::sin(degToRad(5)), 1e-15);
  EXPECT_NEAR(a.y, 0, 1e-15);
  EXPECT_NEAR(a.z, std::cos(degToRad(5)), 1e-15);
  const Vec3 t = leadTiltAxis({1, 0, 0}, 0, 10);  // tilt towards c = z x f = +y
  EXPECT_NEAR(t.y, std::sin(degToRad(10)), 1e-15);
}

TEST(Raster, PassesDepthAndExtent) {
  const Cutter bull = Cutter::make(CutterType::Bull, 3, 1);
  const Box3 stock({0, 0, -5}, {20, 20, 0});
  RasterSpec spec;
  spec.stepOver = 2.5;
  spec.depth = 0.5;
  spec.leadDeg = 5;
  const ToolPath path = makeRaster(bull, stock, spec);
  // Passes at y = 0, 2.5, ..., 20: nine cutting moves and eight rapids between them.
  EXPECT_EQ(path.cuttingMoves(), 9u);
  EXPECT_EQ(path.moves.size(), 17u);
  const Move& first = path.moves.front();
  EXPECT_DOUBLE_EQ(first.from.tip.x, -4.0);
  EXPECT_DOUBLE_EQ(first.to.tip.x, 24.0);
  // The lowest point of the tilted cutter is at the floor, z = -0.5.
  const double lowest = first.from.tip.z + cutterSupport(bull, first.from.axis, {0, 0, -1}).z;
  EXPECT_NEAR(lowest, -0.5, 1e-12);
  // For a torus tilted by rho the lowest point is Rb sin(rho) + r (1 - cos(rho)) below
  // the tip (the centre circle's lowest point, then down by r).
  const double rho = degToRad(5);
  EXPECT_NEAR(first.from.tip.z, -0.5 + 2 * std::sin(rho) + 1 * (1 - std::cos(rho)), 1e-12);
}

TEST(Raster, RejectsBadFieldsByName) {
  const Cutter ball = Cutter::make(CutterType::Ball, 3);
  const Box3 stock({0, 0, -5}, {20, 20, 0});
  RasterSpec spec;
  spec.stepOver = 0;
  try {
    makeRaster(ball, stock, spec);
    FAIL() << "step_over = 0 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("path.raster.step_over"), std::string::npos);
  }
  spec.stepOver = 1;
  spec.leadDeg = 90;
  EXPECT_THROW(makeRaster(ball, stock, spec), InputError);
  // Absurdly many moves are refused rather than exhausting memory.
  spec.leadDeg = 0;
  spec.segmentLength = 1e-9;
  try {
    makeRaster(ball, stock, spec);
    FAIL() << "1e12 moves accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("path.raster.segment_length"), std::string::npos);
  }
}

}  // namespace
}  // namespace scallop
