// The benchmark run (tools/run/bench_run.h) called directly: its document, the stages
// it reports progress for, a progress callback that throws (the CLI's Ctrl-C) stopping
// it, and bad settings.
#include "tools/run/bench_run.h"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "raycast/simulation.h"
#include "tests/support/bench_heights.h"
#include "tools/run/bench_cases.h"

namespace scallop {
namespace {

BenchSettings smallB1() {
  BenchSettings s;
  s.quick = true;
  s.cases = {"B1"};
  s.area = 1;
  s.stamp = false;
  s.threads = 2;
  return s;
}

TEST(BenchRun, OneCaseGivesTheHeightsOfSimulateAndNamesItsStages) {
  BenchSettings s = smallB1();
  std::vector<std::string> stages;
  int64_t lastDone = 0, lastTotal = -1;
  s.openStage = [&](const std::string& label) -> CellProgress {
    stages.push_back(label);
    return [&](int64_t done, int64_t total) { lastDone = done, lastTotal = total; };
  };
  const BenchResult r = runBench(s);
  ASSERT_EQ(r.report["cases"].size(), 1u);
  const nlohmann::json& c = r.report["cases"][0];
  EXPECT_EQ(c["name"], "B1");
  EXPECT_EQ(c["cells"], 100 * 100);
  EXPECT_EQ(c["threads"], 2);
  EXPECT_TRUE(c["speedup_2v1"].is_number());
  EXPECT_EQ(r.report["threads"], 2);
  EXPECT_TRUE(r.report["stamp"].empty());
  EXPECT_EQ(r.report["area_mm"], 1.0);
  EXPECT_TRUE(r.report.contains("scallop_version"));  // newReport()'s document

  // Two runs each at 1 and at 2 threads, alternating, every one with its bar.
  EXPECT_EQ(stages, (std::vector<std::string>{"B1 (1 thread)", "B1 (2 threads)", "B1 (1 thread)",
                                              "B1 (2 threads)"}));
  EXPECT_EQ(lastDone, lastTotal);
  EXPECT_EQ(lastTotal, 100 * 100);

  EXPECT_EQ(c["heights_hash"].get<std::string>(), test::simulatedQuickHash("B1", 1));
}

// B11 reads its generated program alone (no simulation case): every G1 of it is a move
// (the passes' points), and the rates are the counts over the seconds.
TEST(BenchRun, TheReadingCaseCountsTheProgramsMoves) {
  BenchSettings s;
  s.quick = true;
  s.cases = {"B11"};
  s.area = 4;
  s.stamp = false;
  const BenchResult r = runBench(s);
  EXPECT_TRUE(r.report["cases"].empty());
  ASSERT_TRUE(r.report.contains("reading"));
  const nlohmann::json& b = r.report["reading"];
  Box3 stock;
  stock.extend({0, 0, -5});
  stock.extend({4, 2, 0});
  const std::string text = finishingGcode(Cutter::make(CutterType::Ball, 1), stock, 0.1, 0.05);
  size_t g1 = 0;
  for (size_t at = text.find("G1 "); at != std::string::npos; at = text.find("G1 ", at + 1)) ++g1;
  EXPECT_GE(b["moves"].get<size_t>(), g1);
  EXPECT_LE(b["moves"].get<size_t>(), g1 + 3 * 21 + 1);  // and the rapids: 3 a pass, 21 passes
  EXPECT_EQ(b["bytes"].get<double>(), double(text.size()));
  EXPECT_DOUBLE_EQ(b["moves_per_s"].get<double>(),
                   b["moves"].get<double>() / b["seconds"].get<double>());
}

TEST(BenchRun, TheStampingBaselineHasItsOwnStage) {
  BenchSettings s = smallB1();
  s.stamp = true;
  s.stampWindow = 0.2;
  s.threads = 1;
  int stampStages = 0;
  s.openStage = [&](const std::string& label) -> CellProgress {
    if (label == "B1 stamping") ++stampStages;
    return {};
  };
  const BenchResult r = runBench(s);
  EXPECT_GE(stampStages, 2);  // the step search, then the chosen step once more
  EXPECT_LE(r.report["stamp"]["B1"]["max_error_mm"].get<double>(), 1e-4);
  EXPECT_GT(r.report["stamp_ratio"]["B1"].get<double>(), 0);
}

TEST(BenchRun, AProgressThatThrowsStopsTheRun) {
  BenchSettings s = smallB1();
  struct Stop : std::runtime_error {
    Stop() : std::runtime_error("stop") {}
  };
  s.openStage = [](const std::string&) -> CellProgress {
    return [](int64_t, int64_t) { throw Stop(); };
  };
  EXPECT_THROW(runBench(s), Stop);
}

TEST(BenchRun, BadSettingsAreInputErrors) {
  BenchSettings s = smallB1();
  s.cases = {"B10"};
  EXPECT_THROW(runBench(s), InputError);
  s = smallB1();
  s.area = -1;
  EXPECT_THROW(runBench(s), InputError);
}

}  // namespace
}  // namespace scallop
