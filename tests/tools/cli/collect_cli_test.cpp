// `scallop collect DIR...` (tools/cli/collect_command.h): report.json files of several
// runs into one CSV, inputs flattened then measurements; bad folders or reports exit 1
// naming them and write no table.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/cli_harness.h"

namespace fs = std::filesystem;

namespace {

using scallop::test::CliRun;
using scallop::test::slurp;

std::vector<std::vector<std::string>> parseCsv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::string cell;
    bool quoted = false;
    for (size_t i = 0; i < line.size(); ++i) {
      const char c = line[i];
      if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cell += '"';
        ++i;
      } else if (c == '"') {
        quoted = !quoted;
      } else if (c == ',' && !quoted) {
        cells.push_back(cell);
        cell.clear();
      } else {
        cell += c;
      }
    }
    cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

size_t column(const std::vector<std::string>& header, const std::string& name) {
  for (size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return i;
  ADD_FAILURE() << "no column " << name;
  return 0;
}

class Collect : public scallop::test::CliFixture {
 protected:
  // A small raster at step-over `step`; its report.json in DIR.
  void simulate(const std::string& dir, double step) {
    const std::string job = write(dir + ".json", R"({
      "tool":  {"type": "ball", "radius": 1.0},
      "stock": {"min": [0, 0, -1], "max": [1, 1, 0]},
      "grid":  {"spacing": 0.02},
      "path":  {"raster": {"direction": "x", "step_over": )" +
                                                     std::to_string(step) + R"(, "depth": 0.2}}
    })")
                                .string();
    const CliRun r = run("simulate " + job + " -o " + path(dir));
    ASSERT_EQ(r.status, 0) << r.err;
  }
  nlohmann::json report(const std::string& dir) {
    return nlohmann::json::parse(slurp(path(dir) + "/report.json"));
  }
};

TEST_F(Collect, OneRowPerRunWithInputsAndMeasurements) {
  simulate("s2", 0.2);
  simulate("s4", 0.4);
  const CliRun r = run("collect " + path("s2") + " " + path("s4") + " -o " + path("t.csv"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "");
  const auto rows = parseCsv(slurp(path("t.csv")));
  ASSERT_EQ(rows.size(), 3u);
  const auto& h = rows[0];
  EXPECT_EQ(h[0], "run");
  EXPECT_EQ(h[1], "job");
  for (size_t k = 1; k < 3; ++k) {
    const nlohmann::json rep = report(k == 1 ? "s2" : "s4");
    EXPECT_EQ(rows[k].size(), h.size());
    EXPECT_EQ(rows[k][0], path(k == 1 ? "s2" : "s4"));
    EXPECT_EQ(rows[k][column(h, "tool.type")], "ball");
    EXPECT_EQ(std::stod(rows[k][column(h, "tool.radius")]), 1.0);
    EXPECT_EQ(std::stod(rows[k][column(h, "stock.min[2]")]), -1.0);
    EXPECT_EQ(std::stod(rows[k][column(h, "path.raster.step_over")]),
              rep["inputs"]["path"]["raster"]["step_over"].get<double>());
    // Measurements round-trip exactly (shortest decimal of the double).
    EXPECT_EQ(std::stod(rows[k][column(h, "measurements.max_scallop_height")]),
              rep["measurements"]["max_scallop_height"].get<double>());
    EXPECT_EQ(std::stod(rows[k][column(h, "surface_stats.Sq_mm")]),
              rep["surface_stats"]["Sq_mm"].get<double>());
    EXPECT_EQ(rows[k][column(h, "grid.nx")], "50");
  }
  // A wider step-over leaves a taller scallop.
  EXPECT_LT(std::stod(rows[1][column(h, "measurements.max_scallop_height")]),
            std::stod(rows[2][column(h, "measurements.max_scallop_height")]));
}

TEST_F(Collect, ColumnsChooseTheMeasurements) {
  simulate("s2", 0.2);
  const CliRun r =
      run("collect " + path("s2") + "/report.json --columns timings_s,measurements.floor_z");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = parseCsv(r.out);
  ASSERT_EQ(rows.size(), 2u);
  const auto& h = rows[0];
  EXPECT_EQ(h[h.size() - 1], "measurements.floor_z");
  for (const char* c : {"timings_s.scene_build", "timings_s.cast", "timings_s.total"}) column(h, c);
  for (const std::string& c : h) EXPECT_NE(c, "measurements.min_height");
  // --columns takes one argument: folders after it stay folders.
  const CliRun before = run("collect --columns grid.nx " + path("s2") + " " + path("s2"));
  ASSERT_EQ(before.status, 0) << before.err;
  const auto twice = parseCsv(before.out);
  ASSERT_EQ(twice.size(), 3u);
  EXPECT_EQ(twice[0].back(), "grid.nx");
  EXPECT_EQ(twice[2][0], path("s2"));
  const CliRun bad = run("collect " + path("s2") + " --columns measurements.nothing");
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.err.find("measurements.nothing"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("--columns"), std::string::npos) << bad.err;
}

TEST_F(Collect, BadFoldersAndReportsAreNamedAndWriteNoTable) {
  simulate("good", 0.2);
  fs::create_directories(path("empty"));
  fs::create_directories(path("broken"));
  write("broken/report.json", "{\"inputs\": {\"tool\": ");
  fs::create_directories(path("other"));
  write("other/report.json", "[1, 2]");
  const std::string table = path("t.csv");
  for (const char* bad : {"empty", "broken", "other", "nowhere"}) {
    const CliRun r = run("collect " + path("good") + " " + path(bad) + " -o " + table);
    EXPECT_EQ(r.status, 1) << bad;
    EXPECT_NE(r.err.find(path(bad)), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_FALSE(fs::exists(table)) << bad;
  }
  EXPECT_NE(run("collect " + path("empty")).err.find("report.json"), std::string::npos);
  EXPECT_EQ(run("collect").status, 2);
  // An unwritable table is named too, and nothing is left.
  const CliRun r = run("collect " + path("good") + " -o " + path("nofolder/t.csv"));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("nofolder/t.csv"), std::string::npos) << r.err;
}

TEST_F(Collect, CellsWithCommasAreQuoted) {
  simulate("a,b", 0.2);
  const CliRun r = run("collect '" + path("a,b") + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = parseCsv(r.out);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1][0], path("a,b"));
  EXPECT_EQ(rows[1].size(), rows[0].size());
}

}  // namespace
