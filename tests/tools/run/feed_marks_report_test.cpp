// report.json "feed_marks" (tools/run/feed_mark_report.h) of teeth runs, as `simulate`
// writes it: the closed form of the feed marks met on the pass centre line, the same
// section from bands as from the whole map, the line sampled as `export --profile`
// samples it, and the teeth model's refusals and warnings around the run.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "analysis/feed_mark_formula.h"
#include "analysis/feed_marks.h"
#include "analysis/profile_metrology.h"
#include "analysis/triangle_mesh.h"
#include "tests/support/cli_harness.h"
#include "tools/io/job.h"
#include "tools/io/stl_io.h"
#include "tools/run/feed_mark_report.h"
#include "tools/run/job_loader.h"

namespace scallop {
namespace {

using nlohmann::json;
using scallop::test::CliRun;

// Ball R3, lead 15 deg, 2 flutes, fz 0.1 mm: three passes 0.02 mm apart, the middle one
// on y = 0, over 0.8 mm (8 marks) on a 2 um grid (8000 cells).
const std::string kJob = R"({
  "tool":  {"type": "ball", "radius": 3.0},
  "cutting": {"model": "teeth", "feed_per_tooth": 0.1},
  "stock": {"min": [0, -0.02, -2], "max": [0.8, 0.02, 0]},
  "grid":  {"spacing": 0.002},
  "path":  {"raster": {"direction": "x", "step_over": 0.02, "depth": 0.1, "lead_deg": 15}}
})";

class FeedMarksReport : public scallop::test::CliFixture {
 protected:
  json simulate(const std::string& job, const std::string& extra = "") {
    const CliRun r = run("simulate " + write("job.json", job).string() + " -o " + path("out") +
                         " --json" + extra);
    EXPECT_EQ(r.status, 0) << r.err;
    return r.status == 0 ? json::parse(r.out) : json();
  }
};

TEST_F(FeedMarksReport, TheCentreLineShowsTheClosedFormsMarks) {
  const json report = simulate(kJob);
  const json& f = report.at("feed_marks");
  const json& line = f.at("line");
  // The middle pass (move 3 of 5: pass, rapid, pass, rapid, pass), over the cell
  // centres' span along x.
  EXPECT_EQ(line["move"], 3);
  EXPECT_NEAR(line["from"][0].get<double>(), 0.001, 1e-15);  // the first cell centre
  EXPECT_EQ(line["from"][1], 0.0);
  EXPECT_NEAR(line["to"][0].get<double>(), 0.799, 1e-15);
  EXPECT_EQ(line["samples"], 400);
  // The prediction is the formula's for the job.
  const FeedMarkPrediction p = predictFeedMarks(Cutter::make(CutterType::Ball, 3), 15, 0, 0.1);
  const json& predicted = f.at("predicted");
  EXPECT_EQ(predicted["peak_to_valley_um"].get<double>(), p.heightMm * 1e3);
  EXPECT_EQ(predicted["spacing_mm"].get<double>(), 0.1);
  EXPECT_EQ(predicted["runout_threshold_mm"].get<double>(), p.runoutThresholdMm);
  // Measured: the highest samples lie up to half a step from the cusps, below them by at
  // most the arcs' slope there, (fz / 2) / R, times step / 2; the heights are exact to
  // 1e-9 mm.
  const double pv = f["peak_to_valley_um"].get<double>() * 1e-3;
  const double slope = 0.05 / std::sqrt(9 - 0.0025);
  EXPECT_LE(pv, p.heightMm + 2e-9);
  EXPECT_GE(pv, p.heightMm - slope * 0.001 - 2e-9);
  // Every bottom is the same arc, refined by a parabola (its bias ~1e-7 of a step).
  EXPECT_EQ(f["valleys"], 8);
  EXPECT_NEAR(f["mean_spacing_mm"].get<double>(), 0.1, 1e-6);

  // The envelope has no feed marks (and no section).
  std::string envelope = kJob;
  envelope.replace(envelope.find("\"teeth\""), 7, "\"envelope\"");
  EXPECT_FALSE(simulate(envelope).contains("feed_marks"));
}

// G-code feeds reach the teeth: fz = F / (S flutes) spaces the marks. The axis leans
// 15 deg along the feed (a table-table machine with TCP on, B -15: a vertical axis under
// teeth does not finish near its centre line yet, docs/teeth.md "Limits").
TEST_F(FeedMarksReport, GcodeFeedsPerToothSpaceTheMarks) {
  const std::string job = R"({"tool": {"type": "ball", "radius": 3},
      "cutting": {"model": "teeth"}, "machine": {"kinematics": "xyzbc-trt"},
      "stock": {"min": [0, -0.02, -2], "max": [0.8, 0.02, 0]}, "grid": {"spacing": 0.002},
      "path": {"file": "p.nc"}})";
  for (const double feed : {1200.0, 1500.0}) {
    write("p.nc",
          "G43.4\nS6000 M3\nG0 X-4 Y0 Z1 B-15 C0\nG1 Z-0.1 F" + std::to_string(feed) + "\nX5\n");
    const json f = simulate(job).at("feed_marks");
    const double fz = feed / (6000 * 2);
    EXPECT_EQ(f.at("line").at("move"), 2) << f;  // X-4 -> X5, after the plunge
    EXPECT_NEAR(f.at("mean_spacing_mm").get<double>(), fz, 1e-6) << feed;
    const double h = circularMarkHeight(3, fz), slope = 0.5 * fz / std::sqrt(9 - 0.25 * fz * fz);
    const double pv = f.at("peak_to_valley_um").get<double>() * 1e-3;
    EXPECT_LE(pv, h + 2e-9) << feed;
    EXPECT_GE(pv, h - slope * 0.001 - 2e-9) << feed;
  }
}

// Every straight pass of a path gets its own line and measurement: two passes 0.2 mm
// apart (far enough that neither cuts the other's centre line: the ball is 0.2^2 / 6 mm
// = 6.7 um higher there, above the 0.42 um marks), the second in reverse, and a third
// that misses the map, which is reported as such.
TEST_F(FeedMarksReport, EveryPassOfAPathIsMeasured) {
  const std::string job = R"({"tool": {"type": "ball", "radius": 3},
      "cutting": {"model": "teeth"}, "machine": {"kinematics": "xyzbc-trt"},
      "stock": {"min": [0, -0.01, -2], "max": [0.4, 0.21, 0]}, "grid": {"spacing": 0.002},
      "path": {"file": "p.nc"}})";
  write("p.nc",
        "G43.4\nS6000 M3\nG0 X-4 Y0 Z1 B-15 C0\nG1 Z-0.1 F1200\nX5\nG0 Z1\nY0.2\n"
        "G1 Z-0.1\nX-4\nG0 Z1\nY5\nG1 Z-0.1\nX5\n");
  const json f = simulate(job).at("feed_marks");
  const json& passes = f.at("passes");
  ASSERT_EQ(passes.size(), 3u) << f;
  EXPECT_EQ(f.at("pass_count"), 3);
  EXPECT_EQ(f.at("passes_crossing_the_map"), 2);
  const double fz = 1200.0 / (6000 * 2), h = circularMarkHeight(3, fz);
  const double slope = 0.5 * fz / std::sqrt(9 - 0.25 * fz * fz);
  for (int k = 0; k < 2; ++k) {
    const json& pass = passes[k];
    ASSERT_TRUE(pass.contains("line")) << pass;
    EXPECT_NEAR(pass["line"]["from"][1].get<double>(), 0.2 * k, 1e-12);
    EXPECT_NEAR(pass.at("mean_spacing_mm").get<double>(), fz, 1e-6) << pass;
    const double pv = pass.at("peak_to_valley_um").get<double>() * 1e-3;
    EXPECT_LE(pv, h + 2e-9) << pass;
    EXPECT_GE(pv, h - slope * 0.001 - 2e-9) << pass;
  }
  EXPECT_EQ(passes[0]["line"]["pass_moves"], json({2, 2}));  // X5, after the plunge
  EXPECT_FALSE(passes[2].contains("line"));
  EXPECT_NE(passes[2].at("reason").get<std::string>().find("does not cross the map"),
            std::string::npos)
      << passes[2];
}

// A pass of a path file gets the closed form too, measured against its own feed and
// axis: here three teeth of unequal pitch with offsets, runout at a phase of 60 deg and
// a 30 deg helix (the lower envelope of their arcs, analysis/feed_mark_formula.h),
// against the teeth model's exact heights.
TEST_F(FeedMarksReport, APassOfAPathMeetsTheClosedFormWithToothErrors) {
  const std::string job = R"({"tool": {"type": "ball", "radius": 3, "flutes": 3,
        "helix_deg": 30, "runout_mm": 0.001, "runout_phase_deg": 60,
        "tooth_angles_deg": [0, 100, 230],
        "tooth_offsets": [[0, 0], [0, 0.0004], [0.0015, 0]]},
      "cutting": {"model": "teeth"}, "machine": {"kinematics": "xyzbc-trt"},
      "stock": {"min": [0, -0.02, -2], "max": [0.8, 0.02, 0]}, "grid": {"spacing": 0.002},
      "path": {"file": "p.nc"}})";
  write("p.nc", "G43.4\nS6000 M3\nG0 X-4 Y0 Z1 B-15 C0\nG1 Z-0.1 F1200\nX5\n");
  const json f = simulate(job).at("feed_marks");
  const json& pass = f.at("passes").at(0);
  ASSERT_TRUE(pass.contains("predicted")) << pass;
  const json& predicted = pass["predicted"];
  Cutter ball = Cutter::make(CutterType::Ball, 3);
  ball.teeth = CutterTeeth::make(3, 30, 0.001, 60, 3);
  ball.teeth.editToothAnglesDeg() = {0, 100, 230};
  ball.teeth.editToothOffsets() = {{0, 0}, {0, 0.0004}, {0.0015, 0}};
  const double fz = 1200.0 / (6000 * 3);
  const FeedMarkPrediction p = predictFeedMarks(ball, 15, 0, fz);
  ASSERT_TRUE(p.applicable) << p.reason;
  EXPECT_NEAR(predicted["peak_to_valley_um"].get<double>(), p.heightMm * 1e3, 1e-9);
  EXPECT_EQ(predicted["regime"], p.regime);
  EXPECT_EQ(predicted["cutting_teeth"], json(p.cuttingTeeth));
  // Measured on the grid: the highest samples lie within half a step of the cusps, below
  // them by at most the arcs' slope there (< half the period / rho_f) times the step.
  const double pv = pass.at("peak_to_valley_um").get<double>() * 1e-3;
  const double slope = 1.5 * fz / 3;
  EXPECT_LE(pv, p.heightMm + 2e-9) << pass;
  EXPECT_GE(pv, p.heightMm - slope * 0.001 - 2e-9) << pass;
  EXPECT_NEAR(pass.at("mean_spacing_mm").get<double>(), p.spacingMm, 0.01 * fz) << pass;
}

// Which way a tooth's offset moves its mark matters once the pitch is unequal: tooth 1
// at 140 deg, 2 um further out, sits sigma = 2 cos(15 deg) um further along the feed
// (docs/teeth.md), making the gaps 0.1056 and 0.1611 mm; moved the other way they
// would be 0.1018 and 0.1649 mm and the marks 52 nm higher, more than the sampling's
// slack (the arcs' slope at the cusps, < 0.055, times half a 1 um step).
TEST_F(FeedMarksReport, AnOffsetToothsMarkMovesAlongTheFeed) {
  const std::string job = R"({"tool": {"type": "ball", "radius": 3, "flutes": 2,
        "tooth_angles_deg": [0, 140], "tooth_offsets": [[0, 0], [0.002, 0]]},
      "cutting": {"model": "teeth"}, "machine": {"kinematics": "xyzbc-trt"},
      "stock": {"min": [0, -0.004, -2], "max": [0.6, 0.004, 0]}, "grid": {"spacing": 0.001},
      "path": {"file": "p.nc"}})";
  write("p.nc", "G43.4\nS6000 M3\nG0 X-4 Y0 Z1 B-15 C0\nG1 Z-0.1 F1600\nX5\n");
  const json pass = simulate(job).at("feed_marks").at("passes").at(0);
  const double predicted = pass.at("predicted").at("peak_to_valley_um").get<double>() * 1e-3;
  const double pv = pass.at("peak_to_valley_um").get<double>() * 1e-3;
  EXPECT_LE(pv, predicted + 2e-9) << pass;
  EXPECT_GE(pv, predicted - 0.055 * 0.0005 - 2e-9) << pass;
  EXPECT_EQ(pass["predicted"]["regime"], "both teeth cut");
}

// Edge spans decide which teeth leave marks: at lead 15 deg the contact lies 3 pi / 12 =
// 0.785 mm along the ball's profile from the tip, its marks within 0.1 mm of it. Tooth 2's
// span [2, 13] mm starts 0.24 mm higher on the profile, so tooth 1 alone finishes: marks
// 2 fz apart, as deep as one tooth's arc over that chord, against the exact heights. A
// span that ends within the marks has no closed form, and the pass says so.
TEST_F(FeedMarksReport, AToothWhoseSpanMissesTheContactLeavesNoMark) {
  const std::string job = R"({"tool": {"type": "ball", "radius": 3, "flutes": 2,
        "tooth_edge_spans": [[0, 13], [SPAN, 13]]},
      "cutting": {"model": "teeth"}, "machine": {"kinematics": "xyzbc-trt"},
      "stock": {"min": [0, -0.004, -2], "max": [0.8, 0.004, 0]}, "grid": {"spacing": 0.002},
      "path": {"file": "p.nc"}})";
  write("p.nc", "G43.4\nS6000 M3\nG0 X-4 Y0 Z1 B-15 C0\nG1 Z-0.1 F1200\nX5\n");
  std::string missing = job;
  missing.replace(missing.find("SPAN"), 4, "2");
  const json pass = simulate(missing).at("feed_marks").at("passes").at(0);
  ASSERT_TRUE(pass.contains("predicted")) << pass;
  const double fz = 0.1, h = circularMarkHeight(3, 2 * fz);
  EXPECT_NEAR(pass["predicted"]["peak_to_valley_um"].get<double>() * 1e-3, h, 1e-12) << pass;
  EXPECT_EQ(pass["predicted"]["cutting_teeth"], json({0})) << pass;
  EXPECT_EQ(pass["predicted"]["regime"], "one tooth cuts") << pass;
  EXPECT_NEAR(pass.at("mean_spacing_mm").get<double>(), 2 * fz, 1e-6) << pass;
  const double pv = pass.at("peak_to_valley_um").get<double>() * 1e-3;
  const double slope = fz / std::sqrt(9 - fz * fz);
  EXPECT_LE(pv, h + 2e-9) << pass;
  EXPECT_GE(pv, h - slope * 0.001 - 2e-9) << pass;

  std::string ending = job;
  ending.replace(ending.find("SPAN"), 4, "0.8");
  const json cut = simulate(ending).at("feed_marks").at("passes").at(0);
  EXPECT_FALSE(cut.contains("predicted")) << cut;
  EXPECT_NE(cut.at("predicted_reason").get<std::string>().find("tooth 2's edge span"),
            std::string::npos)
      << cut;
}

// Where the closed form does not apply to a pass, the pass says why and is measured.
TEST_F(FeedMarksReport, APassWithoutAClosedFormSaysWhy) {
  const std::string job = R"({"tool": {"type": "ball", "radius": 3},
      "cutting": {"model": "teeth"},
      "stock": {"min": [0, -0.02, -2], "max": [0.8, 0.02, 0]}, "grid": {"spacing": 0.004},
      "path": {"file": "p.nc"}})";
  write("p.nc", "S6000 M3\nG0 X-4 Y0 Z1\nG1 Z-0.1 F1200\nX5 Z-0.11\n");
  const json pass = simulate(job).at("feed_marks").at("passes").at(0);
  EXPECT_TRUE(pass.contains("peak_to_valley_um")) << pass;
  EXPECT_NE(pass.at("predicted_reason").get<std::string>().find("not level"), std::string::npos)
      << pass;
}

TEST_F(FeedMarksReport, BandsGiveTheWholeMapsSection) {
  const json whole = simulate(kJob).at("feed_marks");
  // 20 rows in bands of 3: the line (between rows 9 and 10) spans two bands.
  EXPECT_EQ(simulate(kJob, " --tile-rows 3").at("feed_marks"), whole);
  // Band files carry the plan in their run description; merge measures it again.
  const CliRun bands = run("simulate " + path("job.json") + " -o " + path("bands") +
                           " --tile-rows 3 --json --bands 0:7");
  ASSERT_EQ(bands.status, 0) << bands.err;
  const CliRun merged = run("merge " + path("bands") + " --json");
  ASSERT_EQ(merged.status, 0) << merged.err;
  EXPECT_EQ(json::parse(merged.out).at("feed_marks"), whole);
}

TEST(FeedMarkSampler, SamplesAsExtractProfileDoesFromAnyBands) {
  Job job = loadJob(kJob, "job.json");
  const GridSpec g = job.grid();
  ZMap map(g, 0);
  for (int64_t j = 0; j < g.ny; ++j)  // heights with no symmetry to hide a swapped index
    for (int64_t i = 0; i < g.nx; ++i) map.at(i, j) = std::sin(0.37 * i + 1.1 * j * j) * 1e-3;
  const json plan = feedMarkPlan(job, g);
  const json& line = plan.at("line");
  const Profile profile = extractProfile(map, line["from"][0], line["from"][1], line["to"][0],
                                         line["to"][1], line["step_mm"], "test");
  const FeedMarks expected = measureFeedMarks(profile);
  FeedMarkSampler whole(plan, g);
  whole.add(map);
  const json r = whole.report();
  EXPECT_EQ(r["peak_to_valley_um"].get<double>(), expected.peakToValleyMm * 1e3);
  EXPECT_EQ(r["valleys"], expected.valleysMm.size());
  // Row by row, in any order: the same bits.
  FeedMarkSampler rows(plan, g);
  for (int64_t j = g.ny - 1; j >= 0; --j) {
    ZMap band(g.rows(j, j + 1), 0);
    for (int64_t i = 0; i < g.nx; ++i) band.at(i, 0) = map.at(i, j);
    rows.add(band);
  }
  EXPECT_EQ(rows.report(), r);
}

// Whether the raster's neighbours may cut the centre line's marks, against the ball's
// closed form: a ball's section is its circle whatever the lead, so the neighbours (tip
// lines w away) reach the centre line R - sqrt(R^2 - w^2) above its floor, and they may
// cut the marks iff that is below the marks' height. (At w = fz / 2 the two are equal:
// the same circle; the step-overs stay clear of it.)
TEST(FeedMarkPlan, NeighbouringPassesMayCutTheMarksIffTheyReachBelowThePeaks) {
  const double R = 3, fz = 0.1;
  const FeedMarkPrediction p = predictFeedMarks(Cutter::make(CutterType::Ball, R), 15, 0, fz);
  ASSERT_TRUE(p.applicable) << p.reason;
  int reach = 0, clear = 0;
  for (const double w : {0.02, 0.04, 0.07, 0.2, 0.5}) {
    std::string text = kJob;
    text.replace(text.find("0.02, \"depth\""), 4, fmt::format("{}", w));
    text.replace(text.find("-0.02, -2"), 5, "-0.6");  // room for passes at every w
    text.replace(text.find("0.02, 0]"), 4, "0.6");
    const Job job = loadJob(text, "job.json");
    ASSERT_EQ(job.raster.stepOver, w);
    const json plan = feedMarkPlan(job, job.grid());
    const bool expected = R - std::sqrt(R * R - w * w) < p.heightMm;
    const json& n = plan.at("predicted").at("neighbouring_passes");
    EXPECT_EQ(n.at("may_cut_the_marks").get<bool>(), expected) << w;
    EXPECT_EQ(n.at("step_over_mm").get<double>(), w);
    (expected ? reach : clear) += 1;
  }
  EXPECT_EQ(reach, 2);
  EXPECT_EQ(clear, 3);
}

TEST_F(FeedMarksReport, LinesThatCannotBeMeasuredSayWhy) {
  // The plan alone (no simulation: a vertical axis under teeth does not finish near
  // its centre line yet, docs/teeth.md "Limits"). A pass no longer than two cutter radii
  // leaves no centre line; a path file gets no prediction (only rasters do).
  write("p.nc", "S10000\nG0 X0.1 Y0 Z1\nG1 Z-0.1 F2000\nX0.7\n");
  const Job job = loadJob(R"({"tool": {"type": "ball", "radius": 3}, "cutting": {"model": "teeth"},
      "stock": {"min": [0, -0.02, -2], "max": [0.8, 0.02, 0]}, "grid": {"spacing": 0.01},
      "path": {"file": "p.nc"}})",
                          path("job.json"));
  const json plan = feedMarkPlan(job, job.grid());
  EXPECT_FALSE(plan.contains("line"));
  EXPECT_NE(plan.at("reason").get<std::string>().find("two cutter radii"), std::string::npos)
      << plan;
  EXPECT_TRUE(plan.contains("predicted_reason"));
  // A pass that misses the map, and a raster the formula does not cover (no lead).
  write("far.nc", "S10000\nG0 X-20 Y5 Z-0.1\nG1 X20 F2000\n");
  Job far = job;
  far.path = loadJob(R"({"tool": {"type": "ball", "radius": 3}, "cutting": {"model": "teeth"},
      "stock": {"min": [0, -0.02, -2], "max": [0.8, 0.02, 0]}, "grid": {"spacing": 0.01},
      "path": {"file": "far.nc"}})",
                     path("job.json"))
                 .path;
  EXPECT_NE(feedMarkPlan(far, far.grid()).at("reason").get<std::string>().find("does not cross"),
            std::string::npos);
  std::string flat = kJob;
  flat.replace(flat.find(", \"lead_deg\": 15"), 16, "");
  const Job noLead = loadJob(flat, "job.json");
  const json p = feedMarkPlan(noLead, noLead.grid());
  EXPECT_TRUE(p.contains("line"));
  EXPECT_NE(p.at("predicted_reason").get<std::string>().find("lead"), std::string::npos) << p;
  // An envelope job has no plan.
  EXPECT_TRUE(feedMarkPlan(parseJob(R"({"tool": {"type": "ball", "radius": 1},
      "stock": {"min": [0, 0, -2], "max": [4, 4, 0]}, "grid": {"spacing": 0.1},
      "path": {"raster": {"direction": "x", "step_over": 0.8, "depth": 0.3}}})",
                                    "e.json"),
                           job.grid())
                  .is_null());
}

TEST_F(FeedMarksReport, DesignGougesAreNotTracedWithTeeth) {
  // The plane z = -0.05 under a cut 0.1 deep: one gouge, reported without its moves.
  const std::array<Vec3, 3> t1{{{-1, -1, -0.05}, {2, -1, -0.05}, {2, 1, -0.05}}};
  const std::array<Vec3, 3> t2{{{-1, -1, -0.05}, {2, 1, -0.05}, {-1, 1, -0.05}}};
  writeStl(meshFromTriangles({t1, t2}), path("plane.stl"), StlFormat::Binary, "plane");
  std::string job = kJob;
  job.insert(job.rfind('}'), R"(, "design": {"stl": "plane.stl"})");
  const CliRun r = run("simulate " + write("job.json", job).string() + " -o " + path("out"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("not traced"), std::string::npos) << r.err;
  const json report = json::parse(scallop::test::slurp(path("out/report.json")));
  const json& gouges = report.at("design").at("gouges");
  EXPECT_GT(gouges.at("count").get<int>(), 0);
  EXPECT_EQ(gouges.at("moves_traced"), false);
  for (const json& g : gouges.at("deepest")) EXPECT_TRUE(g.at("moves").empty());
}

}  // namespace
}  // namespace scallop
