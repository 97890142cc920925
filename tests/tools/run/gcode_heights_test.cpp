// G-code programs simulated (tools/io/gcode_reader.h through the exact sweep): a
// post's program gives the plain program's heights bit for bit; every drilling cycle
// leaves the closed-form hole of its cutters; a two-tool program the closed-form
// grooves of each ball; 5-axis TCP programs (xyzbc-trt, xyzac-trt) the brute-force
// sweep of the same pose curves within 1e-6 mm; report.json lists tools and ignored
// words.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <random>

#include "base/constants.h"
#include "raycast/simulation.h"
#include "sweep/brute_force_reference.h"
#include "tests/support/cli_harness.h"
#include "tools/io/job.h"
#include "tools/run/job_loader.h"

namespace scallop {
namespace {

namespace fs = std::filesystem;

class GcodeHeights : public test::CliFixture {
 protected:
  ZMap simulateJob(const fs::path& jobFile) {
    const Job job = loadJobFile(jobFile.string());
    return simulate(job.cutter, job.path, job.stock, job.grid()).map;
  }
  void expectFiveAxisAgrees(bool ac);
};

TEST_F(GcodeHeights, PostProgramGivesThePlainProgramsHeightsBitForBit) {
  const fs::path examples = fs::path(SCALLOP_SOURCE_DIR) / "examples";
  const ZMap post = simulateJob(examples / "ball_raster_post.json");
  const ZMap plain = simulateJob(examples / "ball_raster_gcode.json");
  EXPECT_TRUE(post.heights() == plain.heights());
  EXPECT_LT(*std::min_element(post.heights().begin(), post.heights().end()), -0.2);  // it cut
}

// Holes of a flat R1 (T1) and a ball R1 (T2) to z = -1, drilled by `cycle`: the flat's
// is a disk of depth 1, the ball's bottom is -1 + R - sqrt(R^2 - d^2).
TEST_F(GcodeHeights, EveryDrillingCycleLeavesTheClosedFormHole) {
  for (const char* cycle : {"G73", "G81", "G82", "G83", "G84", "G85", "G86", "G88", "G89"}) {
    SCOPED_TRACE(cycle);
    const std::string program = fmt::format(
        "%\nG21 G90 G17 G80\nT1 M6\nG0 X0 Y0 Z10\nG98 {0} X2 Y2 Z-1 R1 Q0.4 P0.2 F100\nG80\n"
        "T2 M6\nG0 X5.5 Y2\nG99 {0} Z-1 R1 Q0.3\nG80\nM30\n%\n",
        cycle);
    write("drill.nc", program);
    const fs::path jobFile = write("drill.json", R"({
      "tools": {"1": {"type": "flat", "radius": 1}, "2": {"type": "ball", "radius": 1}},
      "stock": {"min": [0, 0, -3], "max": [7.5, 4, 0]},
      "grid":  {"spacing": 0.05},
      "path":  {"file": "drill.nc"}})");
    const ZMap map = simulateJob(jobFile);
    const GridSpec& g = map.grid();
    int flat = 0, ball = 0;
    double worst = 0;
    for (int64_t j = 0; j < g.ny; ++j) {
      for (int64_t i = 0; i < g.nx; ++i) {
        const double x = g.cellCentreX(i), y = g.cellCentreY(j);
        const double d1 = std::hypot(x - 2, y - 2), d2 = std::hypot(x - 5.5, y - 2);
        if (std::fabs(d1 - 1) < 1e-6 || std::fabs(d2 - 1) < 1e-6) continue;
        double want = 0;
        if (d1 < 1) want = -1, ++flat;
        if (d2 < 1) want = std::fmin(want, -1 + 1 - std::sqrt(1 - d2 * d2)), ++ball;
        worst = std::fmax(worst, std::fabs(map.at(i, j) - want));
      }
    }
    EXPECT_GT(flat, 1000);
    EXPECT_GT(ball, 1000);
    EXPECT_LT(worst, 1e-9);
  }
}

// Two ball passes along x with different tools: on each centre line the depth, between
// them the circles of both radii (clipped at the stock top).
TEST_F(GcodeHeights, TwoToolProgramGivesEachToolsGroove) {
  write("two.nc",
        "G21 G90\nT3 M6\nG0 X-2 Y1.2 Z5\nG1 Z-0.4\nX9\nG0 Z5\nT8 M6\nG0 X-2 Y2.6\n"
        "G1 Z-0.2\nX9\nG0 Z5\nM30\n");
  const fs::path jobFile = write("two.json", R"({
      "tools": {"3": {"type": "ball", "radius": 1}, "8": {"type": "ball", "radius": 0.5}},
      "stock": {"min": [0, 0, -2], "max": [7, 4, 0]},
      "grid":  {"spacing": 0.02},
      "path":  {"file": "two.nc"}})");
  const ZMap map = simulateJob(jobFile);
  const GridSpec& g = map.grid();
  double worst = 0;
  for (int64_t j = 0; j < g.ny; ++j) {
    const double y = g.cellCentreY(j), d1 = std::fabs(y - 1.2), d2 = std::fabs(y - 2.6);
    double want = 0;
    if (d1 < 1) want = std::fmin(want, -0.4 + 1 - std::sqrt(1 - d1 * d1));
    if (d2 < 0.5) want = std::fmin(want, -0.2 + 0.5 - std::sqrt(0.25 - d2 * d2));
    for (int64_t i = 0; i < g.nx; ++i) worst = std::fmax(worst, std::fabs(map.at(i, j) - want));
  }
  EXPECT_LT(worst, 1e-9);
  // The report lists both tools with their moves and first lines.
  const test::CliRun r = run("simulate " + jobFile.string() + " -o " + (dir_ / "out").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(test::slurp(dir_ / "out" / "report.json"));
  const nlohmann::json& tools = report.at("path_file").at("tools");
  ASSERT_EQ(tools.size(), 2u);
  EXPECT_EQ(tools[0].at("number"), 3);
  EXPECT_EQ(tools[0].at("cutting_moves"), 2);
  EXPECT_EQ(tools[0].at("first_line"), 4);
  EXPECT_EQ(tools[1].at("number"), 8);
  EXPECT_EQ(tools[1].at("tool").at("radius"), 0.5);
  EXPECT_EQ(tools[1].at("first_line"), 9);
  bool listedM6 = false;
  for (const auto& w : report.at("path_file").at("ignored_words"))
    listedM6 |= w.at("word") == "M30";
  EXPECT_TRUE(listedM6);
}

// A generated 5-axis program with TCP on, simulated, against the brute-force sweep of
// the same pose curves (tip linear, B/A and C linear in t, the axis from
// CONVENTIONS.md's formula), written here from the program's own numbers.
void GcodeHeights::expectFiveAxisAgrees(bool ac) {
  SCOPED_TRACE(ac ? "xyzac-trt" : "xyzbc-trt");
  const char tiltLetter = ac ? 'A' : 'B';
  struct Point {
    double x, y, z, tilt, c;
  };
  std::vector<Point> points;
  std::mt19937_64 rng(ac ? 5 : 3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 5; ++k)
    points.push_back(
        {0.5 + 1.2 * k, 2 + 0.6 * u(rng), -0.3 + 0.1 * u(rng), 12 * u(rng), 40 * u(rng)});
  std::string program = "G21 G90 G94\nM428 (TCP on)\n";
  program += fmt::format("G0 X{} Y{} Z5 {}{} C{}\n", points[0].x, points[0].y, tiltLetter,
                         points[0].tilt, points[0].c);
  program += "G93\n";
  for (const Point& p : points)
    program += fmt::format("G1 X{:.6f} Y{:.6f} Z{:.6f} {}{:.6f} C{:.6f} F60\n", p.x, p.y, p.z,
                           tiltLetter, p.tilt, p.c);
  program += "G94 G0 Z10\nM429\nM30\n";
  write("five.ngc", program);
  const std::string kin = ac ? "xyzac-trt" : "xyzbc-trt";
  const std::string job = R"({
      "tool": {"type": "bull", "radius": 1.5, "corner_radius": 0.5},
      "machine": {"kinematics": ")" +
                          kin + R"(", "tcp_on": ["M428"], "tcp_off": ["M429"]},
      "stock": {"min": [0, 0, -2], "max": [6, 4, 0]},
      "grid":  {"spacing": 0.25},
      "path":  {"file": "five.ngc"}})";
  const Job loaded = loadJobFile(write("five.json", job).string());
  const ZMap map = simulate(loaded.cutter, loaded.path, loaded.stock, loaded.grid()).map;
  // The reference's pose curves, from the rounded numbers the program holds.
  const ref::RefCutter rc = ref::makeRefCutter(CutterType::Bull, 1.5, 0.5);
  std::vector<ref::RefCurve> curves;
  auto round6 = [](double v) { return std::stod(fmt::format("{:.6f}", v)); };
  for (size_t k = 0; k + 1 < points.size(); ++k) {
    const Point a = points[k], b = points[k + 1];
    const double t0 = degToRad(round6(a.tilt)), t1 = degToRad(round6(b.tilt));
    const double c0 = degToRad(round6(a.c)), c1 = degToRad(round6(b.c));
    curves.push_back(
        {{round6(a.x), round6(a.y), round6(a.z)},
         {round6(b.x), round6(b.y), round6(b.z)},
         [=](double t) {
           const double T = t0 + (t1 - t0) * t, C = c0 + (c1 - c0) * t;
           if (ac) return Vec3{std::sin(C) * std::sin(T), std::cos(C) * std::sin(T), std::cos(T)};
           return Vec3{-std::cos(C) * std::sin(T), std::sin(C) * std::sin(T), std::cos(T)};
         }});
  }
  const GridSpec& g = map.grid();
  int compared = 0, cut = 0;
  double worst = 0;
  for (int64_t j = 0; j < g.ny; ++j) {
    for (int64_t i = 0; i < g.nx; ++i) {
      const double x = g.cellCentreX(i), y = g.cellCentreY(j);
      double want = loaded.stock.max.z;
      bool grazing = false;
      for (const ref::RefCurve& c : curves) {
        double depth = 0;
        const ref::RefHit h = ref::turningLowest(rc, c, x, y, 201, &depth);
        grazing |= std::fabs(depth) < 1e-5;
        if (h.hit) want = std::fmin(want, h.z);
      }
      if (grazing) continue;
      ++compared;
      cut += want < loaded.stock.max.z - 0.05;
      worst = std::fmax(worst, std::fabs(map.at(i, j) - want));
    }
  }
  std::printf("%s: %d cells (%d cut), worst |simulated - brute force| = %.3g mm\n", kin.c_str(),
              compared, cut, worst);
  EXPECT_GT(compared, 250);
  EXPECT_GT(cut, 100);
  EXPECT_LT(worst, 1e-6);
}

TEST_F(GcodeHeights, FiveAxisTcpProgramsAgreeWithBruteForce) {
  expectFiveAxisAgrees(false);
  expectFiveAxisAgrees(true);
}

}  // namespace
}  // namespace scallop
