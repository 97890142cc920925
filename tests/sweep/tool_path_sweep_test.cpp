// From tool paths to swept segments: rapids dropped, collinear moves merged exactly,
// turning axes subdivided within the stated tolerance.
#include "sweep/tool_path_sweep.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sweep/input_error.h"

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
  const std::vector<SweptSegment> segs = sweepToolPath(bull, path);
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

TEST(ToolPathSweep, TurningAxisIsSubdividedWithinTolerance) {
  const Cutter bull = Cutter::make(CutterType::Bull, 3, 1);
  const double phi = 2.0 * M_PI / 180;  // the axis turns by 2 degrees along the move
  const Vec3 a0{0, 0, 1}, a1{std::sin(phi), 0, std::cos(phi)};
  const Vec3 p0{0, 0, 0}, p1{1, 0.3, -0.1};
  ToolPath path;
  path.moves.push_back(cut(p0, p1, a0, a1));
  SweepOptions options;
  options.axisTolerance = 1e-4;
  const std::vector<SweptSegment> segs = sweepToolPath(bull, path, options);
  const double reach = std::hypot(bull.fluteLength, bull.radius);
  EXPECT_EQ(segs.size(), size_t(std::ceil(reach * phi / (2 * options.axisTolerance))));

  // Reference: the true rotating cutter stamped at 20001 poses (tip lerp, axis slerp).
  // Stamps lie on the true swept solid, so the subdivided sweep must stay within the
  // tolerance of them and never be above the densest stamp by more than that either.
  const int kStamps = 20001;
  double worst = 0;
  for (double x : {-1.0, 0.2, 0.5, 0.8, 1.7}) {
    for (double y : {-1.5, 0.0, 0.15, 0.4, 2.0}) {
      double swept = HUGE_VAL;
      for (const SweptSegment& s : segs) {
        const LowestPoint lp = s.lowestPoint(x, y);
        if (lp.hit) swept = std::min(swept, lp.z);
      }
      double stamped = HUGE_VAL;
      for (int k = 0; k < kStamps; ++k) {
        const double t = double(k) / (kStamps - 1);
        const Vec3 tip = p0 + (p1 - p0) * t;
        const Vec3 axis = normalize(a0 * (std::sin((1 - t) * phi) / std::sin(phi)) +
                                    a1 * (std::sin(t * phi) / std::sin(phi)));
        const LowestPoint lp = cutterLowestPoint(bull, axis, x - tip.x, y - tip.y);
        if (lp.hit) stamped = std::min(stamped, lp.z + tip.z);
      }
      ASSERT_EQ(std::isfinite(swept), std::isfinite(stamped)) << x << " " << y;
      if (!std::isfinite(swept)) continue;
      worst = std::max(worst, std::fabs(swept - stamped));
      EXPECT_NEAR(swept, stamped, options.axisTolerance + 1e-6) << x << " " << y;
    }
  }
  std::printf("turning axis: worst |subdivided - stamped| = %.3g mm (tolerance %.0e)\n", worst,
              options.axisTolerance);
}

TEST(ToolPathSweep, ImpossibleSubdivisionIsRefusedByMove) {
  const Cutter ball = Cutter::make(CutterType::Ball, 3);
  ToolPath path;
  path.moves.push_back(cut({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {1, 0, 0}));  // 90 degrees
  SweepOptions tight;
  tight.axisTolerance = 1e-9;
  try {
    sweepToolPath(ball, path, tight);
    FAIL() << "a billion pieces accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("path move 1"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace scallop
