// The scallop command line, run as a user would: exit statuses, messages that name
// the file or field, and no output left behind by a failure (CONVENTIONS.md).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "base/version.h"
#include "tests/support/cli_harness.h"
#include "tools/io/height_images.h"

namespace fs = std::filesystem;

namespace {

using scallop::test::CliRun;
using scallop::test::slurp;

class Cli : public scallop::test::CliFixture {
 protected:
  // A small valid job; `edit` patches it before writing.
  fs::path job(const std::function<void(nlohmann::json&)>& edit = {}) {
    nlohmann::json j = nlohmann::json::parse(R"({
      "tool":  {"type": "bull", "radius": 3.0, "corner_radius": 1.0},
      "stock": {"min": [0, 0, -2], "max": [2, 3, 0]},
      "grid":  {"spacing": 0.05},
      "path":  {"raster": {"direction": "x", "step_over": 1.5, "depth": 0.3, "lead_deg": 5}}
    })");
    if (edit) edit(j);
    return write("job.json", j.dump(2));
  }

  // Runs a failing job and checks status, that the message names `needle`, and that
  // the output folder got no file at all.
  void expectRejected(const fs::path& jobFile, const std::string& needle, int status = 1) {
    const fs::path out = dir_ / "out";
    fs::remove_all(out);
    const CliRun r = run("simulate " + jobFile.string() + " -o " + out.string());
    EXPECT_EQ(r.status, status) << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos)
        << "message does not name " << needle << ": " << r.err;
    const bool empty = !fs::exists(out) || fs::is_empty(out);
    EXPECT_TRUE(empty) << "a failed run left files in " << out;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
};

TEST_F(Cli, HelpTeachesEveryOptionWithUnits) {
  const CliRun top = run("--help");
  EXPECT_EQ(top.status, 0);
  EXPECT_NE(top.out.find("simulate"), std::string::npos);
  const CliRun sim = run("simulate --help");
  EXPECT_EQ(sim.status, 0);
  for (const char* word : {"--output", "--threads", "--json", "mm", "heights.exr", "report.json"})
    EXPECT_NE(sim.out.find(word), std::string::npos) << word;
}

// The top-level --help lists each command on one line (its summary sentence) and fits a
// terminal; the job keys stay in `simulate --help`.
TEST_F(Cli, TopLevelHelpIsOneLineACommand) {
  const CliRun top = run("--help");
  ASSERT_EQ(top.status, 0);
  EXPECT_LE(std::count(top.out.begin(), top.out.end(), '\n'), 40) << top.out;
  EXPECT_EQ(top.out.find("tooth_offsets"), std::string::npos) << top.out;
  EXPECT_NE(run("simulate --help").out.find("tooth_offsets"), std::string::npos);
  for (const char* command : {"simulate", "surface", "gouge", "interval", "validate", "bench",
                              "merge", "stats", "export", "collect", "cutter"}) {
    const size_t at = top.out.find(std::string("\n  ") + command + " ");
    ASSERT_NE(at, std::string::npos) << command << " is not listed: " << top.out;
    const size_t end = top.out.find('\n', at + 1);
    // One line: the summary ends with its sentence's full stop.
    EXPECT_EQ(top.out[end - 1], '.') << top.out.substr(at, end - at);
  }
}

TEST_F(Cli, VersionPrintsTheProjectVersion) {
  const CliRun r = run("--version");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.out, std::string("scallop ") + scallop::kScallopVersion + "\n");
}

TEST_F(Cli, UnknownMethodIsAUsageErrorAndStampCannotBeTiled) {
  EXPECT_EQ(run("simulate " + job().string() + " -o " + path("m") + " --method sampled").status, 2);
  const CliRun r =
      run("simulate " + job().string() + " -o " + path("m") + " --method stamp --tiled");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("--method"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "m" / "heights.exr"));
}

TEST_F(Cli, UsageErrorsExitTwo) {
  EXPECT_EQ(run("").status, 2);
  EXPECT_EQ(run("frobnicate").status, 2);
  EXPECT_EQ(run("simulate --no-such-option").status, 2);
  EXPECT_EQ(run("simulate --threads -3").status, 2);
}

TEST_F(Cli, MalformedJsonNamesFileAndLine) {
  const fs::path p =
      write("broken.json", "{\n  \"tool\": {\"type\": \"ball\",\n  \"radius\": }\n}\n");
  expectRejected(p, "broken.json:3:");
}

TEST_F(Cli, MissingFileIsBadInput) {
  expectRejected(dir_ / "nope.json", "nope.json");
}

TEST_F(Cli, MissingAndUnknownKeysAreNamed) {
  expectRejected(job([](nlohmann::json& j) { j.erase("grid"); }), "grid");
  expectRejected(job([](nlohmann::json& j) { j["tool"].erase("radius"); }), "tool.radius");
  expectRejected(job([](nlohmann::json& j) { j["tool"]["colour"] = "red"; }), "tool.colour");
  expectRejected(job([](nlohmann::json& j) { j["path"]["raster"]["stepover"] = 1; }),
                 "path.raster.stepover");
  expectRejected(job([](nlohmann::json& j) { j["stock"]["min"] = "zero"; }), "stock.min");
}

TEST_F(Cli, BadCutterParametersAreNamed) {
  expectRejected(job([](nlohmann::json& j) { j["tool"]["corner_radius"] = 3.0; }),
                 "tool.corner_radius");
  expectRejected(job([](nlohmann::json& j) { j["tool"]["radius"] = -1; }), "tool.radius");
  expectRejected(job([](nlohmann::json& j) { j["tool"]["type"] = "drill"; }), "tool.type");
  expectRejected(job([](nlohmann::json& j) { j["path"]["raster"]["lead_deg"] = 95; }),
                 "path.raster.lead_deg");
}

TEST_F(Cli, BadSpacingIsNamed) {
  expectRejected(job([](nlohmann::json& j) { j["grid"]["spacing"] = 0; }), "grid.spacing");
  expectRejected(job([](nlohmann::json& j) { j["grid"]["spacing"] = -0.01; }), "grid.spacing");
}

TEST_F(Cli, GridTooLargeIsRefusedUpFrontWithItsSize) {
  expectRejected(job([](nlohmann::json& j) { j["grid"]["spacing"] = 1e-6; }), "GiB");
}

TEST_F(Cli, UnwritableOutputFolderIsBadInput) {
  // A regular file where the folder should be: it can neither be created nor written.
  const fs::path blocker = write("blocker", "x");
  const CliRun r = run("simulate " + job().string() + " -o " + (blocker / "sub").string());
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("blocker"), std::string::npos) << r.err;
}

TEST_F(Cli, SimulateWritesEveryOutputAndTheReportDescribesThem) {
  const fs::path out = dir_ / "out";
  fs::create_directories(out);
  std::ofstream(out / "keep.txt") << "mine";
  const CliRun r =
      run("simulate " + job().string() + " -o " + out.string() + " --json --threads 2");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(r.out);  // stdout is exactly the JSON
  EXPECT_EQ(report, nlohmann::json::parse(slurp(out / "report.json")));
  EXPECT_EQ(report["grid"]["nx"], 40);
  EXPECT_EQ(report["grid"]["ny"], 60);
  EXPECT_EQ(report["inputs"]["tool"]["type"], "bull");
  EXPECT_EQ(report["sweep"]["cutting_moves"], report["sweep"]["swept_segments"]);
  EXPECT_EQ(slurp(out / "keep.txt"), "mine");
  for (const char* f : {"heights.exr", "heights.gsf", "preview.png", "report.json"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  for (const auto& entry : fs::directory_iterator(out))
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();

  // The floor of the raster is at stock top - depth: nothing is below it, and the cells
  // nearest a pass centre line (0.025 mm away) are within a few micrometres of it.
  const scallop::ZMap map = scallop::readHeightsExr((out / "heights.exr").string());
  const double minHeight = report["measurements"]["min_height"].get<double>();
  EXPECT_GE(minHeight, -0.3 - 1e-12);
  EXPECT_LT(minHeight, -0.3 + 1e-4);
  EXPECT_NEAR(map.minHeight(), minHeight, 1e-7);  // float32 in the file
  const std::string stats =
      "oiiotool --stats " + (out / "heights.exr").string() + " >/dev/null 2>&1";
  EXPECT_EQ(std::system(stats.c_str()), 0);
}

TEST_F(Cli, ResultsDoNotDependOnThreads) {
  const fs::path a = dir_ / "a", b = dir_ / "b";
  ASSERT_EQ(run("simulate " + job().string() + " -o " + a.string() + " --threads 1").status, 0);
  ASSERT_EQ(run("simulate " + job().string() + " -o " + b.string() + " --threads 2").status, 0);
  EXPECT_EQ(slurp(a / "heights.gsf"), slurp(b / "heights.gsf"));
  const scallop::ZMap ma = scallop::readHeightsExr((a / "heights.exr").string());
  const scallop::ZMap mb = scallop::readHeightsExr((b / "heights.exr").string());
  EXPECT_EQ(ma.heights(), mb.heights());
}

TEST_F(Cli, PathFileWithBadLineIsNamed) {
  write("part.cl", "# test\n0 0 0\n1 0 0\nfoo 1 2\n");
  expectRejected(job([](nlohmann::json& j) { j["path"] = {{"file", "part.cl"}}; }), "part.cl:4");
}

}  // namespace
