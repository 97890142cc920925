// A frame's depth (raycast/frame_depth.h, CONVENTIONS.md "Frames"): only the part of a
// cell's line with w >= -depth counts. Three flat R2 slots along x behind a stock face,
// seen from that face (normal -Y, depth 5), against the contract's closed forms: a slot
// entirely beyond the depth leaves the face, one across it cuts through to -depth, one
// within it shows its own wall.
#include "raycast/frame_depth.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "raycast/simulation.h"

namespace scallop {
namespace {

TEST(FrameDepth, OnlyCutsWithinTheDepthShow) {
  // The stock: x in [0, 20], the face at y = 0, z in [-10, 0]; the frame on the face,
  // looking along -Y: w = -y, map coordinates (x, z + 10).
  const Box3 stock{{0, 0, -10}, {20, 30, 0}};
  const GridFrame frame = makeGridFrame({0, 0, -10}, {1, 0, 0}, {0, -1, 0}, 20, 10, 5, "frame");
  const Cutter flat = Cutter::make(CutterType::Flat, 2.0);
  // Slots at y = 15 (w in [-17, -13]), y = 5 (w in [-7, -3]) and y = 1.5 (w in [-3.5, 0.5]),
  // the cutter's bottom at z = -3.
  ToolPath path;
  const Vec3 up{0, 0, 1};
  for (const auto& [x0, y] : {std::pair{2.0, 15.0}, {9.0, 5.0}, {16.0, 1.5}}) {
    Move m;
    m.from = {{x0, y, -3}, up};
    m.to = {{x0 + 2, y, -3}, up};
    path.moves.push_back(m);
  }
  SimulationOptions options;
  options.frame = frame;
  const SimulationResult r =
      simulate(flat, pathInFrame(path, frame), stock, frame.grid(0.25), options);
  const ZMap& map = r.map;
  auto at = [&](double x, double z) {
    const GridSpec& g = map.grid();
    return map.at(int64_t(x / g.spacing), int64_t((z + 10) / g.spacing));
  };
  EXPECT_EQ(at(3, -1), 0.0);    // beyond the depth: the face (was -5)
  EXPECT_EQ(at(10, -1), -5.0);  // across it: cut through
  EXPECT_NEAR(at(17, -1), -3.5, 1e-12);  // within it: the slot's far wall
  EXPECT_EQ(at(10, -5), 0.0);   // below the slots' floor: the face
  EXPECT_GT(r.frameCells.cutThroughCells, 0);
  // Every cell of the first slot's columns reads the face.
  for (int64_t j = 0; j < map.ny(); ++j)
    for (int64_t i = 0; i < int64_t(6 / map.grid().spacing); ++i)
      EXPECT_EQ(map.at(i, j), 0.0) << i << " " << j;
}

}  // namespace
}  // namespace scallop
