// `scallop interval` and `scallop validate`, run as a user would: the JSON document,
// exit statuses and messages naming the option, and the validation files. Expected
// numbers are computed here (closed forms, analysis/ functions), never written down.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/path_interval.h"
#include "analysis/simulated_interval.h"
#include "base/constants.h"
#include "tests/support/cli_harness.h"

namespace fs = std::filesystem;
using nlohmann::json;

namespace scallop {
namespace {

constexpr double kThreeDecimals = 0.0005 + 1e-12;  // half a unit of the printed digit

using scallop::test::CliRun;
using scallop::test::slurp;

class IntervalCli : public scallop::test::CliFixture {
 protected:
  json runJson(const std::string& args) {
    const CliRun r = run("interval " + args + " --json");
    EXPECT_EQ(r.status, 0) << r.err;
    return json::parse(r.out);  // stdout is exactly one JSON document
  }

  void expectRejected(const std::string& args, const std::string& needle, int status) {
    const CliRun r = run("interval " + args);
    EXPECT_EQ(r.status, status) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos)
        << args << ": message does not name " << needle << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
};

const json& procedure(const json& doc, const std::string& name) {
  for (const json& p : doc["procedures"])
    if (p["name"] == name) return p;
  static const json none;
  ADD_FAILURE() << "no procedure " << name;
  return none;
}

TEST_F(IntervalCli, BullWithLeadDocument) {
  const json doc = runJson("--tool bull --radius 3 --corner-radius 1 --lead 5 --scallop 0.05");
  EXPECT_EQ(doc["tool"], json::parse(R"({"type": "bull", "radius": 3.0, "corner_radius": 1.0})"));
  EXPECT_EQ(doc["lead_deg"], 5.0);
  EXPECT_EQ(doc["tilt_deg"], 0.0);
  EXPECT_EQ(doc["scallop"], 0.05);
  const double exact = halfIntervalComputational(3, 1, 5, 0.05).value;
  EXPECT_NEAR(doc["simulated_half_interval"].get<double>(), exact, 1e-6);

  const std::vector<std::string> names = {"computational", "sekine", "redonnet",        "bedi",
                                          "ball",          "exact",  "effective_radius"};
  ASSERT_EQ(doc["procedures"].size(), names.size());
  SimulatedPass pass(Cutter::make(CutterType::Bull, 3, 1), 5, 0);
  for (size_t i = 0; i < names.size(); ++i) {
    const json& p = doc["procedures"][i];
    EXPECT_EQ(p["name"], names[i]);
    for (const char* key : {"half_interval", "simulated_scallop", "applicable", "reason"})
      EXPECT_TRUE(p.contains(key)) << key;
    if (names[i] == "ball") {
      EXPECT_FALSE(p["applicable"].get<bool>());
      EXPECT_FALSE(p["reason"].get<std::string>().empty());
      EXPECT_TRUE(p["half_interval"].is_null());
      continue;
    }
    ASSERT_TRUE(p["applicable"].get<bool>()) << p["reason"];
    EXPECT_EQ(p["reason"], "");
    const double l2 = p["half_interval"].get<double>();
    EXPECT_NEAR(p["simulated_scallop"].get<double>(), pass.cusp(2 * l2).heightMm, 1e-9);
  }
  EXPECT_NEAR(procedure(doc, "computational")["simulated_scallop"].get<double>(), 0.05, 1e-6);
  EXPECT_NEAR(procedure(doc, "exact")["half_interval"].get<double>(), exact, 1e-9);
  EXPECT_NEAR(procedure(doc, "effective_radius")["half_interval"].get<double>(),
              procedure(doc, "redonnet")["half_interval"].get<double>(), 1e-12);
  EXPECT_NEAR(procedure(doc, "sekine")["half_interval"].get<double>(),
              halfIntervalSekine(3, 1, 5, 0.05).value, 1e-12);
}

TEST_F(IntervalCli, BallInAnyPostureIsSeed001Eq1) {
  const json doc = runJson("--tool ball --radius 3 --lead 10 --tilt -5 --scallop 0.05");
  const double want = std::sqrt(2 * 3 * 0.05 - 0.05 * 0.05);
  EXPECT_NEAR(doc["simulated_half_interval"].get<double>(), want, 1e-6);
  EXPECT_NEAR(doc["simulated_half_interval_plus"].get<double>(), want, 1e-6);
  const json& ball = procedure(doc, "ball");
  ASSERT_TRUE(ball["applicable"].get<bool>());
  EXPECT_NEAR(ball["simulated_scallop"].get<double>(), 0.05, 1e-6);
  EXPECT_FALSE(procedure(doc, "sekine")["applicable"].get<bool>());
}

TEST_F(IntervalCli, InclinedFlatEndMillIsTheEllipse) {
  const json doc = runJson("--tool flat --radius 3 --lead 10 --scallop 0.05");
  const double s = 3 * std::sin(degToRad(10));
  EXPECT_NEAR(doc["simulated_half_interval"].get<double>(),
              3 * std::sqrt(1 - std::pow((s - 0.05) / s, 2)), 1e-6);
  for (const json& p : doc["procedures"]) {
    if (p["name"] == "exact") continue;
    EXPECT_FALSE(p["applicable"].get<bool>()) << p["name"];
    EXPECT_NE(p["reason"].get<std::string>().find("flat"), std::string::npos) << p["reason"];
  }
  // The exact procedure covers it, and its L/2 leaves h in the simulation.
  const json& exact = procedure(doc, "exact");
  ASSERT_TRUE(exact["applicable"].get<bool>());
  EXPECT_NEAR(exact["half_interval"].get<double>(), doc["simulated_half_interval"].get<double>(),
              1e-9);
  EXPECT_NEAR(exact["simulated_scallop"].get<double>(), 0.05, 1e-9);
}

TEST_F(IntervalCli, TiltReportsBothSidesAndLeavesTheBullProceduresOut) {
  const json doc =
      runJson("--tool bull --radius 3 --corner-radius 1 --lead 5 --tilt 7 --scallop 0.05");
  const double plus = doc["simulated_half_interval_plus"].get<double>();
  const double minus = doc["simulated_half_interval_minus"].get<double>();
  EXPECT_NEAR(doc["simulated_half_interval"].get<double>(), 0.5 * (plus + minus), 1e-12);
  SimulatedPass pass(Cutter::make(CutterType::Bull, 3, 1), 5, 7);
  EXPECT_NEAR(pass.cusp(plus + minus).heightMm, 0.05, 1e-9);
  for (const char* name : {"computational", "sekine", "redonnet", "bedi"}) {
    EXPECT_FALSE(procedure(doc, name)["applicable"].get<bool>()) << name;
    EXPECT_NE(procedure(doc, name)["reason"].get<std::string>().find("tilt"), std::string::npos);
  }
  // With the tilt, the exact procedure's step-over is the simulated one.
  const json& exact = procedure(doc, "exact");
  ASSERT_TRUE(exact["applicable"].get<bool>());
  EXPECT_NEAR(exact["half_interval"].get<double>(), 0.5 * (plus + minus), 1e-9);
  EXPECT_NEAR(exact["simulated_scallop"].get<double>(), 0.05, 1e-9);
  EXPECT_TRUE(procedure(doc, "effective_radius")["applicable"].get<bool>());
}

TEST_F(IntervalCli, TableForPeople) {
  const CliRun r = run("interval --tool bull --radius 6 --corner-radius 2 --lead 10 --scallop 0.1");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* word :
       {"simulated exact L/2", "computational", "sekine", "redonnet", "bedi", "not applicable"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word;
  const CliRun help = run("interval --help");
  EXPECT_EQ(help.status, 0);
  for (const char* word : {"--tool", "--radius", "--corner-radius", "--lead", "--tilt", "--scallop",
                           "--json", "--threads", "mm", "deg"})
    EXPECT_NE(help.out.find(word), std::string::npos) << word;
}

// --feed-per-tooth adds the feed marks' closed form (docs/teeth.md), computed here from
// the circle and the threshold's defining equality.
TEST_F(IntervalCli, FeedMarksBesideTheInterval) {
  const json ball = runJson("--tool ball --radius 3 --lead 15 --scallop 0.01 --feed-per-tooth 0.1");
  const json& f = ball.at("feed_marks");
  EXPECT_EQ(f["applicable"], true);
  EXPECT_EQ(f["profile_radius"], 3.0);
  EXPECT_EQ(f["spacing"], 0.1);
  EXPECT_NEAR(f["height"].get<double>(), 3 - std::sqrt(9 - 0.0025), 1e-15);
  EXPECT_NEAR(f["height_parabola"].get<double>(), 0.01 / 24, 1e-18);
  const double star = f["runout_threshold"].get<double>(), l = degToRad(15);
  EXPECT_NEAR(2 * star * std::sin(l),
              (0.01 - 4 * star * star * std::cos(l) * std::cos(l)) / (2 * 3), 1e-15);
  // A bull's marks are its corner's; above the threshold one tooth cuts, 2 fz apart.
  const json bull = runJson(
      "--tool bull --radius 5 --corner-radius 1 --lead 10 --scallop 0.01 --feed-per-tooth 0.1 "
      "--runout 0.02");
  EXPECT_EQ(bull["feed_marks"]["profile_radius"], 1.0);
  EXPECT_EQ(bull["feed_marks"]["regime"], "one tooth cuts");
  EXPECT_EQ(bull["feed_marks"]["spacing"], 0.2);
  EXPECT_NEAR(bull["feed_marks"]["height"].get<double>(), 1 - std::sqrt(1 - 0.01), 1e-15);
  // Where the formula does not apply it says why; without fz there is no section.
  for (const char* args : {"--tool flat --radius 3 --lead 15", "--tool ball --radius 3"}) {
    const json no = runJson(std::string(args) + " --scallop 0.01 --feed-per-tooth 0.1");
    EXPECT_EQ(no["feed_marks"]["applicable"], false) << args;
    EXPECT_FALSE(no["feed_marks"]["reason"].get<std::string>().empty()) << args;
    EXPECT_TRUE(no["feed_marks"]["height"].is_null()) << args;
  }
  EXPECT_FALSE(runJson("--tool ball --radius 3 --scallop 0.01").contains("feed_marks"));
  const CliRun table =
      run("interval --tool ball --radius 3 --lead 15 --scallop 0.01 "
          "--feed-per-tooth 0.1");
  char expected[64];
  std::snprintf(expected, sizeof expected, "h_f = %.6f um", f["height"].get<double>() * 1e3);
  EXPECT_NE(table.out.find(expected), std::string::npos) << expected << "\n" << table.out;
  std::snprintf(expected, sizeof expected, "rho* = %.6f um", star * 1e3);
  EXPECT_NE(table.out.find(expected), std::string::npos) << expected << "\n" << table.out;
}

TEST_F(IntervalCli, BadValuesExitOneNamingTheOption) {
  const std::string bull = "--tool bull --radius 3 --corner-radius 1";
  expectRejected("--tool bull --radius 0 --corner-radius 1 --scallop 0.05", "--radius", 1);
  expectRejected("--tool ball --radius -3 --scallop 0.05", "--radius", 1);
  expectRejected("--tool ball --radius nan --scallop 0.05", "--radius", 1);
  expectRejected("--tool bull --radius 3 --corner-radius 3 --scallop 0.05", "--corner-radius", 1);
  expectRejected("--tool bull --radius 3 --corner-radius 4 --scallop 0.05", "--corner-radius", 1);
  expectRejected("--tool bull --radius 3 --corner-radius 0 --scallop 0.05", "--corner-radius", 1);
  expectRejected("--tool bull --radius 3 --corner-radius -1 --scallop 0.05", "--corner-radius", 1);
  expectRejected("--tool ball --radius 3 --corner-radius 1 --scallop 0.05", "--corner-radius", 1);
  expectRejected(bull + " --lead 90 --scallop 0.05", "--lead", 1);
  expectRejected(bull + " --lead -95 --scallop 0.05", "--lead", 1);
  expectRejected(bull + " --tilt 90 --scallop 0.05", "--tilt", 1);
  expectRejected(bull + " --lead 5 --scallop 0", "--scallop", 1);
  expectRejected(bull + " --lead 5 --scallop -0.05", "--scallop", 1);
  expectRejected(bull + " --lead 5 --scallop 5", "--scallop", 1);  // beyond the cutter
  expectRejected("--tool flat --radius 3 --scallop 0.01", "beyond the cutter", 1);
  expectRejected("--tool drill --radius 3 --scallop 0.05", "--tool", 1);
}

TEST_F(IntervalCli, UsageErrorsExitTwo) {
  expectRejected("--tool ball --radius 3", "--scallop", 2);
  expectRejected("--tool ball --radius abc --scallop 0.05", "--radius", 2);
  expectRejected("--tool ball --radius 3 --scallop 0.05 --colour red", "--colour", 2);
  expectRejected("--tool bull --radius 3 --scallop 0.05", "--corner-radius", 2);
}

// ---- validate ---------------------------------------------------------------------------

using CsvRow = std::map<std::string, std::string>;

std::vector<CsvRow> readCsv(const fs::path& p, std::vector<std::string>* header) {
  std::istringstream in(slurp(p));
  std::string line;
  auto split = [](const std::string& l) {
    std::vector<std::string> cells;
    std::stringstream s(l);
    std::string c;
    while (std::getline(s, c, ',')) cells.push_back(c);
    if (!l.empty() && l.back() == ',') cells.push_back("");
    return cells;
  };
  std::getline(in, line);
  *header = split(line);
  std::vector<CsvRow> rows;
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = split(line);
    EXPECT_EQ(cells.size(), header->size()) << line;
    CsvRow row;
    for (size_t c = 0; c < cells.size() && c < header->size(); ++c) row[(*header)[c]] = cells[c];
    rows.push_back(row);
  }
  return rows;
}

double num(const CsvRow& r, const std::string& column) {
  EXPECT_TRUE(r.count(column)) << column;
  return r.count(column) ? std::stod(r.at(column)) : NAN;
}

TEST_F(IntervalCli, ValidateWritesTablesAndPictures) {
  const fs::path out = dir_ / "validation";
  fs::create_directories(out);
  std::ofstream(out / "keep.txt") << "mine";
  const CliRun r = run("validate -o " + out.string() + " --json --threads 2");
  ASSERT_EQ(r.status, 0) << r.err;
  const json doc = json::parse(r.out);
  EXPECT_EQ(slurp(out / "keep.txt"), "mine");
  EXPECT_EQ(doc["pictures"].size(), 24u);
  for (const json& p : doc["pictures"]) {
    const std::string svg = slurp(out / p.get<std::string>());
    EXPECT_EQ(svg.rfind("<svg", 0), 0u) << p;
    EXPECT_NE(svg.find("simulated exact L/2"), std::string::npos) << p;
  }
  for (const auto& entry : fs::recursive_directory_iterator(out))
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();

  std::vector<std::string> header;
  // Seed 000 Tables 2 and 3: the 2D procedures' formulas reproduce the printed L/2;
  // the printed computational values lie up to 0.013 mm below the exact geometric L/2,
  // which our computational procedure and the simulation both give.
  for (const char* file : {"seed000_table2.csv", "seed000_table3.csv"}) {
    const std::vector<CsvRow> rows = readCsv(out / file, &header);
    ASSERT_EQ(rows.size(), 16u) << file;
    for (const char* col : {"condition", "rho_deg", "h_mm", "procedure", "printed_half_interval_mm",
                            "computed_half_interval_mm", "simulated_scallop_at_printed_mm",
                            "scallop_error_um", "simulated_exact_half_interval_mm"})
      EXPECT_NE(std::find(header.begin(), header.end(), col), header.end()) << col;
    for (const CsvRow& row : rows) {
      const double printed = num(row, "printed_half_interval_mm");
      const double computed = num(row, "computed_half_interval_mm");
      const double h = num(row, "h_mm");
      EXPECT_NEAR(num(row, "scallop_error_um"),
                  1000 * (num(row, "simulated_scallop_at_printed_mm") - h), 1e-6);
      if (row.at("procedure") == "computational") {
        EXPECT_GE(computed + kThreeDecimals, printed) << file;
        EXPECT_LT(computed - printed, 0.014) << file;
        EXPECT_NEAR(num(row, "simulated_exact_half_interval_mm"), computed, 1e-6) << file;
        EXPECT_NEAR(num(row, "simulated_scallop_at_computed_mm"), h, 1e-6) << file;
      } else {
        EXPECT_NEAR(computed, printed, kThreeDecimals) << file << " " << row.at("procedure");
      }
    }
  }
  // Tables 4 and 5: Eqs. (12)-(13) reproduce the printed h (all but Table 4 condition 3
  // sekine, see path_interval_test.cpp); our computational inverse gives the simulated h.
  for (const char* file : {"seed000_table4.csv", "seed000_table5.csv"}) {
    const std::vector<CsvRow> rows = readCsv(out / file, &header);
    ASSERT_EQ(rows.size(), 16u) << file;
    for (const CsvRow& row : rows) {
      const std::string p = row.at("procedure");
      if (p == "computational") {
        EXPECT_NEAR(num(row, "computed_h_mm"), num(row, "simulated_h_mm"), 1e-6) << file;
      } else if (!(std::string(file) == "seed000_table4.csv" && row.at("condition") == "3" &&
                   p == "sekine")) {
        EXPECT_NEAR(num(row, "computed_h_mm"), num(row, "printed_h_mm"), kThreeDecimals)
            << file << " " << p << " " << row.at("condition");
      }
    }
  }
  // Seed 001 Table 1: Eq. (1) reproduces every printed L/2 and is the simulated truth.
  const std::vector<CsvRow> ball = readCsv(out / "seed001_table1.csv", &header);
  ASSERT_EQ(ball.size(), 8u);
  for (const CsvRow& row : ball) {
    EXPECT_NEAR(num(row, "computed_half_interval_mm"), num(row, "printed_half_interval_mm"),
                kThreeDecimals);
    EXPECT_NEAR(num(row, "simulated_exact_half_interval_mm"), num(row, "computed_half_interval_mm"),
                1e-6);
  }
  EXPECT_EQ(readCsv(out / "seed001_table2.csv", &header).size(), 8u);
  for (const char* file : {"seed001_table3.csv", "seed001_table4.csv"}) {
    const std::vector<CsvRow> rows = readCsv(out / file, &header);
    ASSERT_EQ(rows.size(), 32u) << file;
    for (const CsvRow& row : rows)
      EXPECT_NEAR(num(row, "computed"), num(row, "printed"), 0.005 + 1e-9) << file;
  }
  EXPECT_TRUE(doc["tables"].contains("seed000_table2"));
}

TEST_F(IntervalCli, ValidateIntoAFileIsBadInput) {
  std::ofstream(dir_ / "blocker") << "x";
  const CliRun r = run("validate -o " + (dir_ / "blocker" / "sub").string());
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("blocker"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace scallop
