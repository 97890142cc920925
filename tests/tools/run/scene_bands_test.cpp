// A path whose whole culling scene does not fit in memory runs in bands, each band with
// the scene of the moves that reach it (SimulationPlan::sceneBands, tiled_simulation.h):
// the same heights, bit for bit, as one scene for every band.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "base/input_error.h"
#include "tests/support/cli_harness.h"
#include "tools/io/height_images.h"
#include "tools/io/job.h"
#include "tools/run/job_loader.h"
#include "tools/run/simulation_plan.h"
#include "tools/run/simulation_run.h"
#include "tools/run/tiled_simulation.h"

namespace fs = std::filesystem;

namespace scallop {
namespace {

constexpr double kPlenty = 64.0 * (1ull << 30);  // bytes of memory available

// Passes along X 0.83 mm apart over a stock 12 mm long in y: a band of 64 rows (1.28 mm)
// meets the few passes within the cutter's reach of it, a fifth of the path or less.
Job passesJob(const std::string& cutting) {
  return loadJob(R"({"tool": {"type": "bull", "radius": 0.5, "corner_radius": 0.2,
    "flutes": 2}, "stock": {"min": [0, 0, -1], "max": [2, 12, 0]}, "grid": {"spacing": 0.02},
    "path": {"raster": {"direction": "x", "step_over": 0.83, "depth": 0.1, "lead_deg": 3,
    "segment_length": 0.3}}, "cutting": )" +
                     cutting + "}",
                 "passes.json");
}

class SceneBands : public test::CliFixture {
 protected:
  // Runs `job` in bands of 64 rows with `available` bytes of memory, into `out`.
  // A path file streamed by the bands (SimulationPlan::streamPath) is re-read in parts of
  // `partMoves` moves (0: the plan's).
  SimulationPlan runInBands(const Job& job, double available, const std::string& out,
                            size_t partMoves = 0) {
    RunSettings settings;
    settings.tileRows = 64;
    settings.quiet = true;
    settings.outDir = path(out);
    fs::create_directories(settings.outDir);
    SimulationPlan plan = planSimulation(job, settings, available);
    if (partMoves > 0) plan.streamPartMoves = partMoves;
    runTiledSimulation(job, plan, settings);
    return plan;
  }
  void expectSameHeights(const Job& job, size_t partMoves = 0) {
    const SimulationPlan whole = runInBands(job, kPlenty, "whole");
    ASSERT_FALSE(whole.sceneBands);
    ASSERT_FALSE(whole.streamPath);
    ASSERT_GT(whole.memory.sceneBytes, 0);
    // Memory for 90 % of the whole scene: it no longer fits, its bands' scenes do.
    const double available = whole.memory.sceneBytes / 0.8 * 0.9;
    const SimulationPlan banded = runInBands(job, available, "banded", partMoves);
    ASSERT_TRUE(banded.sceneBands);
    EXPECT_EQ(banded.streamPath, !job.isRaster);
    EXPECT_TRUE(banded.inBands);
    EXPECT_FALSE(banded.memory.wholeSceneFits());
    EXPECT_TRUE(banded.memory.sceneFits());
    EXPECT_LT(banded.memory.largestBandBytes, 0.5 * whole.memory.sceneBytes);
    EXPECT_EQ(banded.layout.bands, whole.layout.bands);
    EXPECT_GE(banded.layout.bands, 9);

    const ZMap a = readHeightsExr(path("whole") + "/heights.exr");
    const ZMap b = readHeightsExr(path("banded") + "/heights.exr");
    EXPECT_TRUE(a.heights() == b.heights());
    EXPECT_EQ(test::slurp(path("whole") + "/heights.gsf"),
              test::slurp(path("banded") + "/heights.gsf"));
    const nlohmann::json ra = nlohmann::json::parse(test::slurp(path("whole") + "/report.json"));
    const nlohmann::json rb = nlohmann::json::parse(test::slurp(path("banded") + "/report.json"));
    for (const char* key : {"min_height", "max_height"})
      EXPECT_EQ(ra["measurements"][key], rb["measurements"][key]) << key;
    if (job.isRaster) {
      EXPECT_EQ(ra["measurements"]["max_scallop_height"], rb["measurements"]["max_scallop_height"]);
    }
    // Each band held part of the path: the bands' scenes summed hold each segment once
    // or, near a band's edge, twice; never all of them in every band.
    const int64_t segments = ra["sweep"]["swept_segments"].get<int64_t>();
    const int64_t summed = rb["sweep"]["swept_segments"].get<int64_t>();
    EXPECT_GE(summed, segments);
    EXPECT_LT(summed, 4 * segments);
  }
};

TEST_F(SceneBands, EnvelopeHeightsAreTheOneScenesBitForBit) {
  expectSameHeights(passesJob(R"({"model": "envelope"})"));
}

// The teeth model: each kept move keeps its own spindle phase (sweepToolPath pairs them).
TEST_F(SceneBands, TeethHeightsAreTheOneScenesBitForBit) {
  expectSameHeights(passesJob(R"({"model": "teeth", "feed_per_tooth": 0.08})"));
}

// A G-code program streamed from its file a band at a time, in parts of 7 moves (runs
// merge across the parts' edges): modal G1 and G91, arcs (their indices count on
// through the parts), two tools changed pass by pass, each pass re-read from the same
// reader state. The same heights as the one scene of the moves read whole.
TEST_F(SceneBands, StreamedGcodeHeightsAreTheOneScenesBitForBit) {
  std::string program = "%\nG21 G90 G17\n";
  for (int pass = 0; pass < 14; ++pass) {
    const double y = 0.3 + 0.83 * pass;
    program += fmt::format("T{} M6\nG0 X-0.8 Y{:.3f} Z2\nG1 Z-0.1 F300\nG91\n", 1 + pass % 2, y);
    for (int k = 0; k < 12; ++k)  // modal G1, incremental: level pairs merge, then a ramp
      program += k % 3 == 2 ? "X0.3 Z0.04\n" : k % 3 == 0 ? "X0.3 Z-0.04\n" : "X0.3\n";
    program += "G90\nG3 X2.8 Y" + fmt::format("{:.3f}", y + 0.5) + " I0 J0.25\nG0 Z2\n";
  }
  program += "M30\n%\n";
  write("finish.nc", program);
  const fs::path jobFile = write("finish.json", R"({
      "tools": {"1": {"type": "ball", "radius": 0.5},
                "2": {"type": "bull", "radius": 0.4, "corner_radius": 0.1}},
      "stock": {"min": [0, 0, -1], "max": [2, 12, 0]}, "grid": {"spacing": 0.02},
      "path": {"file": "finish.nc"}})");
  const Job job = loadJobFile(jobFile.string());
  ASSERT_EQ(job.path.cutters.size(), 2u);
  ASSERT_FALSE(job.path.arcs.empty());
  expectSameHeights(job, 7);
}

// A CL file (APT, tilted tool axes that turn in a move of each pass, two CUTTER/s of its
// own, RAPID between passes) streamed the same way.
TEST_F(SceneBands, StreamedClFileHeightsAreTheOneScenesBitForBit) {
  std::string cl = "UNITS/MM\nMULTAX\n";
  for (int pass = 0; pass < 14; ++pass) {
    const double y = 0.3 + 0.83 * pass;
    cl += pass % 2 ? "CUTTER/0.8,0.1\n" : "CUTTER/1.0,0.5\n";
    cl += fmt::format("RAPID\nGOTO/-0.8,{:.3f},2,0,0,1\n", y);
    for (int k = 0; k <= 12; ++k) {
      // Tilted, the axis turning in the pass's last move only (turning moves are slow).
      const double x = -0.8 + 0.3 * k, lean = k < 12 ? 0.08 * std::sin(1.3 + pass) : 0;
      cl += fmt::format("GOTO/{:.4f},{:.3f},{:.4f},{:.6f},0,{:.6f}\n", x, y,
                        -0.1 + 0.03 * std::cos(0.9 * k), lean, std::sqrt(1 - lean * lean));
    }
  }
  write("finish.cl", cl + "FINI\n");
  const fs::path jobFile = write("finish-cl.json", R"({
      "stock": {"min": [0, 0, -1], "max": [2, 12, 0]}, "grid": {"spacing": 0.02},
      "path": {"file": "finish.cl"}})");
  const Job job = loadJobFile(jobFile.string());
  ASSERT_EQ(job.path.cutters.size(), 2u);
  expectSameHeights(job, 7);
}

// A file that changes between the run's first read and a band's re-read is refused
// (the moves' count differs), never simulated from two different programs.
TEST_F(SceneBands, AFileChangedBeforeItsBandsReadItIsRefused) {
  std::string program = "G21 G90\nG0 X-0.8 Y0.3 Z2\nG1 Z-0.1\n";
  for (int pass = 0; pass < 14; ++pass)
    program += fmt::format("G1 Y{:.3f}\nX{}\n", 0.3 + 0.83 * pass, pass % 2 ? -0.8 : 2.8);
  write("change.nc", program);
  const fs::path jobFile = write("change.json", R"({"tool": {"type": "ball", "radius": 0.5},
      "stock": {"min": [0, 0, -1], "max": [2, 12, 0]}, "grid": {"spacing": 0.02},
      "path": {"file": "change.nc"}})");
  const Job job = loadJobFile(jobFile.string());
  RunSettings settings;
  settings.tileRows = 64;
  settings.quiet = true;
  settings.outDir = path("changed");
  fs::create_directories(settings.outDir);
  const double whole = planSimulation(job, settings, kPlenty).memory.sceneBytes;
  const SimulationPlan plan = planSimulation(job, settings, whole / 0.8 * 0.9);
  ASSERT_TRUE(plan.streamPath);
  write("change.nc", program + "G1 X1\n");
  try {
    runTiledSimulation(job, plan, settings);
    FAIL() << "a changed file simulated";
  } catch (const InputError& e) {
    EXPECT_NE(e.reason().find("changed while it was being simulated"), std::string::npos)
        << e.reason();
  }
  EXPECT_FALSE(fs::exists(path("changed") + "/heights.exr"));
}

// A path whose moves all lie within a band's reach gains nothing from bands: still
// refused, naming the largest band's bytes.
TEST(SceneBandsPlan, APathThatNoBandSplitsIsRefusedNamingTheLargestBand) {
  Job job = passesJob(R"({"model": "envelope"})");
  Move m;
  m.from = {{1, 6, -0.1}, {0, 0, 1}};
  m.to = {{1.1, 6, -0.1}, {0, 0, 1}};
  job.path.moves.assign(1000, m);
  const double sceneBytes = planSimulation(job, RunSettings(), kPlenty).memory.sceneBytes;
  const SimulationPlan plan = planSimulation(job, RunSettings(), sceneBytes);
  EXPECT_TRUE(plan.sceneBands);
  EXPECT_FALSE(plan.memory.sceneFits());
  try {
    requireRunFitsMemory(job, plan.grid, plan.memory, false);
    FAIL() << "a scene larger than memory accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "passes.json: path");
    EXPECT_NE(e.reason().find("the largest band still needs"), std::string::npos) << e.reason();
  }
}

}  // namespace
}  // namespace scallop
