// `scallop stats` and `scallop export` as a user runs them: the numbers read back from
// heights.gsf / heights.exr equal the in-memory map's report.json block to float32
// precision; bad files and arguments exit 1 or 2 with a message and no stdout.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/cli_harness.h"

namespace scallop::test {
namespace {

using nlohmann::json;

constexpr const char* kJob = R"({
  "tool": {"type": "bull", "radius": 3.0, "corner_radius": 1.0},
  "stock": {"min": [0, 0, -5], "max": [6, 5, 0]},
  "grid": {"spacing": 0.04},
  "path": {"raster": {"direction": "x", "step_over": 2.0, "depth": 0.5,
                      "lead_deg": 5, "tilt_deg": 0, "zigzag": false}}
})";

class StatsCli : public CliFixture {
 protected:
  // Simulates kJob into DIR/out once per test and returns report.json.
  json simulate() {
    write("job.json", kJob);
    const CliRun r = run("simulate " + path("job.json") + " -o " + path("out") + " --json");
    EXPECT_EQ(r.status, 0) << r.err;
    return json::parse(r.out);
  }
  json stats(const std::string& args) {
    const CliRun r = run("stats " + args + " --json");
    EXPECT_EQ(r.status, 0) << r.err;
    return json::parse(r.out);
  }
  // Runs a command that must fail with `status`, print nothing on stdout, and say
  // `needle` on stderr.
  void expectFailure(const std::string& args, int status, const std::string& needle) {
    const CliRun r = run(args);
    EXPECT_EQ(r.status, status) << args << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << args << "\n" << r.out;
    EXPECT_NE(r.err.find(needle), std::string::npos) << args << "\n" << r.err;
  }
};

// Heights in the files are float32: each differs from the double by at most half an
// ulp at |z| <= 0.5 mm, so every length parameter moves by at most about that.
void expectSameWithinFloat(const json& file, const json& memory) {
  const double zTol = 2 * FLT_EPSILON * 0.5;  // mm
  const double sq = memory["Sq_mm"].get<double>();
  for (const char* key : {"Sa_mm", "Sq_mm", "Sp_mm", "Sv_mm", "Sz_mm"})
    EXPECT_NEAR(file[key].get<double>(), memory[key].get<double>(), 2 * zTol) << key;
  // Ssk and Sku are ratios of moments of residuals of size ~Sq: relative change ~zTol/Sq.
  for (const char* key : {"Ssk", "Sku"})
    EXPECT_NEAR(file[key].get<double>(), memory[key].get<double>(),
                8 * zTol / sq * std::abs(memory[key].get<double>()))
        << key;
  EXPECT_EQ(file["cells"], memory["cells"]);
  EXPECT_EQ(file["levelling"], memory["levelling"]);
}

TEST_F(StatsCli, FilesGiveTheInMemoryReportNumbers) {
  const json report = simulate();
  ASSERT_TRUE(report.contains("surface_stats"));
  const json& memory = report["surface_stats"];
  EXPECT_EQ(memory["levelling"], "least-squares plane");
  EXPECT_EQ(memory["cells"], 150 * 125);
  EXPECT_GT(memory["Sq_mm"].get<double>(), 1e-3);  // a real scallop surface, not zeros
  for (const char* file : {"heights.gsf", "heights.exr"}) {
    SCOPED_TRACE(file);
    const json s = stats(path("out") + "/" + file);
    expectSameWithinFloat(s["surface_stats"], memory);
    EXPECT_EQ(s["grid"]["nx"], 150);
    EXPECT_EQ(s["grid"]["ny"], 125);
    EXPECT_NEAR(s["grid"]["spacing"].get<double>(), 0.04, 1e-15);
  }
}

TEST_F(StatsCli, ThreadCountDoesNotChangeABit) {
  simulate();
  const CliRun one = run("stats " + path("out/heights.gsf") + " --json --threads 1");
  const CliRun three = run("stats " + path("out/heights.gsf") + " --json --threads 3");
  ASSERT_EQ(one.status, 0) << one.err;
  EXPECT_EQ(one.out, three.out);
}

TEST_F(StatsCli, RegionLevelAndProfile) {
  simulate();
  const json s = stats(path("out/heights.gsf") +
                       " --region 1 1 4 4 --level none --profile 0.5 0.02 0.5 4.98 --cutoff 0.8");
  EXPECT_EQ(s["surface_stats"]["levelling"], "none");
  // Centres 1.02 .. 3.98 mm: 75 x 75 cells, cell edges from 1 to 4 mm.
  EXPECT_EQ(s["surface_stats"]["cells"], 75 * 75);
  EXPECT_NEAR(s["region_mm"][0].get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(s["region_mm"][3].get<double>(), 4.0, 1e-12);
  const json& p = s["profile"];
  EXPECT_EQ(p["samples"], 125);
  EXPECT_EQ(p["sampling_lengths"], 4);  // 4.96 mm: 2 x 0.8 run-in/out, 4 x 0.8 evaluated
  EXPECT_GT(p["Rz_mm"].get<double>(), 0);
  EXPECT_GE(p["Rt_mm"].get<double>(), p["Rz_mm"].get<double>());
  EXPECT_GE(p["Rq_mm"].get<double>(), p["Ra_mm"].get<double>());
  EXPECT_NE(p["filter"].get<std::string>().find("lc 0.8 mm"), std::string::npos);
  EXPECT_NEAR(p["sampling_length_mm"].get<double>(), 0.8, 1e-12);
  // Unfiltered: one sampling length, the whole line; Rz = Rt.
  const json u = stats(path("out/heights.gsf") + " --profile 0.5 0.02 0.5 4.98 --unfiltered");
  EXPECT_NE(u["profile"]["filter"].get<std::string>().find("unfiltered"), std::string::npos);
  EXPECT_EQ(u["profile"]["sampling_lengths"], 1);
  EXPECT_NEAR(u["profile"]["evaluation_length_mm"].get<double>(), 4.96, 1e-9);
  EXPECT_EQ(u["profile"]["Rz_mm"], u["profile"]["Rt_mm"]);
  // Human output names the convention, the filter and the lengths.
  const CliRun human = run("stats " + path("out/heights.gsf") +
                           " --profile 0.5 0.02 0.5 4.98 --cutoff 0.8 --lambda-s 0.08");
  EXPECT_EQ(human.status, 0);
  EXPECT_NE(human.out.find("plain kurtosis"), std::string::npos);
  EXPECT_NE(human.out.find("ls 0.08 mm"), std::string::npos) << human.out;
  EXPECT_NE(human.out.find("sampling length(s) of 0.8 mm"), std::string::npos) << human.out;
  EXPECT_NE(human.out.find("Rsm"), std::string::npos);
  // A short-wave cutoff under two samples (the grid is 0.04 mm) is refused naming it.
  expectFailure(
      "stats " + path("out/heights.gsf") + " --profile 0.5 0.02 0.5 4.98 --lambda-s 0.05 --json", 1,
      "--lambda-s");
}

TEST_F(StatsCli, FilesThatAreNotHeightMapsExit1) {
  write("notes.txt", "hello\n");
  expectFailure("stats " + path("notes.txt") + " --json", 1, "notes.txt");
  expectFailure("stats " + path("missing.gsf") + " --json", 1, "missing.gsf");
  write("text.exr", "not an image at all\n");
  expectFailure("stats " + path("text.exr") + " --json", 1, "text.exr");
  write("text.gsf", "not a gsf\n");
  expectFailure("stats " + path("text.gsf") + " --json", 1, "Gwyddion Simple Field");
}

TEST_F(StatsCli, TruncatedAndInconsistentFilesExit1) {
  simulate();
  const std::string gsf = slurp(path("out/heights.gsf"));
  const std::string exr = slurp(path("out/heights.exr"));
  write("cut.gsf", gsf.substr(0, gsf.size() - 7));
  expectFailure("stats " + path("cut.gsf") + " --json", 1, "float32 values need");
  write("cut.exr", exr.substr(0, exr.size() / 2));
  expectFailure("stats " + path("cut.exr") + " --json", 1, "cut.exr");
  write("header-only.exr", exr.substr(0, 200));
  expectFailure("stats " + path("header-only.exr") + " --json", 1, "header-only.exr");
  auto edited = [&](const std::string& from, const std::string& to) {
    std::string s = gsf;
    const size_t at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return s.replace(at, from.size(), to);
  };
  // The same header length keeps the data offset: only the fields are inconsistent.
  write("xres.gsf", edited("XRes = 150", "XRes = 151"));
  expectFailure("stats " + path("xres.gsf") + " --json", 1, "xres.gsf");
  write("zero.gsf", edited("XRes = 150", "XRes = 000"));
  expectFailure("stats " + path("zero.gsf") + " --json", 1, "XRes and YRes");
  write("text.gsf", edited("XRes = 150", "XRes = abc"));
  expectFailure("stats " + path("text.gsf") + " --json", 1, "XRes");
  write("square.gsf", edited("YReal = 0.005", "YReal = 0.006"));
  expectFailure("stats " + path("square.gsf") + " --json", 1, "square");
  write("unit.gsf", edited("ZUnits = m", "ZUnits = s"));
  expectFailure("stats " + path("unit.gsf") + " --json", 1, "ZUnits");
  std::string inf = gsf;
  inf.replace(inf.size() - 4, 4, std::string("\x00\x00\x80\x7f", 4));  // a float +inf
  write("inf.gsf", inf);
  expectFailure("stats " + path("inf.gsf") + " --json", 1, "infinite");
  // NaN is a cell without material (a frame's line that misses the stock): left out.
  std::string nan = gsf;
  nan.replace(nan.size() - 4, 4, std::string("\x00\x00\xc0\x7f", 4));  // a float NaN
  write("nan.gsf", nan);
  EXPECT_EQ(stats(path("nan.gsf"))["surface_stats"]["cells"], 150 * 125 - 1);
}

TEST_F(StatsCli, BadArgumentsExit1Or2) {
  simulate();
  const std::string gsf = path("out/heights.gsf");
  expectFailure("stats " + gsf + " --region 4 1 1 4", 1, "--region");
  expectFailure("stats " + gsf + " --region 10 10 20 20", 1, "no cell centre");
  expectFailure("stats " + gsf + " --profile 0 0 9 0", 1, "--profile");
  expectFailure("stats " + gsf + " --profile 0.5 0.5 1 0.5", 1, "--cutoff");
  expectFailure("stats " + gsf + " --region 1 2 3", 2, "region");
  expectFailure("stats " + gsf + " --level cubic", 2, "level");
  expectFailure("export " + gsf + " --to out.doc", 2, "--to");
  expectFailure("export " + gsf + " --to p.csv", 2, "--profile");
}

TEST_F(StatsCli, ExportedFilesReadBackToTheSameStatistics) {
  simulate();
  const std::string gsf = path("out/heights.gsf");
  // EXR to EXR keeps the float32 millimetres: the same bits of every number.
  ASSERT_EQ(run("export " + path("out/heights.exr") + " --to " + path("copy.exr")).status, 0);
  EXPECT_EQ(stats(path("copy.exr"))["surface_stats"],
            stats(path("out/heights.exr"))["surface_stats"]);
  // GSF (float32 metres) to EXR (float32 mm) rounds once more: float precision.
  ASSERT_EQ(run("export " + gsf + " --to " + path("from-gsf.exr")).status, 0);
  expectSameWithinFloat(stats(path("from-gsf.exr"))["surface_stats"], stats(gsf)["surface_stats"]);
  // X3P (float64 metres) is read by stats too (the height-format table): the EXR's
  // float32 millimetres through m and back, within a rounding of each.
  ASSERT_EQ(run("export " + path("out/heights.exr") + " --to " + path("h.x3p")).status, 0);
  expectSameWithinFloat(stats(path("h.x3p"))["surface_stats"],
                        stats(path("out/heights.exr"))["surface_stats"]);
  const CliRun csv =
      run("export " + gsf + " --to " + path("p.csv") + " --profile 0.02 2.5 5.98 2.5 --cutoff 0.8");
  ASSERT_EQ(csv.status, 0) << csv.err;
  std::ifstream in(path("p.csv"));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "distance_mm,x_mm,y_mm,z_mm,roughness_mm");
  int lines = 0, withRoughness = 0;
  while (std::getline(in, line)) {
    ++lines;
    withRoughness += line.back() != ',';
  }
  EXPECT_EQ(lines, 150);
  EXPECT_EQ(withRoughness, 150 - 2 * 20);  // run-in and run-out of 0.8 mm = 20 samples each
}

}  // namespace
}  // namespace scallop::test
