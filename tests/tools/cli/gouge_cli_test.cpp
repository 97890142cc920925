// `scallop surface` and `scallop gouge` as a user runs them: JSON on stdout only, the
// postures CSV, output files, and exit statuses with messages naming the input.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "tests/support/cli_harness.h"

namespace fs = std::filesystem;

namespace {

using CliResult = scallop::test::CliRun;
using scallop::test::slurp;

class GougeCli : public scallop::test::CliFixture {};

TEST_F(GougeCli, HelpNamesOptionsAndUnits) {
  const CliResult s = run("surface --help");
  EXPECT_EQ(s.status, 0);
  for (const char* w : {"--shape", "--size", "--facets", "dome", "bowl", "saddle", "wave", "mm"})
    EXPECT_NE(s.out.find(w), std::string::npos) << w;
  const CliResult g = run("gouge --help");
  EXPECT_EQ(g.status, 0);
  for (const char* w : {"--radius", "--length", "--slice-spacing", "--postures", "--json",
                        "--threads", "mm", "deg"})
    EXPECT_NE(g.out.find(w), std::string::npos) << w;
}

TEST_F(GougeCli, PlaneIsFullyMachinableWithJsonAndCsv) {
  const CliResult s =
      run("surface --shape plane --size 40 30 --facets 600 -o " + path("plane.stl"));
  ASSERT_EQ(s.status, 0) << s.err;
  const CliResult g =
      run("gouge " + path("plane.stl") + " --radius 3 --length 10 --json --postures " +
          path("p.csv") + " -o " + path("out"));
  ASSERT_EQ(g.status, 0) << g.err;
  const nlohmann::json j = nlohmann::json::parse(g.out);  // stdout is one JSON document
  const int n = j["cc_points"].get<int>();
  EXPECT_GT(n, 0);
  EXPECT_EQ(j["vertex_test"]["free_initial"].get<int>(), n);
  EXPECT_EQ(j["vertex_test"]["non_machinable"].get<int>(), 0);
  for (const char* k : {"inclined", "reversed"}) EXPECT_EQ(j["vertex_test"][k].get<int>(), 0) << k;
  EXPECT_DOUBLE_EQ(j["machinable_pct"].get<double>(), 100.0);
  EXPECT_DOUBLE_EQ(j["non_machinable_pct"].get<double>(), 0.0);
  EXPECT_EQ(j["exact"]["gouging_postures"].get<int>(), 0);
  EXPECT_LE(j["exact"]["max_depth"].get<double>(), 1e-9);
  EXPECT_EQ(j["missed_by_vertex_test"].get<int>(), 0);
  EXPECT_EQ(j["gouge_map"]["over_cut"]["cells"].get<int>(), 0);

  std::istringstream csv(slurp(path("p.csv")));
  std::string line;
  std::getline(csv, line);
  for (const char* col : {"cc_x", "normal_z", "feed_x", "tip_x", "axis_z", "inclination_deg",
                          "reversed", "vertex_test", "exact_depth_mm"})
    EXPECT_NE(line.find(col), std::string::npos) << col;
  int rows = 0;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, n);
  for (const char* f : {"report.json", "gouge_map.png", "gouge_depth.exr"})
    EXPECT_TRUE(fs::exists(dir_ / "out" / f)) << f;
}

TEST_F(GougeCli, AsciiSurfaceGivesTheSameAnswer) {
  ASSERT_EQ(run("surface --shape wave --size 30 30 --facets 800 -o " + path("b.stl")).status, 0);
  ASSERT_EQ(
      run("surface --shape wave --size 30 30 --facets 800 --ascii -o " + path("a.stl")).status, 0);
  const std::string opts = " --radius 2 --length 6 --no-map --json";
  const CliResult b = run("gouge " + path("b.stl") + opts),
                  a = run("gouge " + path("a.stl") + opts);
  ASSERT_EQ(b.status, 0) << b.err;
  ASSERT_EQ(a.status, 0) << a.err;
  auto jb = nlohmann::json::parse(b.out), ja = nlohmann::json::parse(a.out);
  EXPECT_EQ(ja["surface"]["format"], "ascii");
  EXPECT_EQ(jb["surface"]["format"], "binary");
  EXPECT_EQ(ja["vertex_test"], jb["vertex_test"]);
  EXPECT_EQ(ja["cc_points"], jb["cc_points"]);
}

TEST_F(GougeCli, BadInputAndUsage) {
  std::ofstream(path("junk.stl")) << "this is not a mesh";
  CliResult r = run("gouge " + path("junk.stl") + " --radius 3 --length 10");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("junk.stl"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());

  ASSERT_EQ(run("surface --shape dome --size 20 20 --facets 200 -o " + path("d.stl")).status, 0);
  r = run("gouge " + path("d.stl") + " --radius -3 --length 10");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("--radius"), std::string::npos) << r.err;
  r = run("gouge " + path("d.stl") + " --radius 3 --length 10 --inclination-axis sideways");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("--inclination-axis"), std::string::npos) << r.err;
  EXPECT_EQ(run("gouge " + path("d.stl") + " --length 10").status, 2);  // --radius missing
  // Turning moves are swept exactly now: the old tolerance is an unknown option.
  EXPECT_EQ(run("gouge " + path("d.stl") + " --radius 3 --length 10 --axis-tolerance 1e-3").status,
            2);
  EXPECT_EQ(run("surface --shape cube -o " + path("c.stl")).status, 1);
  EXPECT_FALSE(fs::exists(path("c.stl")));
  EXPECT_EQ(run("gouge " + path("missing.stl") + " --radius 3 --length 10").status, 1);
}

}  // namespace
