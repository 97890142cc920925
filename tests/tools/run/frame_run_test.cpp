// Jobs with "grid": {"frame"} (CONVENTIONS.md "Frames") run end to end: the default
// frame gives the map without a frame bit for bit; a wall machined by a ball on a
// horizontal axis, seen from the side, is the closed form of its scallops; depth and
// cut-through counting against a closed-form plunge; lines that miss the stock are NaN
// in heights.exr and heights.gsf and counted; bad frames and axes pointing away from
// the normal are errors naming the field or line, with nothing written.
#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <zip.h>

#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <set>

#include "analysis/triangle_mesh.h"
#include "base/input_error.h"
#include "tests/support/cli_harness.h"
#include "tests/support/input_error_message.h"
#include "tools/io/job.h"
#include "tools/io/stl_io.h"
#include "tools/run/job_loader.h"
#include "tools/run/simulation_run.h"

namespace scallop {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

class FrameRun : public test::CliFixture {
 protected:
  ZMap heightsOf(const fs::path& jobFile) {
    RunSettings settings;
    settings.quiet = true;
    return computeSimulation(loadJobFile(jobFile.string()), settings).map;
  }
  std::string errorOf(const fs::path& jobFile) {
    return inputErrorMessage([&] { loadJobFile(jobFile.string()); });
  }
};

TEST_F(FrameRun, TheDefaultFrameGivesTheMapWithoutAFrameBitForBit) {
  json job = json::parse(defaultJobJson());
  job["grid"]["spacing"] = 0.05;
  const ZMap plain = heightsOf(write("plain.json", job.dump()));
  job["grid"]["frame"] = {
      {"origin", {0, 0, 0}}, {"u", {1, 0, 0}}, {"normal", {0, 0, 1}}, {"size", {20, 20}}};
  const ZMap framed = heightsOf(write("framed.json", job.dump()));
  ASSERT_EQ(framed.nx(), plain.nx());
  ASSERT_EQ(framed.ny(), plain.ny());
  EXPECT_TRUE(framed.heights() == plain.heights());
  EXPECT_LT(plain.minHeight(), -0.4);  // it cut
}

// A ball R = 1 on the horizontal axis +X cuts the wall x = 20 in passes along y at
// heights z_k = -0.4 - 0.8 k, its tip at x = 19.7. Seen along +X (u = +Y, v = +Z) from
// (20, 0, -5), a cell at (y, z) holds 0.7 - sqrt(1 - (z - z_k)^2), the lowest over the
// passes: the scallops of step 0.8 on the wall.
TEST_F(FrameRun, AWallCutByAHorizontalBallIsTheClosedFormSeenFromTheSide) {
  std::string cl;
  const int passes = 6;
  for (int k = 0; k < passes; ++k) {
    const double z = -0.4 - 0.8 * k;
    cl += fmt::format("25 -2 {0} 1 0 0\n19.7 -2 {0} 1 0 0\n19.7 12 {0} 1 0 0\n25 12 {0} 1 0 0\n\n",
                      z);
  }
  write("wall.cl", cl);
  const fs::path jobFile = write("wall.json", R"({
    "tool":  {"type": "ball", "radius": 1},
    "stock": {"min": [0, 0, -5], "max": [20, 10, 0]},
    "grid":  {"spacing": 0.05, "frame": {"origin": [20, 0, -5], "u": [0, 1, 0],
                                         "normal": [1, 0, 0], "size": [10, 5]}},
    "path":  {"file": "wall.cl"}})");
  const ZMap map = heightsOf(jobFile);
  const GridSpec& g = map.grid();
  ASSERT_EQ(g.nx, 200);
  ASSERT_EQ(g.ny, 100);
  double worst = 0;
  for (int64_t j = 0; j < g.ny; ++j) {
    const double z = g.cellCentreY(j) - 5;
    double expected = 0;  // the wall itself
    for (int k = 0; k < passes; ++k) {
      const double dz = z - (-0.4 - 0.8 * k);
      if (std::fabs(dz) < 1) expected = std::min(expected, 0.7 - std::sqrt(1 - dz * dz));
    }
    for (int64_t i = 0; i < g.nx; ++i) worst = std::max(worst, std::fabs(map.at(i, j) - expected));
  }
  EXPECT_LE(worst, 1e-9);
  EXPECT_LT(map.minHeight(), -0.29);  // the balls' bottoms: 0.7 - 1 at the passes
  EXPECT_GT(map.maxHeight(), -0.22);  // crests, and the rows beyond the last pass
}

// The vertical design comparison runs in the frame: the wall's design (the plane
// x = 19.75 where the passes' bottoms lie, two facets facing +X; exact in the STL's
// float32) seen from +X has w = -0.25 on every line, so each cell's deviation is its
// height + 0.25: the scallops. One pass 0.125 mm deeper than the design (tip x =
// 19.625, at z = -2.025, a row of cell centres) is a gouge traced to its moves' lines. Normal
// deviation in a frame is refused (it does not depend on one).
TEST_F(FrameRun, TheDesignIsComparedAlongTheFramesNormal) {
  std::string cl;
  for (int k = 0; k < 6; ++k) {
    const double z = k == 2 ? -2.025 : -0.4 - 0.8 * k, x = k == 2 ? 19.625 : 19.75;
    cl += fmt::format("25 -2 {0} 1 0 0\n{1} -2 {0} 1 0 0\n{1} 12 {0} 1 0 0\n25 12 {0} 1 0 0\n\n", z,
                      x);
  }
  write("wall.cl", cl);
  TriangleMesh wall;
  wall.vertices = {{19.75, -1, -6}, {19.75, 11, -6}, {19.75, 11, 1}, {19.75, -1, 1}};
  wall.triangles = {{0, 1, 2}, {0, 2, 3}};
  wall.normals = {{1, 0, 0}, {1, 0, 0}};
  writeStl(wall, path("wall.stl"), StlFormat::Binary, "wall");
  json job = json::parse(R"({
    "tool":  {"type": "ball", "radius": 1},
    "stock": {"min": [0, 0, -5], "max": [20, 10, 0]},
    "grid":  {"spacing": 0.05, "frame": {"origin": [20, 0, -5], "u": [0, 1, 0],
                                         "normal": [1, 0, 0], "size": [10, 5]}},
    "path":  {"file": "wall.cl"},
    "design": {"stl": "wall.stl", "gouge_tolerance": 0.01}})");
  const test::CliRun r =
      run("simulate " + write("wall.json", job.dump()).string() + " -o " + path("out") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const json report = json::parse(r.out);
  const json& design = report.at("design");
  const json& dev = design.at("deviation_mm");
  const json& m = report.at("measurements");
  EXPECT_NEAR(dev.at("max").get<double>(), m.at("max_height").get<double>() + 0.25, 1e-12)
      << design;
  EXPECT_NEAR(dev.at("min").get<double>(), -0.125, 1e-9) << design;
  EXPECT_EQ(design.at("cells_compared"), 200 * 100);
  const json& gouges = design.at("gouges");
  EXPECT_EQ(gouges.at("count"), 1) << design;
  ASSERT_EQ(gouges.at("deepest").size(), 1u) << design;
  const json& gouge = gouges["deepest"][0];
  EXPECT_NEAR(gouge.at("depth_mm").get<double>(), 0.125, 1e-9);
  EXPECT_NEAR(gouge.at("y").get<double>() - 5, -2.025, 1e-12);  // v = z + 5 in the part
  const std::set<int> lines = {11, 12, 13};  // the deep pass's cutting moves' CL lines
  ASSERT_FALSE(gouge.at("moves").empty());
  for (const json& mv : gouge.at("moves"))
    EXPECT_TRUE(lines.count(mv.at("line").get<int>())) << gouge;
  EXPECT_TRUE(fs::exists(dir_ / "out" / "deviation.png"));

  job["design"]["normal_deviation"] = true;
  EXPECT_NE(errorOf(write("nd.json", job.dump())).find("does not depend on the map's frame"),
            std::string::npos);
}

// A ball R = 1 plunged to tip z = -1.5 at (5, 5), seen from above with depth 1: a
// cell at r from the axis is cut to -0.5 - sqrt(1 - r^2), below -1 where r^2 < 0.75:
// those hold -1 and are counted as cut through. A cutter pointing down whose every
// point stays below -1 (tip z = -4.9, R + flute length = 3) cannot reach the map and
// is not refused; one that reaches it is, naming its line.
TEST_F(FrameRun, DepthClampsAndCountsCutThroughCellsAndIgnoresMovesBelowIt) {
  const std::string plunge = "5 5 1 0 0 1\n5 5 -1.5 0 0 1\n\n8 8 10 1 0 0\n\n";
  write("plunge.cl", plunge + "8 8 -4.9 0 0 -1\n8 7 -4.9 0 0 -1\n");
  const std::string jobText = R"({
    "tool":  {"type": "ball", "radius": 1, "flute_length": 2},
    "stock": {"min": [0, 0, -5], "max": [10, 10, 0]},
    "grid":  {"spacing": 0.1, "frame": {"origin": [0, 10, 0], "u": [0, -1, 0],
              "normal": [0, 0, 1], "size": [10, 10], "depth": 1}},
    "path":  {"file": "plunge.cl"}})";
  const fs::path jobFile = write("plunge.json", jobText);
  RunSettings settings;
  settings.quiet = true;
  const ComputedSimulation sim = computeSimulation(loadJobFile(jobFile.string()), settings);
  const ZMap& map = sim.map;
  const GridSpec& g = map.grid();
  int64_t cutThrough = 0;
  double worst = 0;
  for (int64_t j = 0; j < g.ny; ++j)
    for (int64_t i = 0; i < g.nx; ++i) {
      // u = -Y, normal = +Z: v = normal x u = +X; cell (x', y') is the part's (y', 10 - x').
      const double px = g.cellCentreY(j), py = 10 - g.cellCentreX(i);
      const double r2 = (px - 5) * (px - 5) + (py - 5) * (py - 5);
      double expected = 0;
      if (r2 < 0.75) {
        expected = -1;
        ++cutThrough;
      } else if (r2 < 1) {
        expected = -0.5 - std::sqrt(1 - r2);
      }
      worst = std::max(worst, std::fabs(map.at(i, j) - expected));
    }
  EXPECT_LE(worst, 1e-9);
  ASSERT_GT(cutThrough, 0);
  EXPECT_EQ(sim.report.at("measurements").at("frame").at("cut_through_cells"), cutThrough);
  EXPECT_EQ(sim.report.at("measurements").at("frame").at("void_cells"), 0);
  EXPECT_EQ(sim.report.at("inputs").at("grid").at("frame").at("v"), json({1, 0, 0}));

  write("plunge.cl", plunge + "8 8 -3.5 0 0 -1\n8 7 -3.5 0 0 -1\n");
  const std::string err = errorOf(jobFile);
  EXPECT_NE(err.find("plunge.cl:7"), std::string::npos) << err;
  EXPECT_NE(err.find("grid.frame.normal"), std::string::npos) << err;
}

// Float32 heights of a GSF file, image row order.
std::vector<float> gsfValues(const std::string& bytes) {
  const size_t nul = bytes.find('\0');
  const size_t start = nul + 4 - nul % 4;
  std::vector<float> values((bytes.size() - start) / 4);
  std::memcpy(values.data(), bytes.data() + start, values.size() * 4);
  return values;
}

TEST_F(FrameRun, LinesThatMissTheStockAreNanInEveryHeightFileAndCounted) {
  write("groove.cl", "-5 5 -0.5\n15 5 -0.5\n");
  write("job.json", R"({
    "tool":  {"type": "ball", "radius": 1},
    "stock": {"min": [0, 0, -5], "max": [10, 10, 0]},
    "grid":  {"spacing": 0.5, "frame": {"origin": [-2, 0, 0], "u": [1, 0, 0],
              "normal": [0, 0, 1], "size": [14, 10]}},
    "path":  {"file": "groove.cl"}})");
  const test::CliRun r = run("simulate " + path("job.json") + " -o " + path("out") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const json report = json::parse(r.out);
  // Columns of centre x < 0 or x > 10: 4 + 4 of 28, over 20 rows.
  EXPECT_EQ(report.at("measurements").at("frame").at("void_cells"), 160);
  EXPECT_EQ(report.at("surface_stats").at("cells"), 400);
  // The groove's bottom at cell centres 0.25 mm beside its axis: 0.5 - sqrt(1 - 0.25^2).
  EXPECT_NEAR(report.at("measurements").at("min_height").get<double>(), 0.5 - std::sqrt(1 - 0.0625),
              1e-12);

  const std::string gsf = test::slurp(dir_ / "out" / "heights.gsf");
  EXPECT_NE(gsf.find("ScallopFrame = origin (-2, 0, 0) mm"), std::string::npos);
  const std::vector<float> values = gsfValues(gsf);
  ASSERT_EQ(values.size(), 28u * 20u);
  auto inStock = [](size_t column) { return column >= 4 && column < 24; };
  for (size_t k = 0; k < values.size(); ++k)
    EXPECT_EQ(std::isnan(values[k]), !inStock(k % 28)) << k;

  auto exr = OIIO::ImageInput::open((dir_ / "out" / "heights.exr").string());
  ASSERT_TRUE(exr);
  EXPECT_NE(exr->spec().get_string_attribute("scallop:frame").find("normal (0, 0, 1)"),
            std::string::npos);
  std::vector<float> pixels(28 * 20);
  ASSERT_TRUE(exr->read_image(0, 0, 0, 1, OIIO::TypeDesc::FLOAT, pixels.data()));
  for (size_t k = 0; k < pixels.size(); ++k)
    EXPECT_EQ(std::isnan(pixels[k]), !inStock(k % 28)) << k;
  EXPECT_TRUE(fs::exists(dir_ / "out" / "preview.png"));

  // Downstream: the statistics leave the void cells out; a 16-bit export keeps 0 for
  // them and starts the heights at 1; an X3P stores NaN, ISO 5436-2's invalid point.
  const test::CliRun stats = run("stats " + path("out/heights.gsf") + " --json");
  ASSERT_EQ(stats.status, 0) << stats.err;
  EXPECT_EQ(json::parse(stats.out).at("surface_stats").at("cells"), 400);
  const test::CliRun tif =
      run("export " + path("out/heights.gsf") + " --to " + path("heights.tif"));
  ASSERT_EQ(tif.status, 0) << tif.err;
  auto in = OIIO::ImageInput::open((dir_ / "heights.tif").string());
  ASSERT_TRUE(in);
  EXPECT_NE(in->spec().get_string_attribute("ImageDescription").find("value 0: no material"),
            std::string::npos);
  std::vector<uint16_t> levels(28 * 20);
  ASSERT_TRUE(in->read_image(0, 0, 0, 1, OIIO::TypeDesc::UINT16, levels.data()));
  for (size_t k = 0; k < levels.size(); ++k) EXPECT_EQ(levels[k] == 0, !inStock(k % 28)) << k;
  EXPECT_EQ(run("export " + path("out/heights.gsf") + " --to " + path("heights.x3p")).status, 0);

  // Every export says which frame its heights are in (read back from the GSF and the
  // EXR): the TIFF's and PNG's ImageDescription (and PNG's scallop:frame), X3P's Comment,
  // a GSF or EXR written again.
  const std::string frame = "origin (-2, 0, 0) mm";
  EXPECT_NE(in->spec().get_string_attribute("ImageDescription").find("frame: " + frame),
            std::string::npos);
  ASSERT_EQ(run("export " + path("out/heights.exr") + " --to " + path("h.png")).status, 0);
  auto png = OIIO::ImageInput::open((dir_ / "h.png").string());
  ASSERT_TRUE(png);
  EXPECT_NE(png->spec().get_string_attribute("scallop:frame").find(frame), std::string::npos);
  ASSERT_EQ(run("export " + path("out/heights.exr") + " --to " + path("again.gsf")).status, 0);
  EXPECT_NE(test::slurp(dir_ / "again.gsf").find("ScallopFrame = " + frame), std::string::npos);
  ASSERT_EQ(run("export " + path("again.gsf") + " --to " + path("again.exr")).status, 0);
  auto again = OIIO::ImageInput::open((dir_ / "again.exr").string());
  ASSERT_TRUE(again);
  EXPECT_EQ(again->spec().get_string_attribute("scallop:frame"),
            exr->spec().get_string_attribute("scallop:frame"));
  int error = 0;
  zip_t* x3p = zip_open(path("heights.x3p").c_str(), ZIP_RDONLY, &error);
  ASSERT_NE(x3p, nullptr);
  zip_stat_t st;
  ASSERT_EQ(zip_stat(x3p, "main.xml", 0, &st), 0);
  std::string xml(size_t(st.size), '\0');
  zip_file_t* entry = zip_fopen(x3p, "main.xml", 0);
  ASSERT_NE(entry, nullptr);
  EXPECT_EQ(zip_fread(entry, xml.data(), st.size), zip_int64_t(st.size));
  zip_fclose(entry);
  zip_close(x3p);
  EXPECT_NE(xml.find("heights in the frame: " + frame), std::string::npos) << xml;
}

// Bands of a frame's map (void cells and all) are the in-memory map's bytes.
TEST_F(FrameRun, BandsGiveTheInMemoryFilesAndCounts) {
  write("wall.cl", "25 -2 -0.4 1 0 0\n19.7 -2 -0.4 1 0 0\n19.7 12 -0.4 1 0 0\n25 12 -0.4 1 0 0\n");
  write("job.json", R"({"tool": {"type": "ball", "radius": 1},
    "stock": {"min": [0, 0, -5], "max": [20, 10, 0]},
    "grid": {"spacing": 0.1, "frame": {"origin": [20, -1, -5], "u": [0, 1, 0],
             "normal": [1, 0, 0], "size": [12, 5]}},
    "path": {"file": "wall.cl"}})");
  const test::CliRun whole = run("simulate " + path("job.json") + " -o " + path("mem") + " --json");
  const test::CliRun bands =
      run("simulate " + path("job.json") + " -o " + path("band") + " --tile-rows 16 --json");
  ASSERT_EQ(whole.status, 0) << whole.err;
  ASSERT_EQ(bands.status, 0) << bands.err;
  EXPECT_EQ(test::slurp(dir_ / "mem" / "heights.gsf"), test::slurp(dir_ / "band" / "heights.gsf"));
  const json a = json::parse(whole.out), b = json::parse(bands.out);
  EXPECT_TRUE(b.contains("tiled"));
  EXPECT_EQ(a.at("measurements").at("frame"), b.at("measurements").at("frame"));
  EXPECT_EQ(a.at("measurements").at("frame").at("void_cells"), 2 * 10 * 50);  // y < 0, y > 10
  EXPECT_EQ(a.at("measurements").at("min_height"), b.at("measurements").at("min_height"));
}

TEST_F(FrameRun, BadFramesAreErrorsNamingTheFieldAndWriteNothing) {
  write("line.cl", "0 5 -0.5\n10 5 -0.5\n");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"("u": [1, 0, 0], "normal": [2, 0, 0], "size": [10, 10])", "grid.frame.normal"},
      {R"("u": [0, 0, 0], "normal": [0, 0, 1], "size": [10, 10])", "grid.frame.u"},
      {R"("u": [1, 0, 0], "normal": [0, 0, 0], "size": [10, 10])", "grid.frame.normal"},
      {R"("u": [1, 0, 0], "normal": [0, 0, 1], "size": [10, 0])", "grid.frame.size"},
      {R"("u": [1, 0, 0], "normal": [0, 0, 1])", "grid.frame.size"},
      {R"("u": [1, 0, 0], "normal": [0, 0, 1], "size": [10, 10], "depth": -1)", "grid.frame.depth"},
      {R"("u": [1, 0, 0], "normal": [0, 0, 1], "size": [10, 10], "up": 1)", "grid.frame.up"},
  };
  for (const auto& [frame, field] : cases) {
    SCOPED_TRACE(frame);
    write("bad.json", R"({"tool": {"type": "ball", "radius": 1},
      "stock": {"min": [0, 0, -5], "max": [10, 10, 0]},
      "grid": {"spacing": 0.5, "frame": {"origin": [0, 0, 0], )" +
                          frame + R"(}}, "path": {"file": "line.cl"}})");
    const test::CliRun r = run("simulate " + path("bad.json") + " -o " + path("out"));
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("bad.json: " + field), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "out"));
  }
}

}  // namespace
}  // namespace scallop
