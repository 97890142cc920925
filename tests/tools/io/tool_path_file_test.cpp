// Tool-path files in jobs and on the command line (tools/io/tool_path_file.h): the same
// raster as a job and as G-code or 5-axis APT gives bit-identical heights; rapids into
// the stock are warned about with their line; CUTTER/ defines a missing tool;
// malformed files exit 1 with file:line and leave no output; a design surface adds
// gouges with the lines that made them.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "raycast/simulation.h"
#include "sweep/raster.h"
#include "tests/support/cli_harness.h"
#include "tools/io/job.h"
#include "tools/io/stl_io.h"
#include "tools/run/job_loader.h"

namespace scallop {
namespace {

namespace fs = std::filesystem;
using test::CliRun;

class PathFile : public test::CliFixture {
 protected:
  // Heights of a job file, simulated in memory.
  std::vector<double> heights(const fs::path& jobFile) {
    const Job job = loadJobFile(jobFile.string());
    SimulationOptions options;
    return simulate(job.cutter, job.path, job.stock, job.grid(), options).map.heights();
  }
};

constexpr const char* kBallJob = R"({
  "tool":  {"type": "ball", "radius": 1.0},
  "stock": {"min": [0, 0, -2], "max": [6, 4, 0]},
  "grid":  {"spacing": 0.02},
  "path":  %s
})";

std::string withPath(const std::string& path) {
  std::string j = kBallJob;
  return j.replace(j.find("%s"), 2, path);
}

TEST_F(PathFile, GcodeBallRasterEqualsTheJobRasterBitForBit) {
  const std::string raster = R"({"raster": {"direction": "x", "step_over": 0.5, "depth": 0.25}})";
  // The same passes by hand: y = 0, 0.5, ..., 4 from x = -2 to 8 at z = -0.25, rapids
  // above the stock between them.
  std::string g = "(ball raster, step-over 0.5 mm)\nG21 G90 G17\n";
  for (int k = 0; k <= 8; ++k)
    g += fmt::format("G0 X-2 Y{:.1f} Z5\nG1 Z-0.25 F500\nX8\nG0 Z5\n", 0.5 * k);
  write("raster.nc", g);
  const auto fromJob = heights(write("a.json", withPath(raster)));
  const auto fromGcode = heights(write("b.json", withPath(R"({"file": "raster.nc"})")));
  ASSERT_EQ(fromJob.size(), fromGcode.size());
  EXPECT_TRUE(fromJob == fromGcode) << "heights differ";
  EXPECT_LT(*std::min_element(fromJob.begin(), fromJob.end()), -0.2);  // it cut
}

TEST_F(PathFile, FiveAxisAptEqualsTheRasterLeadAndTiltBitForBit) {
  const Cutter cutter = Cutter::make(CutterType::Bull, 1.5, 0.5);
  const Box3 stock({0, 0, -2}, {5, 4, 0});
  RasterSpec spec;
  spec.stepOver = 0.7, spec.depth = 0.2, spec.leadDeg = 10, spec.tiltDeg = -4, spec.zigzag = true;
  const ToolPath raster = makeRaster(cutter, stock, spec);
  // CL data as a post-processor reads it: tip and unit tool axis, 17 digits.
  std::string apt = "PARTNO/LEAD TILT RASTER\nMULTAX\nCUTTER/3,0.5\nUNITS/MM\n";
  auto goto6 = [](const Pose& p) {
    return fmt::format("GOTO/{:.17g},{:.17g},{:.17g},$\n  {:.17g},{:.17g},{:.17g}\n", p.tip.x,
                       p.tip.y, p.tip.z, p.axis.x, p.axis.y, p.axis.z);
  };
  apt += "FROM/" + goto6(raster.moves[0].from).substr(5);
  for (const Move& mv : raster.moves) apt += (mv.rapid ? "RAPID\n" : "") + goto6(mv.to);
  apt += "FINI\n";
  write("raster.cl", apt);
  const std::string job = R"({
    "stock": {"min": [0, 0, -2], "max": [5, 4, 0]}, "grid": {"spacing": 0.025},
    "path": {"file": "raster.cl"}})";
  const Job fromFile = loadJobFile(write("apt.json", job).string());  // CUTTER/ is the tool
  EXPECT_EQ(fromFile.cutter.type, CutterType::Bull);
  ASSERT_EQ(fromFile.path.moves.size(), raster.moves.size());
  const GridSpec grid = fromFile.grid();
  const ZMap a = simulate(cutter, raster, stock, grid).map;
  const ZMap b = simulate(fromFile.cutter, fromFile.path, fromFile.stock, grid).map;
  EXPECT_TRUE(a.heights() == b.heights()) << "heights differ";
  // The raster's rapids run at cutting depth (they are never simulated); in a file
  // they are crashes, and each one is reported.
  EXPECT_EQ(fromFile.pathWarnings.total,
            size_t(std::count_if(raster.moves.begin(), raster.moves.end(),
                                 [](const Move& mv) { return mv.rapid; })));
  for (const std::string& w : fromFile.pathWarnings.kept)
    EXPECT_NE(w.find("rapid move cuts the stock"), std::string::npos) << w;
}

TEST_F(PathFile, RapidThroughTheStockIsWarnedWithItsLine) {
  write("p.txt", "# pass 1\n-2 1 -0.2\n8 1 -0.2\n\n-2 3 -0.2\n8 3 -0.2\n\n8 3 5\n");
  const Job job = loadJobFile(write("j.json", withPath(R"({"file": "p.txt"})")).string());
  // Line 5's rapid goes back across the stock at z = -0.2 (its ends are outside).
  ASSERT_EQ(job.pathWarnings.total, 1u);
  // Worded for a box: the cutter's lowest point, the tip there, how deep below the top,
  // and that the check knows the stock as it started only.
  const std::string& w = job.pathWarnings.kept[0];
  EXPECT_NE(w.find("p.txt:5: rapid move cuts the stock box: the cutter's lowest point, z = -0.2 "
                   "mm with the tip at (x, y) = (8, 1) mm, is 0.2 mm below its top z = 0 mm"),
            std::string::npos)
      << w;
  EXPECT_NE(w.find("judged against the stock as it started, not the material earlier moves left"),
            std::string::npos)
      << w;
  // The one from line 8 goes up, outside the stock's xy box: no warning. It cannot
  // reach the grid either: read, and left out (tools/io/move_window.h).
  EXPECT_EQ(job.movesRead, 4u);
  EXPECT_EQ(job.moveLines.back(), 6);
}

TEST_F(PathFile, ToolIsRequiredUnlessThePathDefinesIt) {
  write("p.nc", "G0 X0 Y0 Z1\nG1 X5\n");
  const std::string noTool = R"({"stock": {"min": [0, 0, -1], "max": [5, 4, 0]},
    "grid": {"spacing": 0.1}, "path": {"file": "p.nc"}})";
  const CliRun r = run("simulate " + write("j.json", noTool).string() + " -o " + path("out"));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("tool: missing"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("out")) && !fs::is_empty(path("out")));
}

TEST_F(PathFile, MalformedFilesExitOneNamingTheLineWithoutOutput) {
  // File, content, and what the message must say (file:line: ...).
  const char* cases[][3] = {
      {"bad.nc", "G0 X0 Y0 Z0\nG1 X1.2.3\n", "bad.nc:2: word X1.2.3"},
      {"g41.nc", "G0 X0 Y0 Z0\nG41\n", "g41.nc:2: G41 (cutter radius compensation)"},
      {"cut.nc", "G0 X0 Y0 Z0\nG1 X\n", "cut.nc:2: word X has no number"},
      {"mix.nc", "G0 X0 Y0 Z0\nG1 X1\nG20\n", "mix.nc:3: mixed units"},
      {"arc.nc", "G0 X0 Y0 Z0\nG2 X2 Y0 I1.5 J0\n", "arc.nc:2: arc radii differ"},
      {"nan.txt", "0 0 0\nnan 1 1\n", "nan.txt:2: expected a finite decimal number"},
      {"nan.cl", "GOTO/0,0,0\nGOTO/nan,0,0\n", "nan.cl:2: x: expected a finite decimal"},
      {"cont.apt", "GOTO/0,0,0\nGOTO/1,0,$\n", "cont.apt:2: the statement continues"},
  };
  for (const auto& [name, text, needle] : cases) {
    write(name, text);
    const fs::path out = dir_ / "out";
    const CliRun r = run("simulate " + write("j.json", withPath("{\"file\": \"x.txt\"}")).string() +
                         " --path " + path(name) + " -o " + out.string());
    EXPECT_EQ(r.status, 1) << name << ": " << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
    EXPECT_TRUE(!fs::exists(out) || fs::is_empty(out)) << name;
  }
}

TEST_F(PathFile, DesignReportNamesTheGougeAndTheLineThatMadeIt) {
  // Design: the plane z = -0.3 over the stock (two triangles). The path cuts at
  // -0.25 except one move that dips to -0.4 (line 4): a 0.1 mm gouge.
  const std::array<Vec3, 3> t1{{{-1, -1, -0.3}, {7, -1, -0.3}, {7, 5, -0.3}}};
  const std::array<Vec3, 3> t2{{{-1, -1, -0.3}, {7, 5, -0.3}, {-1, 5, -0.3}}};
  writeStl(meshFromTriangles({t1, t2}), path("plane.stl"), StlFormat::Binary, "plane");
  write("p.txt", "# x y z\n-2 2 -0.25\n2 2 -0.25\n3 2 -0.4\n4 2 -0.25\n8 2 -0.25\n");
  std::string job = withPath(R"({"file": "p.txt"})");
  job.insert(job.rfind('}'), R"(, "design": {"stl": "plane.stl", "gouge_tolerance": 0.001})");
  const CliRun r =
      run("simulate " + write("j.json", job).string() + " -o " + path("out") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto report = nlohmann::json::parse(r.out);
  const auto& d = report.at("design");
  EXPECT_EQ(d.at("gouges").at("count"), 1);
  const auto& g = d.at("gouges").at("deepest").at(0);
  // The ball's lowest point reaches -0.4 at (3, 2): 0.1 below the plane, to the grid's
  // resolution (the deepest cell centre is within half a cell of x = 3, y = 2).
  EXPECT_NEAR(g.at("depth_mm").get<double>(), 0.1, 1e-3);
  EXPECT_NEAR(g.at("x").get<double>(), 3, 0.011);
  std::vector<int> lines;
  for (const auto& m : g.at("moves")) lines.push_back(m.at("line"));
  EXPECT_EQ(lines, (std::vector<int>{4, 5}));  // the moves into and out of the dip
  // Where nothing was cut the stock top z = 0 is left above the plane (float32 in STL).
  EXPECT_EQ(d.at("deviation_mm").at("max").get<double>(), -double(-0.3f));
  EXPECT_TRUE(fs::exists(path("out/deviation.png")));
}

}  // namespace
}  // namespace scallop
