// The simulation plan (tools/run/simulation_plan.h): the grid, the bands and the memory
// verdict of a run, made once before its computation.
#include "tools/run/simulation_plan.h"

#include <gtest/gtest.h>

#include <string>

#include "base/input_error.h"
#include "tests/support/short_moves_job.h"
#include "tools/io/job.h"
#include "tools/run/simulation_run.h"

namespace scallop {
namespace {

constexpr double kPlenty = 64.0 * (1ull << 30);  // bytes of memory available

// A 20 x 20 mm stock on a 0.01 mm grid (2000 x 2000 cells) cut by three short moves.
Job planJob() {
  return test::shortMovesJob(3, 0.01, "plan.json");
}

TEST(SimulationPlan, AJobThatFitsRunsInMemoryOnItsGrid) {
  const Job job = planJob();
  const SimulationPlan plan = planSimulation(job, RunSettings(), kPlenty);
  EXPECT_EQ(plan.grid.nx, 2000);
  EXPECT_EQ(plan.grid.ny, 2000);
  EXPECT_DOUBLE_EQ(plan.grid.spacing, 0.01);
  EXPECT_TRUE(plan.exact);
  EXPECT_FALSE(plan.inBands);
  EXPECT_DOUBLE_EQ(plan.memory.mapBytes, 2000.0 * 2000.0 * 12.0);
  EXPECT_GT(plan.memory.sceneBytes, 0);
  EXPECT_TRUE(plan.memory.mapFits());
  EXPECT_TRUE(plan.memory.sceneFits());
  EXPECT_EQ(plan.cellsToCompute(), 2000 * 2000);
  EXPECT_NE(plan.banner.find("plan.json: ball cutter R=1 mm, 3 cutting moves, 2000 x 2000 "
                             "cells of 0.01 mm"),
            std::string::npos)
      << plan.banner;
  EXPECT_NO_THROW(requireRunFitsMemory(job, plan.grid, plan.memory, true));
}

TEST(SimulationPlan, AskedBandsAreLaidOutAndNarrowed) {
  RunSettings settings;
  settings.tileRows = 64;
  settings.bands = "1:3";
  const SimulationPlan plan = planSimulation(planJob(), settings, kPlenty);
  EXPECT_TRUE(plan.inBands);
  EXPECT_TRUE(plan.partial);
  EXPECT_EQ(plan.layout.bandRows, 64);
  EXPECT_EQ(plan.layout.bands, 32);  // 2000 rows: 31 of 64 and one of 16
  EXPECT_EQ(plan.firstBand, 1);
  EXPECT_EQ(plan.endBand, 3);
  EXPECT_EQ(plan.cellsToCompute(), 2 * 64 * 2000);
  EXPECT_NE(plan.banner.find("bands 1..2 of 32 (64 rows each)"), std::string::npos) << plan.banner;

  settings.bands = "3:1";
  try {
    planSimulation(planJob(), settings, kPlenty);
    FAIL() << "3:1 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "--bands");
  }
}

TEST(SimulationPlan, AMapThatDoesNotFitRunsInBandsOrIsRefusedNamingTheGrid) {
  const Job job = planJob();
  const double sceneBytes = planSimulation(job, RunSettings(), kPlenty).memory.sceneBytes;
  // Room for the scene, not for the 48 MB map.
  const double available = 10 * sceneBytes;
  ASSERT_GT(2000.0 * 2000.0 * 12.0, 0.8 * available);

  const SimulationPlan exact = planSimulation(job, RunSettings(), available);
  EXPECT_TRUE(exact.memory.sceneFits());
  EXPECT_FALSE(exact.memory.mapFits());
  EXPECT_TRUE(exact.inBands);  // not asked for: the map does not fit
  EXPECT_FALSE(exact.bandsAsked);
  EXPECT_EQ(exact.firstBand, 0);
  EXPECT_EQ(exact.endBand, exact.layout.bands);
  EXPECT_NO_THROW(requireRunFitsMemory(job, exact.grid, exact.memory, false));

  // Held whole (the Python module, the stamp baseline), it is refused by field.
  try {
    requireRunFitsMemory(job, exact.grid, exact.memory, true);
    FAIL() << "a map larger than memory accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "plan.json: grid.spacing");
    EXPECT_NE(e.reason().find("2000 x 2000 grid needs"), std::string::npos) << e.reason();
  }
}

TEST(SimulationPlan, ASceneThatDoesNotFitIsRefusedNamingThePath) {
  const Job job = planJob();
  const SimulationPlan plan = planSimulation(job, RunSettings(), 1000.0);
  EXPECT_FALSE(plan.memory.sceneFits());
  try {
    requireRunFitsMemory(job, plan.grid, plan.memory, false);
    FAIL() << "a scene larger than memory accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "plan.json: path");
    EXPECT_NE(e.reason().find("3 cutting moves"), std::string::npos) << e.reason();
  }

  // The stamp baseline builds no scene: only its map counts.
  RunSettings stamp;
  stamp.method = "stamp";
  const SimulationPlan stamped = planSimulation(job, stamp, 1000.0);
  EXPECT_EQ(stamped.memory.sceneBytes, 0);
  EXPECT_FALSE(stamped.inBands);
}

}  // namespace
}  // namespace scallop
