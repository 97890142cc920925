// The gouge run (tools/run/gouge_run.h) called directly, as the CLI and the Python
// module call it: the summary and report of a surface, the files it writes, and bad
// settings refused before anything is written.
#include "tools/run/gouge_run.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "analysis/analytic_surfaces.h"
#include "base/input_error.h"
#include "tests/support/temp_folder.h"
#include "tools/io/stl_io.h"

namespace scallop {
namespace {

namespace fs = std::filesystem;

class GougeRun : public test::TempFolderTest {
 protected:
  GougeRun() : TempFolderTest("gouge-run") {}
  void SetUp() override {
    TempFolderTest::SetUp();
    fs::create_directories(dir_);
  }

  std::string surface(SurfaceShape shape, int64_t facets) {
    SurfaceSpec spec;
    spec.shape = shape;
    spec.sizeX = 30;
    spec.sizeY = 20;
    spec.facets = facets;
    const std::string file = (dir_ / (std::string(toString(shape)) + ".stl")).string();
    writeStl(makeAnalyticSurface(spec), file, StlFormat::Binary, "gouge run test");
    return file;
  }

  // The surface of `shape` machined by a cylinder of `radius` and `length` (mm), mapped
  // on a 0.5 mm grid.
  GougeSettings settings(SurfaceShape shape, int64_t facets, double radius, double length) {
    GougeSettings s;
    s.surface = surface(shape, facets);
    s.radius = radius;
    s.length = length;
    s.gridSpacing = 0.5;
    return s;
  }
};

TEST_F(GougeRun, PlaneIsFullyMachinableAndTheReportSaysSo) {
  GougeSettings s = settings(SurfaceShape::Plane, 400, 3, 10);
  const GougeResult r = runGouge(s);
  EXPECT_EQ(r.stlFormat, "binary");
  EXPECT_GT(r.triangles, 0u);
  EXPECT_DOUBLE_EQ(r.sliceSpacingMm, 10);  // L when not given
  EXPECT_GT(r.summary.ccPoints, 0u);
  EXPECT_EQ(r.summary.freeInitial, r.summary.ccPoints);
  EXPECT_EQ(r.summary.nonMachinable, 0u);
  EXPECT_EQ(r.summary.gougingPostures, 0u);
  ASSERT_TRUE(r.map.has_value());
  EXPECT_EQ(r.map->overCutCells, 0);
  EXPECT_TRUE(r.outputs.empty());  // no folder, no postures file: nothing written

  // The report is the summary's, built by newReport() and printed as reportText().
  EXPECT_TRUE(r.report.contains("scallop_version"));
  EXPECT_EQ(r.report["cc_points"].get<size_t>(), r.summary.ccPoints);
  EXPECT_EQ(r.report["surface"]["triangles"].get<size_t>(), r.triangles);
  EXPECT_EQ(r.report["gouge_map"]["grid"]["spacing"].get<double>(), 0.5);
  EXPECT_EQ(nlohmann::json::parse(r.reportText), r.report);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

TEST_F(GougeRun, WritesThePosturesAndTheFolderItIsGiven) {
  GougeSettings s = settings(SurfaceShape::Dome, 300, 2, 5);
  s.posturesCsv = (dir_ / "postures.csv").string();
  s.outDir = (dir_ / "out").string();
  const GougeResult r = runGouge(s);
  ASSERT_EQ(r.outputs.size(), 4u);
  EXPECT_EQ(r.outputs[0], s.posturesCsv);
  for (const std::string& file : r.outputs) EXPECT_TRUE(fs::exists(file)) << file;
  std::ifstream report(dir_ / "out" / "report.json");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(report), {}), r.reportText);
  std::ifstream csv(s.posturesCsv);
  size_t lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  EXPECT_EQ(lines, r.summary.ccPoints + 1);  // a header, then one row per cc-point

  s.noMap = true;
  s.outDir.clear();
  s.posturesCsv.clear();
  const GougeResult noMap = runGouge(s);
  EXPECT_FALSE(noMap.map.has_value());
  EXPECT_TRUE(noMap.report["gouge_map"].is_null());
  EXPECT_EQ(noMap.summary.ccPoints, r.summary.ccPoints);
}

TEST_F(GougeRun, BadSettingsNameTheOptionAndWriteNothing) {
  GougeSettings good;
  good.surface = surface(SurfaceShape::Plane, 100);
  good.radius = 3;
  good.length = 10;
  good.posturesCsv = (dir_ / "p.csv").string();
  auto expectField = [&](GougeSettings s, const std::string& field) {
    try {
      runGouge(s);
      ADD_FAILURE() << "accepted bad " << field;
    } catch (const InputError& e) {
      EXPECT_EQ(e.where(), field) << e.what();
    }
    EXPECT_FALSE(fs::exists(good.posturesCsv)) << field;
  };
  GougeSettings s = good;
  s.radius = -3;
  expectField(s, "--radius");
  s = good;
  s.feed = "z";
  expectField(s, "--feed");
  s = good;
  s.inclinationAxis = "sideways";
  expectField(s, "--inclination-axis");
  s = good;
  s.gridSpacing = 1e-6;  // 3e15 cells
  expectField(s, "--grid-spacing");
  s = good;
  s.surface = (dir_ / "missing.stl").string();
  EXPECT_THROW(runGouge(s), InputError);
}

}  // namespace
}  // namespace scallop
