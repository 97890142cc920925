// The culling scene's memory estimate (estimateSceneBytes), made before a scene is
// built, against the memory a built scene really takes: it must never err low (a job
// it accepts must not be killed for memory) and should not err absurdly high.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "raycast/simulation.h"
#include "tests/sanitizer.h"

namespace scallop {
namespace {

long peakKb() {
  std::ifstream in("/proc/self/status");
  std::string line;
  long kb = -1;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) kb = std::stol(line.substr(6));
  return kb;
}

// A 5-axis CAM-like path of `passes` x 400 turning moves of 0.05 mm (the axis at every
// CL point, leaned from the normal of a wavy surface), bull R3 r1.
ToolPath turningPath(int passes) {
  auto pose = [](double x, double y) {
    const Vec3 n = normalize(Vec3{-0.3 * std::cos(x), 0.2 * std::sin(y), 1});
    return Pose{{x, y, 0.3 * std::sin(x) + 0.2 * std::cos(y)}, normalize(n + Vec3{0.09, 0, 0})};
  };
  ToolPath path;
  for (int k = 0; k < passes; ++k)
    for (int i = 0; i < 400; ++i)
      path.moves.push_back(Move{pose(0.05 * i, 0.5 * k), pose(0.05 * (i + 1), 0.5 * k), false});
  return path;
}

TEST(SceneMemory, EstimateIsAtLeastWhatTheSceneTakes) {
#if SCALLOP_UNDER_ASAN
  GTEST_SKIP() << "peak memory is not meaningful under AddressSanitizer";
#endif
  const Cutter cutter = Cutter::make(CutterType::Bull, 3, 1);
  const ToolPath path = turningPath(100);  // 40,000 turning moves
  const Box3 stock({0, 0, -2}, {20, 50, 1});
  size_t moves = 0;
  const double estimate = estimateSceneBytes(cutter, path, stock, 0.01, &moves);
  ASSERT_EQ(moves, 40000u);
  // In a child process, so that the peak resident size measures this build alone.
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const long before = peakKb();
    const std::unique_ptr<SweptScene> scene = buildScene(cutter, path, stock, 0.01);
    const double built = double(peakKb() - before) * 1024;
    std::fprintf(stderr,
                 "scene of %zu turning moves: %.0f bytes built (%.0f a move), %.0f "
                 "estimated (%.2fx)\n",
                 moves, built, built / double(moves), estimate, estimate / built);
    _exit(built <= estimate && estimate <= 3 * built ? 0 : 1);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "estimate " << estimate;
}

long residentKb() {
  std::ifstream in("/proc/self/status");
  std::string line;
  long kb = -1;
  while (std::getline(in, line))
    if (line.rfind("VmRSS:", 0) == 0) kb = std::stol(line.substr(6));
  return kb;
}

// B9's kind of program, 10^5 moves: a ball R1 finishing 3-axis passes 0.1 mm apart
// along X, a move every 0.05 mm with the tip on a wavy surface (no two consecutive moves
// collinear, so none merge), on a 0.02 mm grid: 12.5 cells a move, one culling tile each.
ToolPath finishingPath(int passes, int movesPerPass) {
  auto tip = [](double x, double y) {
    return Vec3{x, y, 0.3 * std::sin(x / 3) * std::sin(y / 4 + 0.5) - 0.5};
  };
  ToolPath path;
  for (int k = 0; k < passes; ++k)
    for (int i = 0; i < movesPerPass; ++i) {
      const double y = 0.1 * k;
      path.moves.push_back(
          Move{Pose{tip(0.05 * i, y), {0, 0, 1}}, Pose{tip(0.05 * (i + 1), y), {0, 0, 1}}, false});
    }
  return path;
}

// The scene of 10^5 short moves holds what docs/performance.md states a move (the
// estimate, estimateSceneBytes) within 20 %: by its own accounting (SceneStats) and by
// the resident memory it adds once built.
TEST(SceneMemory, ShortMovesTakeTheStatedBytesAMove) {
#if SCALLOP_UNDER_ASAN
  GTEST_SKIP() << "resident memory is not meaningful under AddressSanitizer";
#endif
  const Cutter cutter = Cutter::make(CutterType::Ball, 1);
  const ToolPath path = finishingPath(100, 1000);
  const Box3 stock({0, 0, -5}, {50, 10, 0});
  const double spacing = 0.02;
  ASSERT_LT(programCellsPerMove(cutter, path, stock, spacing), kCellsPerMoveForTiles);
  size_t moves = 0;
  const double stated = estimateSceneBytes(cutter, path, stock, spacing, &moves);
  ASSERT_EQ(moves, 100000u);
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const long before = residentKb();
    const std::unique_ptr<SweptScene> scene = buildScene(cutter, path, stock, spacing);
    const double resident = double(residentKb() - before) * 1024;
    const double counted = double(scene->stats().bytes());
    std::fprintf(stderr,
                 "scene of %zu short moves (%zu segments, %zu tiles): %.0f bytes a move "
                 "stated, %.0f counted by the scene, %.0f resident\n",
                 moves, scene->stats().segments, scene->stats().tiles, stated / double(moves),
                 counted / double(moves), resident / double(moves));
    const auto within = [&](double measured) {
      return std::fabs(measured - stated) <= 0.2 * stated;
    };
    _exit(scene->stats().segments == moves && within(counted) && within(resident) ? 0 : 1);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "stated " << stated;
}

// Teeth turning counter-clockwise: each constant-axis move also holds its mirror image's
// segment (tool_path_sweep.cpp), which the estimate counts: without it, it erred low.
TEST(SceneMemory, CounterClockwiseTeethAreCountedWithTheirMirrors) {
  const Cutter cutter = Cutter::make(CutterType::Ball, 1, 1);
  const ToolPath path = finishingPath(10, 200);
  const Box3 stock({0, 0, -2}, {10, 1, 0});
  SimulationOptions options;
  options.cutting.kind = CuttingModelKind::Teeth;
  options.cutting.feedPerTooth = 0.05;
  options.cutting.counterClockwise = true;
  const double estimate = estimateSceneBytes(cutter, path, stock, 0.02, nullptr, options.cutting);
  const std::unique_ptr<SweptScene> scene = buildScene(cutter, path, stock, 0.02, options);
  EXPECT_GE(estimate, double(scene->stats().bytes()));
  CuttingModel clockwise = options.cutting;
  clockwise.counterClockwise = false;
  const double perMirror = double(sizeof(SweptSegment) + 32);
  EXPECT_DOUBLE_EQ(estimate - estimateSceneBytes(cutter, path, stock, 0.02, nullptr, clockwise),
                   2000 * perMirror);
}

}  // namespace
}  // namespace scallop
