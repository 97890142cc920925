// `"design": {"normal_deviation": true}` end to end: deviation.ply (binary PLY with a
// float `deviation` per vertex) holds, on a plane design machined by a raster, the
// z-map's height less the plane; report.json has its statistics; a design whose facets
// disagree on their outside is an input error naming the facet, with nothing written, and
// bad keys name the key.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis/triangle_mesh.h"
#include "base/input_error.h"
#include "tests/support/cli_harness.h"
#include "tools/io/height_export.h"
#include "tools/io/job.h"
#include "tools/io/stl_io.h"

namespace scallop {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using scallop::test::CliRun;

const std::string kJob = R"({
  "tool": {"type": "ball", "radius": 1},
  "stock": {"min": [0, 0, -2], "max": [4, 4, 0]},
  "grid": {"spacing": 0.1},
  "path": {"raster": {"direction": "x", "step_over": 0.8, "depth": 0.3}},
  "design": {"stl": "plane.stl", "normal_deviation": true, "gouge_depth": 1}
})";

constexpr double kPlaneZ = -0.35;
constexpr int kSide = 9;  // vertices a side, at the cell centres 1.05, 1.25, ..., 2.65

Vec3 vertexAt(int a, int b) {
  return {0.05 + 0.1 * (10 + 2 * a), 0.05 + 0.1 * (10 + 2 * b), kPlaneZ};
}

// The plane z = kPlaneZ as a grid of facets facing +z (`flipOne`: the first facet wound
// the other way).
void writePlane(const std::string& file, bool flipOne, bool flipAll = false) {
  std::vector<std::array<Vec3, 3>> soup;
  for (int a = 0; a + 1 < kSide; ++a)
    for (int b = 0; b + 1 < kSide; ++b) {
      soup.push_back({vertexAt(a, b), vertexAt(a + 1, b), vertexAt(a, b + 1)});
      soup.push_back({vertexAt(a + 1, b), vertexAt(a + 1, b + 1), vertexAt(a, b + 1)});
    }
  if (flipOne) std::swap(soup[0][1], soup[0][2]);
  if (flipAll)
    for (auto& f : soup) std::swap(f[1], f[2]);
  writeStl(meshFromTriangles(soup), file, StlFormat::Binary, "plane");
}

struct Ply {
  std::string header;
  std::vector<std::array<float, 4>> vertices;  // x, y, z, deviation
};
Ply readPly(const std::string& bytes) {
  Ply ply;
  const size_t end = bytes.find("end_header\n");
  EXPECT_NE(end, std::string::npos);
  ply.header = bytes.substr(0, end);
  const size_t at = ply.header.find("element vertex ");
  const size_t n = std::stoul(ply.header.substr(at + 15));
  ply.vertices.resize(n);
  std::memcpy(ply.vertices.data(), bytes.data() + end + 11, n * 16);  // the test host is LE
  return ply;
}

class NormalDeviationRun : public scallop::test::CliFixture {};

TEST_F(NormalDeviationRun, ThePlyHoldsTheZMapLessThePlaneAndTheReportItsStatistics) {
  writePlane(path("plane.stl"), false);
  const CliRun r = run("simulate " + write("job.json", kJob).string() + " -o " + path("out"));
  ASSERT_EQ(r.status, 0) << r.err;
  const Ply ply = readPly(scallop::test::slurp(path("out/deviation.ply")));
  EXPECT_EQ(ply.header.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u) << ply.header;
  EXPECT_NE(ply.header.find("property float deviation\nelement face 128\n"), std::string::npos);
  ASSERT_EQ(ply.vertices.size(), size_t(kSide * kSide));
  const ZMap map = readHeightFile(path("out/heights.gsf"));
  double lowest = HUGE_VAL;
  for (const auto& v : ply.vertices) {
    const int64_t i = std::llround((v[0] - 0.05) / 0.1), j = std::llround((v[1] - 0.05) / 0.1);
    EXPECT_NEAR(v[3], map.at(i, j) - kPlaneZ, 1e-5) << i << ", " << j;
    lowest = std::fmin(lowest, v[3]);
  }
  const json report = json::parse(scallop::test::slurp(path("out/report.json")));
  const json& nd = report.at("design").at("normal_deviation");
  EXPECT_EQ(nd.at("vertices"), kSide * kSide);
  EXPECT_NEAR(nd.at("min_mm").get<double>(), lowest, 1e-6);
  EXPECT_EQ(nd.at("cut_through_vertices"), 0);
  EXPECT_EQ(nd.at("unresolved_vertices"), 0);
  EXPECT_EQ(nd.at("histogram").at("counts").size(), 20u);
  EXPECT_NE(report.at("outputs").dump().find("deviation.ply"), std::string::npos);
  // The picture of the coloured design (tools/render/deviation_view_png.h).
  EXPECT_TRUE(fs::is_regular_file(path("out/deviation_view.png")));
  EXPECT_EQ(nd.at("picture"), "deviation_view.png");
  EXPECT_NE(report.at("outputs").dump().find("deviation_view.png"), std::string::npos);
}

// The design 0.05 mm above the floor the raster cut (z = -0.25): the report's areas are
// the plane's (1.6 mm square) and the parts of it gouged and above a 5 um scallop
// limit, and the gouging moves are the raster's passes, deepest first, at the PLY's
// lowest value.
TEST_F(NormalDeviationRun, TheReportHasTheAreasAndTheMovesThatGouge) {
  std::vector<std::array<Vec3, 3>> soup;
  const auto at = [](int a, int b) { return Vec3{1.05 + 0.2 * a, 1.05 + 0.2 * b, -0.25}; };
  for (int a = 0; a + 1 < kSide; ++a)
    for (int b = 0; b + 1 < kSide; ++b) {
      soup.push_back({at(a, b), at(a + 1, b), at(a, b + 1)});
      soup.push_back({at(a + 1, b), at(a + 1, b + 1), at(a, b + 1)});
    }
  writeStl(meshFromTriangles(soup), path("plane.stl"), StlFormat::Binary, "plane");
  std::string job = kJob;
  job.replace(job.find(R"("gouge_depth": 1)"), 16, R"("gouge_depth": 1, "scallop_limit": 0.005)");
  const CliRun r = run("simulate " + write("job.json", job).string() + " -o " + path("out"));
  ASSERT_EQ(r.status, 0) << r.err;
  const json nd = json::parse(scallop::test::slurp(path("out/report.json")))
                      .at("design")
                      .at("normal_deviation");
  const json& areas = nd.at("areas");
  // 1e-6: the STL holds the corners in float32 (2.65 to 6e-8 relative).
  EXPECT_NEAR(areas.at("measured_mm2").get<double>(), 1.6 * 1.6, 1e-6) << areas;
  EXPECT_EQ(areas.at("facets_left_out"), 0);
  const double gouged = areas.at("gouged_mm2").get<double>();
  const double above = areas.at("above_limit_mm2").get<double>();
  EXPECT_GT(gouged, 0.5) << areas;  // the passes' grooves, 0.05 mm below the design
  // The highest vertices (between the passes) stand above the limit.
  ASSERT_GT(nd.at("max_mm").get<double>(), 0.005) << nd;
  EXPECT_GT(above, 0) << areas;
  EXPECT_LE(gouged + above, 1.6 * 1.6 + 1e-6);
  const json& moves = nd.at("gouging_moves");
  ASSERT_GE(moves.at("count").get<int>(), 2) << moves;
  const json& deepest = moves.at("deepest");
  EXPECT_NEAR(deepest[0].at("deepest_mm").get<double>(), nd.at("min_mm").get<double>(), 1e-12);
  for (size_t k = 1; k < deepest.size(); ++k)
    EXPECT_LE(deepest[k - 1].at("deepest_mm").get<double>(),
              deepest[k].at("deepest_mm").get<double>());
}

// An open design wound the wrong way round: its normals point down, into the part, and
// every vertex line is reached from behind. The run says so instead of writing a mesh of
// NaN in silence.
TEST_F(NormalDeviationRun, ADesignFacingAwayFromTheToolIsWarnedAbout) {
  writePlane(path("plane.stl"), false, true);
  const CliRun r = run("simulate " + write("job.json", kJob).string() + " -o " + path("out"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("warning: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("do the facets face inwards?"), std::string::npos) << r.err;
  const json report = json::parse(scallop::test::slurp(path("out/report.json")));
  const json& d = report["design"]["normal_deviation"];
  EXPECT_EQ(d["vertices"], 0);
  EXPECT_GT(d["unresolved_vertices"].get<int64_t>(), 0);
  EXPECT_NE(d["warning"].get<std::string>().find("plane.stl"), std::string::npos);
}

TEST_F(NormalDeviationRun, BadDesignsAndKeysAreErrorsWithNothingWritten) {
  writePlane(path("plane.stl"), true);
  CliRun r = run("simulate " + write("job.json", kJob).string() + " -o " + path("out"));
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("facet "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("wound the other way"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("out/deviation.ply")));
  EXPECT_FALSE(fs::exists(path("out/deviation_view.png")));
  EXPECT_FALSE(fs::exists(path("out/report.json")));

  for (const auto& [bad, field] :
       {std::pair{R"("gouge_depth": 0)", "design.gouge_depth"},
        std::pair{R"("normal_deviation": true, "scallop_limit": -1)", "design.scallop_limit"},
        std::pair{R"("scallop_limit": 0.01)", "design.scallop_limit"},
        std::pair{R"("normal_deviation": "yes", "gouge_depth": 1)", "design.normal_deviation"},
        std::pair{R"("normal_deviation": true, "view": {"elevation_deg": 95})",
                  "design.view.elevation_deg"},
        std::pair{R"("normal_deviation": true, "view": {"azimuth_deg": "north"})",
                  "design.view.azimuth_deg"},
        std::pair{R"("normal_deviation": true, "view": {"tilt_deg": 3})", "design.view"},
        std::pair{R"("view": {"azimuth_deg": 10})", "design.view"},
        std::pair{R"("normal_deviation": true, "view": {"light_azimuth_deg": 10})", "design.view"},
        std::pair{R"("normal_deviation": true, "view": {"light_azimuth_deg": 10,
                  "light_elevation_deg": 0})",
                  "design.view.light_elevation_deg"},
        std::pair{R"("normal_deviation": true, "view": {"projection": "fisheye"})",
                  "design.view.projection"}}) {
    std::string job = kJob;
    job.replace(job.find(R"("normal_deviation": true, "gouge_depth": 1)"),
                std::strlen(R"("normal_deviation": true, "gouge_depth": 1)"), bad);
    try {
      parseJob(job, "bad.json");
      ADD_FAILURE() << "no error for " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace scallop
