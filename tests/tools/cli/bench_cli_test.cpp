// `scallop bench`: runs, prints the documented JSON keys, and its heights are those of
// a direct simulate() call, bit for bit.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>

#include "raycast/simulation.h"
#include "tests/support/bench_heights.h"
#include "tests/support/cli_harness.h"
#include "tools/run/bench_cases.h"

namespace scallop {
namespace {

using scallop::test::CliRun;
class BenchCli : public scallop::test::CliFixture {};

TEST_F(BenchCli, QuickCaseB1PrintsTheDocumentedJson) {
  const CliRun r = run("bench --quick --case B1 --area 2 --stamp-window 0.5 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json doc = nlohmann::json::parse(r.out);  // stdout is JSON and only JSON
  ASSERT_EQ(doc["cases"].size(), 1u);
  const nlohmann::json& c = doc["cases"][0];
  for (const char* key : {"name", "cells", "moves", "evals_per_cell", "seconds", "mcells_per_s",
                          "peak_rss_mb", "speedup_2v1"})
    EXPECT_TRUE(c.contains(key)) << key;
  EXPECT_EQ(c["name"], "B1");
  EXPECT_EQ(c["cells"], 200 * 200);
  EXPECT_GT(c["mcells_per_s"].get<double>(), 0);
  ASSERT_TRUE(doc["stamp_ratio"].contains("B1"));
  EXPECT_GT(doc["stamp_ratio"]["B1"].get<double>(), 0);
  EXPECT_LE(doc["stamp"]["B1"]["max_error_mm"].get<double>(), 1e-4);
  EXPECT_GE(doc["stamp"]["B1"]["min_difference_mm"].get<double>(), -1e-9);

  // The same case through simulate(), as `scallop simulate` runs it: same heights.
  EXPECT_EQ(c["heights_hash"].get<std::string>(), test::simulatedQuickHash("B1", 2));
}

TEST_F(BenchCli, TableOnStdoutAndUsageErrors) {
  const CliRun table = run("bench --quick --case B3 --area 1 --no-stamp --threads 1");
  ASSERT_EQ(table.status, 0);
  EXPECT_NE(table.out.find("Mcells/s"), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("B3"), std::string::npos) << table.out;
  EXPECT_EQ(run("bench --case B10").status, 2);
  EXPECT_EQ(run("bench --area -1").status, 2);
}

// B5 is B1 with teeth, timed beside the envelope on its grid; its heights are those of
// simulate() with its cutting model, and --quick keeps it to a 4 mm square.
TEST_F(BenchCli, B5IsB1WithTeethBesideTheEnvelope) {
  const CliRun r = run("bench --quick --case B5 --area 1 --no-stamp --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json doc = nlohmann::json::parse(r.out);
  ASSERT_EQ(doc["cases"].size(), 1u);
  const nlohmann::json& c = doc["cases"][0];
  EXPECT_EQ(c["name"], "B5");
  EXPECT_EQ(c["cutting"], "teeth");
  EXPECT_GT(c["envelope_seconds"].get<double>(), 0);
  EXPECT_EQ(c["teeth_over_envelope"].get<double>(),
            c["seconds"].get<double>() / c["envelope_seconds"].get<double>());
  BenchCaseOptions options;
  options.quick = true;
  options.area = 1;
  const BenchCase b = makeBenchCase("B5", options);
  ASSERT_TRUE(b.cutting.teeth());
  EXPECT_EQ(b.cutting.feedPerTooth, 0.1);
  EXPECT_EQ(b.cutter.teeth.flutes, 2);
  SimulationOptions teeth;
  teeth.cutting = b.cutting;
  EXPECT_EQ(
      c["heights_hash"].get<std::string>(),
      fmt::format("{:016x}", heightsHash(simulate(b.cutter, b.path, b.stock, b.grid, teeth).map)));
  // B1's raster, stock and grid; quick: a 4 mm square, not B1's 20 mm.
  const BenchCase b1 = makeBenchCase("B1", options);
  EXPECT_EQ(b.grid.cells(), b1.grid.cells());
  EXPECT_EQ(b.path.moves.size(), b1.path.moves.size());
  options.area = 0;
  EXPECT_EQ(makeBenchCase("B5", options).stock.max.x, 4);
  EXPECT_EQ(makeBenchCase("B1", options).stock.max.x, 20);
  options.quick = false;
  EXPECT_EQ(makeBenchCase("B5", options).grid.cells(), makeBenchCase("B1", options).grid.cells());
}

// B3 is the freeform path as CAM writes it: CL text read back through the CL-text
// reader, with the axis of every CL point, so the axis turns inside every move; B3c
// has the same tips with one axis per move. Both run along +X at a constant y with tips
// on the surface (B3 to the text's 6 decimals), and consecutive moves share a pose.
TEST(BenchCases, FreeformPathsFollowTheSurfaceAlongX) {
  BenchCaseOptions options;
  options.area = 1;
  for (const char* name : {"B3", "B3c"}) {
    const BenchCase b = makeBenchCase(name, options);
    const bool turning = std::string(name) == "B3";
    ASSERT_GT(b.path.cuttingMoves(), 0u);
    const Move* previous = nullptr;
    size_t turningMoves = 0;
    for (const Move& mv : b.path.moves) {
      if (mv.rapid) {
        previous = nullptr;
        continue;
      }
      EXPECT_NEAR(length(mv.from.axis), 1.0, 1e-12);
      turningMoves += mv.from.axis != mv.to.axis;
      EXPECT_EQ(mv.from.tip.y, mv.to.tip.y);
      EXPECT_NEAR(mv.to.tip.x - mv.from.tip.x, 0.05, 1e-3);
      for (const Pose& p : {mv.from, mv.to})
        EXPECT_NEAR(p.tip.z, freeformHeight(p.tip.x, p.tip.y), turning ? 1e-6 : 0) << name;
      if (previous) {
        EXPECT_EQ(previous->to.tip, mv.from.tip);
        if (turning) {
          EXPECT_EQ(previous->to.axis, mv.from.axis);
        }
      }
      previous = &mv;
    }
    EXPECT_EQ(turningMoves, turning ? b.path.cuttingMoves() : 0u) << name;
    EXPECT_EQ(b.grid.spacing, 0.002);
  }
  EXPECT_EQ(makeBenchCase("B2", options).path.cuttingMoves(), 2u * 180u);
}

// B9 is a finishing program of a million moves read back through the G-code reader: ball R1,
// passes along X 0.1 mm apart over an A x A/2 stock, a plunge and then a G1 every 0.05
// mm with the tip on the surface (to the text's 4 decimals), on a 20 um grid; only run
// when asked for.
TEST(BenchCases, FinishingProgramIsReadFromGcode) {
  BenchCaseOptions options;
  options.area = 1;
  const BenchCase b = makeBenchCase("B9", options);
  EXPECT_EQ(b.cutter.type, CutterType::Ball);
  EXPECT_EQ(b.cutter.radius, 1);
  EXPECT_EQ(b.stock.max.x, 1);
  EXPECT_EQ(b.stock.max.y, 0.5);
  EXPECT_EQ(b.grid.spacing, 0.02);
  // 6 passes (y = 0 .. 0.5) of x from -2 to 3: 100 moves and the plunge each.
  EXPECT_EQ(b.path.cuttingMoves(), 6u * 101u);
  size_t alongX = 0;
  for (const Move& mv : b.path.moves) {
    if (mv.rapid) continue;
    EXPECT_NEAR(mv.to.tip.z, finishingHeight(mv.to.tip.x, mv.to.tip.y), 5.1e-5);
    alongX += mv.from.tip.x != mv.to.tip.x;
  }
  EXPECT_EQ(alongX, 6u * 100u);
  const std::vector<std::string>& all = defaultBenchCaseNames();
  EXPECT_EQ(std::find(all.begin(), all.end(), "B9"), all.end());
}

}  // namespace
}  // namespace scallop
