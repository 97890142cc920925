// A path whose whole culling scene does not fit in memory runs in bands, each band with
// the scene of the moves that reach it (SimulationPlan::sceneBands, tiled_simulation.h):
// the same heights, bit for bit, as one scene for every band.
#include <gtest/gtest.h>

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
  SimulationPlan runInBands(const Job& job, double available, const std::string& out) {
    RunSettings settings;
    settings.tileRows = 64;
    settings.quiet = true;
    settings.outDir = path(out);
    fs::create_directories(settings.outDir);
    const SimulationPlan plan = planSimulation(job, settings, available);
    runTiledSimulation(job, plan, settings);
    return plan;
  }
  void expectSameHeights(const Job& job) {
    const SimulationPlan whole = runInBands(job, kPlenty, "whole");
    ASSERT_FALSE(whole.sceneBands);
    ASSERT_GT(whole.memory.sceneBytes, 0);
    // Memory for 90 % of the whole scene: it no longer fits, its bands' scenes do.
    const double available = whole.memory.sceneBytes / 0.8 * 0.9;
    const SimulationPlan banded = runInBands(job, available, "banded");
    ASSERT_TRUE(banded.sceneBands);
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
    for (const char* key : {"min_height", "max_height", "max_scallop_height"})
      EXPECT_EQ(ra["measurements"][key], rb["measurements"][key]) << key;
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
