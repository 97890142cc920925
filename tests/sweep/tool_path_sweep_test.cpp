// From tool paths to swept moves: rapids dropped, collinear moves merged exactly, one
// primitive per turning move.
#include "sweep/tool_path_sweep.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "base/constants.h"
#include "base/input_error.h"

namespace scallop {
namespace {

Move cut(const Vec3& a, const Vec3& b, const Vec3& axisA, const Vec3& axisB) {
  return Move{{a, axisA}, {b, axisB}, false};
}

TEST(ToolPathSweep, RapidsAreDroppedAndCollinearMovesMerged) {
  const Cutter bull = Cutter::make(CutterType::Bull, 3, 1);
  const Vec3 up{0, 0, 1};
  ToolPath path;
  for (int k = 0; k < 100; ++k)  // one pass cut into 100 moves
    path.moves.push_back(cut({0.05 * k, 0, 0}, {0.05 * (k + 1), 0, 0}, up, up));
  path.moves.push_back(Move{{{5, 0, 0}, up}, {{0, 2, 0}, up}, true});
  path.moves.push_back(cut({0, 2, 0}, {5, 2, 0}, up, up));
  path.moves.push_back(cut({5, 2, 0}, {6, 2, 0.5}, up, up));  // a ramp: not collinear
  const std::vector<SweptMove> segs = sweepToolPath(bull, path);
  ASSERT_EQ(segs.size(), 3u);
  EXPECT_EQ(segs[0].start(), (Vec3{0, 0, 0}));
  EXPECT_NEAR(segs[0].end().x, 5, 1e-12);
  // The merged segment is the same solid: its heights equal the single move's.
  const SweptSegment single(bull, {0, 0, 0}, {5, 0, 0}, up);
  for (double x = -3.5; x <= 8.5; x += 0.37) {
    for (double y = -3.5; y <= 3.5; y += 0.29) {
      const LowestPoint a = segs[0].lowestPoint(x, y), b = single.lowestPoint(x, y);
      ASSERT_EQ(a.hit, b.hit);
      if (a.hit) {
        EXPECT_NEAR(a.z, b.z, 1e-12);
      }
    }
  }
}

TEST(ToolPathSweep, TurningMoveIsOnePrimitiveBelowEveryStamp) {
  const Cutter bull = Cutter::make(CutterType::Bull, 3, 1);
  const double phi = degToRad(2.0);  // the axis turns by 2 degrees along the move
  const Vec3 a0{0, 0, 1}, a1{std::sin(phi), 0, std::cos(phi)};
  const Vec3 p0{0, 0, 0}, p1{1, 0.3, -0.1};
  ToolPath path;
  path.moves.push_back(cut(p0, p1, a0, a1));
  const std::vector<SweptMove> moves = sweepToolPath(bull, path);
  ASSERT_EQ(moves.size(), 1u);
  ASSERT_TRUE(moves[0].turning());

  // The true rotating cutter stamped at 20001 poses (tip lerp, axis slerp as
  // CONVENTIONS.md writes it): every stamp is a point of the swept solid, at or above
  // its lowest point F, and the primitive returns a height within its proof gap of F
  // (F <= height <= F + 1e-9 mm), so never more than 1e-9 mm above the lowest stamp;
  // between stamps 5e-5 apart in t the scallop left is far below 1e-6 mm.
  const int kStamps = 20001;
  double worst = 0;
  for (double x : {-1.0, 0.2, 0.5, 0.8, 1.7}) {
    for (double y : {-1.5, 0.0, 0.15, 0.4, 2.0}) {
      const LowestPoint lp = moves[0].lowestPoint(x, y);
      double stamped = HUGE_VAL;
      for (int k = 0; k < kStamps; ++k) {
        const double t = double(k) / (kStamps - 1);
        const Vec3 tip = p0 + (p1 - p0) * t;
        const Vec3 axis = normalize(a0 * (std::sin((1 - t) * phi) / std::sin(phi)) +
                                    a1 * (std::sin(t * phi) / std::sin(phi)));
        const LowestPoint s = cutterLowestPoint(bull, axis, x - tip.x, y - tip.y);
        if (s.hit) stamped = std::min(stamped, s.z + tip.z);
      }
      ASSERT_EQ(lp.hit, std::isfinite(stamped)) << x << " " << y;
      if (!lp.hit) continue;
      EXPECT_LE(lp.z, stamped + 1e-9) << x << " " << y;
      EXPECT_GE(lp.z, stamped - 1e-6) << x << " " << y;
      worst = std::max(worst, stamped - lp.z);
    }
  }
  std::printf("turning axis: worst (stamped - exact) = %.3g mm\n", worst);
}

TEST(ToolPathSweep, HalfTurnIsRefusedByMove) {
  const Cutter ball = Cutter::make(CutterType::Ball, 3);
  ToolPath path;
  path.moves.push_back(cut({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0, 0, 1}));
  path.moves.push_back(cut({1, 0, 0}, {2, 0, 0}, {0, 0, 1}, {0, 0, -1}));  // 180 degrees
  try {
    sweepToolPath(ball, path);
    FAIL() << "a half turn accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("path move 2"), std::string::npos) << e.what();
  }
}

// A path handed over in parts (a file streamed a band at a time) sweeps to the same
// entries, bit for bit, as the whole path: merges and the spindle's phase carry across
// the parts' boundaries, with and without a window.
TEST(ToolPathSweep, APathInPartsSweepsToTheWholePathsMoves) {
  const std::vector<Cutter> cutters = {Cutter::make(CutterType::Ball, 0.5),
                                       Cutter::make(CutterType::Bull, 0.4, 0.1)};
  const Vec3 up{0, 0, 1};
  ToolPath path;
  for (int pass = 0; pass < 6; ++pass) {
    const double y = 0.6 * pass;
    const uint16_t tool = uint16_t(pass % 2);
    // Points 3 and 6 of a pass are raised: the level pairs between them merge.
    auto z = [](int k) { return k == 3 || k == 6 ? -0.1 : -0.2; };
    for (int k = 0; k < 9; ++k) {
      const double z0 = z(k), z1 = z(k + 1);
      Move m = cut({0.3 * k, y, z0}, {0.3 * (k + 1), y, z1}, up, up);
      m.tool = tool;
      m.feedPerTooth = 0.05 + 0.01 * pass;
      m.spindle = int8_t(pass % 3 == 2 ? -1 : 1);
      path.moves.push_back(m);
    }
    Move turn = cut({2.7, y, -0.2}, {2.9, y + 0.3, -0.15}, up, normalize(Vec3{0.1, 0, 1}));
    turn.tool = tool, turn.feedPerTooth = 0.06;
    path.moves.push_back(turn);
    path.moves.push_back(Move{{{2.9, y + 0.3, 1}, up}, {{0, y + 0.6, 1}, up}, true});
  }
  CuttingModel teeth;
  teeth.kind = CuttingModelKind::Teeth;
  teeth.phaseDeg = 30;
  const SweepWindow window{-1, 1.0, 4, 2.0};
  for (const CuttingModel& cutting : {CuttingModel(), teeth})
    for (const SweepWindow* w : {static_cast<const SweepWindow*>(nullptr), &window})
      for (size_t partMoves : {size_t(1), size_t(4), size_t(7)}) {
        const std::vector<SweptMove> whole = sweepToolPath(cutters, path, cutting, w);
        ToolPathSweeper sweeper(cutters, cutting, w, path.cuttingMoves());
        for (size_t k = 0; k < path.moves.size(); k += partMoves) {
          ToolPath part;
          part.moves.assign(
              path.moves.begin() + std::ptrdiff_t(k),
              path.moves.begin() + std::ptrdiff_t(std::min(path.moves.size(), k + partMoves)));
          sweeper.add(part);
        }
        const std::vector<SweptMove> parts = sweeper.finish();
        ASSERT_EQ(parts.size(), whole.size()) << partMoves;
        ASSERT_LT(whole.size(), path.cuttingMoves());  // some moves merged
        for (size_t e = 0; e < whole.size(); ++e) {
          ASSERT_EQ(parts[e].start(), whole[e].start());
          ASSERT_EQ(parts[e].end(), whole[e].end());
          ASSERT_EQ(parts[e].turning(), whole[e].turning());
          for (double x = -0.5; x < 3.5; x += 0.23)
            for (double dy = -0.6; dy < 0.9; dy += 0.17) {
              const double y = whole[e].start().y + dy;
              const LowestPoint a = parts[e].lowestPoint(x, y), b = whole[e].lowestPoint(x, y);
              ASSERT_EQ(a.hit, b.hit);
              if (a.hit) {
                ASSERT_EQ(a.z, b.z) << "entry " << e << " at " << x << ", " << y;
              }
            }
        }
      }
}

}  // namespace
}  // namespace scallop
