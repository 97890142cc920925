// Jobs with "stock": {"stl": ...} or {"gsf": ...} (CONVENTIONS.md "Stock of any
// shape"): a run on a previous run's heights continues it (bit for bit on the heights
// as stored); a faceted cone blank
// machined by a raster keeps the cone's closed-form heights where it is not cut and
// holds no material (NaN) off its base; the rapid warning is judged against the cone,
// not its bounding box; a stock STL that is not closed, or missing, is an error naming
// stock.stl with nothing written; so is a GSF that does not cover the grid, or missing.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "base/constants.h"
#include "base/input_error.h"
#include "tests/support/cli_harness.h"
#include "tests/support/input_error_message.h"
#include "tools/io/height_export.h"
#include "tools/io/job.h"
#include "tools/run/job_loader.h"
#include "tools/run/simulation_run.h"

namespace scallop {
namespace {

namespace fs = std::filesystem;

// A cone of N side facets: apex (10, 10, 0), base circle of radius 8 at z = -4 closed by
// a fan of N facets about its centre; outward, counter-clockwise facets. `skip` leaves
// facet `skip` (0-based) out: a hole.
constexpr int kFacets = 32;
constexpr double kCx = 10, kCy = 10, kRadius = 8, kHeight = 4;

std::string coneStl(int skip = -1, bool flipFirst = false) {
  std::vector<Vec3> rim(kFacets);
  for (int k = 0; k < kFacets; ++k) {
    const double a = 2 * kPi * k / kFacets;
    rim[size_t(k)] = {kCx + kRadius * std::cos(a), kCy + kRadius * std::sin(a), -kHeight};
  }
  const Vec3 apex{kCx, kCy, 0}, centre{kCx, kCy, -kHeight};
  std::vector<std::array<Vec3, 3>> facets;
  for (int k = 0; k < kFacets; ++k) {
    const Vec3 b0 = rim[size_t(k)], b1 = rim[size_t((k + 1) % kFacets)];
    facets.push_back({apex, b0, b1});
    facets.push_back({centre, b1, b0});
  }
  if (flipFirst) std::swap(facets[0][1], facets[0][2]);
  std::ostringstream out;
  out.precision(17);
  out << "solid cone\n";
  for (size_t f = 0; f < facets.size(); ++f) {
    if (int(f) == skip) continue;
    out << "facet normal 0 0 0\nouter loop\n";
    for (const Vec3& p : facets[f]) out << "vertex " << p.x << " " << p.y << " " << p.z << "\n";
    out << "endloop\nendfacet\n";
  }
  out << "endsolid cone\n";
  return out.str();
}

// The faceted cone's top at (x, y) in closed form (NaN off its base polygon): on the
// side facet k between rim angles 2 pi k / N and 2 pi (k + 1) / N, the plane through the
// apex that falls kHeight over the apothem R cos(pi / N) along the facet's mid angle.
double coneTop(double x, double y) {
  const double r = std::hypot(x - kCx, y - kCy);
  double phi = std::atan2(y - kCy, x - kCx);
  if (phi < 0) phi += 2 * kPi;
  const double sector = 2 * kPi / kFacets;
  const double mid = (std::floor(phi / sector) + 0.5) * sector;
  const double along = r * std::cos(phi - mid), apothem = kRadius * std::cos(kPi / kFacets);
  return along > apothem ? NAN : -kHeight * along / apothem;
}

class StockShapeRun : public test::CliFixture {
 protected:
  std::string errorOf(const fs::path& jobFile) {
    return inputErrorMessage([&] { loadJobFile(jobFile.string()); });
  }
};

TEST_F(StockShapeRun, UncutCellsOfAConeBlankHoldTheConesHeights) {
  write("cone.stl", coneStl());
  const fs::path job = write("j.json", R"({"tool": {"type": "ball", "radius": 1},
    "stock": {"stl": "cone.stl"}, "grid": {"spacing": 0.25},
    "path": {"raster": {"direction": "x", "step_over": 3, "depth": 1}}})");
  const Job loaded = loadJobFile(job.string());
  EXPECT_EQ(loaded.stock.max.z, 0);  // the grid spans the cone's bounding box
  EXPECT_EQ(loaded.stock.min.x, 2);
  RunSettings settings;
  settings.quiet = true;
  const ZMap map = computeSimulation(loaded, settings).map;
  const GridSpec& g = map.grid();
  int64_t cut = 0, uncut = 0, voids = 0;
  for (int64_t j = 0; j < g.ny; ++j)
    for (int64_t i = 0; i < g.nx; ++i) {
      const double x = g.cellCentreX(i), y = g.cellCentreY(j), h = map.at(i, j);
      const double cone = coneTop(x, y);
      if (std::isnan(cone)) {
        EXPECT_TRUE(std::isnan(h)) << x << " " << y << " " << h;
        ++voids;
        continue;
      }
      ASSERT_FALSE(std::isnan(h)) << x << " " << y;
      EXPECT_LE(h, cone + 1e-12) << x << " " << y;
      // The ball's lowest point is the floor z = -1: below it nothing is cut.
      if (cone < -1) {
        EXPECT_NEAR(h, cone, 1e-12) << x << " " << y;
      }
      (h < cone - 1e-9 ? cut : uncut) += 1;
    }
  EXPECT_GT(cut, 50);
  EXPECT_GT(uncut, 1000);
  EXPECT_GT(voids, 500);
}

TEST_F(StockShapeRun, RapidsAreJudgedAgainstTheSolidNotItsBox) {
  write("cone.stl", coneStl());
  // Line 4's rapid runs along x = 18.5 at z = -0.5: inside the cone's box, below its
  // top, but the cone within the ball's reach there is lower than -3.7. Line 10's
  // rapid crosses the cone's apex region at z = -0.5.
  write("p.txt",
        "1 1 -0.5\n19 1 -0.5\n\n18.5 19 -0.5\n1 19 -0.5\n\n1 10 -0.5\n19 10 -0.5\n\n"
        "1 10.5 -0.5\n1 12 5\n");
  const std::string tail = R"(, "grid": {"spacing": 0.5}, "tool": {"type": "ball", "radius": 1},
    "path": {"file": "p.txt"}})";
  const Job solid = loadJobFile(write("s.json", R"({"stock": {"stl": "cone.stl"})" + tail));
  ASSERT_EQ(solid.pathWarnings.total, 1u);
  // Worded for the solid: its highest point within the ball's reach (R = 1) of the
  // rapid is the apex (10, 10, 0), 0.5 mm above the ball's lowest point.
  const std::string& w = solid.pathWarnings.kept[0];
  EXPECT_NE(w.find("p.txt:10: rapid move cuts the solid stock "), std::string::npos) << w;
  EXPECT_NE(w.find("cone.stl: the solid rises to z = 0 mm at (x, y) = (10, 10) mm within the "
                   "cutter's reach of the move, 0.5 mm above the cutter's lowest point (z = -0.5 "
                   "mm); judged against the stock as it started"),
            std::string::npos)
      << w;
  EXPECT_EQ(w.find("stock top"), std::string::npos) << w;
  // A warning, not an error: the run completes (exit 0) and says it on stderr.
  const test::CliRun r = run("simulate " + path("s.json") + " -o " + path("out"));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("rapid move cuts the solid stock"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "out" / "report.json"));
  // The same path over the cone's bounding box as a box stock warns of both.
  const Job box =
      loadJobFile(write("b.json", R"({"stock": {"min": [2, 2, -4], "max": [18, 18, 0]})" + tail));
  EXPECT_EQ(box.pathWarnings.total, 2u);
}

TEST_F(StockShapeRun, AStockThatIsNotAClosedSolidIsAnErrorAndWritesNothing) {
  write("line.txt", "0 5 -0.5\n10 5 -0.5\n");
  write("hole.stl", coneStl(5));
  write("flipped.stl", coneStl(-1, true));
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"hole.stl", "belongs to no other facet"},
      {"flipped.stl", "same edge in the same direction"},
      {"missing.stl", "cannot"},
  };
  for (const auto& [stl, reason] : cases) {
    SCOPED_TRACE(stl);
    write("bad.json", R"({"tool": {"type": "ball", "radius": 1}, "stock": {"stl": ")" + stl +
                          R"("}, "grid": {"spacing": 0.5}, "path": {"file": "line.txt"}})");
    const std::string error = errorOf(dir_ / "bad.json");
    EXPECT_NE(error.find("stock.stl"), std::string::npos) << error;
    EXPECT_NE(error.find(reason), std::string::npos) << error;
    if (stl != "hole.stl") continue;  // one run of the CLI: the same error path for all
    const test::CliRun r = run("simulate " + path("bad.json") + " -o " + path("out"));
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("bad.json: stock.stl"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "out"));
  }
}

ZMap heightsOf(const fs::path& jobFile) {
  RunSettings settings;
  settings.quiet = true;
  return computeSimulation(loadJobFile(jobFile.string()), settings).map;
}

TEST_F(StockShapeRun, ARunOnAPreviousRunsHeightsContinuesIt) {
  write("a.txt", "0 3 -0.3\n10 3 -0.3\n");
  write("b.txt", "0 4.2 -0.5\n10 4.2 -0.5\n");
  write("ab.txt", "0 3 -0.3\n10 3 -0.3\n\n0 4.2 -0.5\n10 4.2 -0.5\n");
  const std::string rest = R"(, "grid": {"spacing": 0.1}, "tool": {"type": "ball", "radius": 1},
    "path": {"file": ")";
  const std::string box = R"({"stock": {"min": [0, 0, -2], "max": [10, 8, 0]})";
  const test::CliRun a = run("simulate " + write("a.json", box + rest + "a.txt\"}}").string() +
                             " -o " + path("A") + " --json");
  ASSERT_EQ(a.status, 0) << a.err;
  const ZMap both = heightsOf(write("ab.json", box + rest + "ab.txt\"}}"));
  const ZMap continued =
      heightsOf(write("b.json", R"({"stock": {"gsf": "A/heights.gsf"})" + rest + "b.txt\"}}"));
  ASSERT_EQ(continued.nx(), both.nx());
  ASSERT_EQ(continued.ny(), both.ny());
  EXPECT_EQ(continued.grid().originX, both.grid().originX);
  // heights.gsf holds float32 metres (tools/io/height_images.h): B continues the stock as
  // read back bit for bit, min(A's heights as stored, B's cut), and equals the one run of
  // A and B to that storage's rounding (2^-24 of 2 mm is 1.2e-7 mm).
  const ZMap stored = readHeightFile(path("A/heights.gsf"));
  const ZMap onlyB = heightsOf(write("bb.json", box + rest + "b.txt\"}}"));
  ASSERT_EQ(stored.heights().size(), both.heights().size());
  for (size_t k = 0; k < both.heights().size(); ++k) {
    ASSERT_EQ(continued.heights()[k], std::min(stored.heights()[k], onlyB.heights()[k])) << k;
    ASSERT_NEAR(continued.heights()[k], both.heights()[k], 2e-7) << k;
  }
  EXPECT_LT(both.minHeight(), -0.45);  // both passes cut
  EXPECT_LT(stored.minHeight(), -0.25);

  // A grid the map does not cover, and a missing map: errors naming stock.gsf.
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"("gsf": "A/heights.gsf", "min": [-1, 0, 0], "max": [10, 8, 0])", "does not cover"},
      {R"("gsf": "none/heights.gsf")", "no such file"},
  };
  for (const auto& [stock, reason] : cases) {
    SCOPED_TRACE(stock);
    write("bad.json", R"({"stock": {)" + stock + "}" + rest + "b.txt\"}}");
    const std::string error = errorOf(dir_ / "bad.json");
    EXPECT_NE(error.find("stock.gsf"), std::string::npos) << error;
    EXPECT_NE(error.find(reason), std::string::npos) << error;
    if (reason != "does not cover") continue;  // one run of the CLI
    const test::CliRun r = run("simulate " + path("bad.json") + " -o " + path("out"));
    EXPECT_EQ(r.status, 1);
    EXPECT_FALSE(fs::exists(dir_ / "out"));
  }
}

}  // namespace
}  // namespace scallop
