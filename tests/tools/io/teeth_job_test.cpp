// The teeth model's inputs (docs/formats.md "Cutting model"): the cutter keys and the
// job's "cutting" read and echoed, G-code feeds per tooth from F, S and the flutes of
// the tool in the spindle, and the refusals that name the field or the line.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "base/input_error.h"
#include "tests/support/cli_harness.h"
#include "tests/support/input_error_message.h"
#include "tools/io/gcode_reader.h"
#include "tools/io/job.h"
#include "tools/run/job_loader.h"

namespace scallop {
namespace {

using nlohmann::json;

const std::string kRaster = R"({
  "tool":  {"type": "ball", "radius": 3.0, "flutes": 3, "helix_deg": 30, "runout_mm": 0.01,
            "runout_phase_deg": 45},
  "cutting": {"model": "teeth", "feed_per_tooth": 0.05, "phase_deg": 10},
  "stock": {"min": [0, 0, -2], "max": [4, 4, 0]},
  "grid":  {"spacing": 0.1},
  "path":  {"raster": {"direction": "x", "step_over": 0.8, "depth": 0.3}}
})";

TEST(TeethJob, CutterKeysAndCuttingAreReadAndEchoed) {
  const Job job = parseJob(kRaster, "job.json");
  const CutterTeeth& t = job.cutter.teeth;
  EXPECT_EQ(t.flutes, 3);
  EXPECT_EQ(t.helixDeg, 30);
  EXPECT_EQ(t.runout, 0.01);
  EXPECT_EQ(t.runoutPhaseDeg, 45);
  EXPECT_TRUE(job.cutting.teeth());
  EXPECT_EQ(job.cutting.feedPerTooth, 0.05);
  EXPECT_EQ(job.cutting.phaseDeg, 10);
  const json echo = jobToJson(job);
  EXPECT_EQ(echo["tool"]["flutes"], 3);
  EXPECT_EQ(echo["tool"]["runout_mm"], 0.01);
  EXPECT_EQ(echo["cutting"]["model"], "teeth");
  EXPECT_EQ(echo["cutting"]["feed_per_tooth"], 0.05);
  EXPECT_EQ(echo["cutting"]["phase_deg"], 10);

  // Defaults: CutterTeeth's, and the envelope.
  const Job plain = parseJob(R"({"tools": {"1": {"type": "ball", "radius": 1},
      "2": {"type": "bull", "radius": 2, "corner_radius": 0.5, "flutes": 4}},
      "stock": {"min": [0, 0, -2], "max": [4, 4, 0]}, "grid": {"spacing": 0.1},
      "path": {"file": "p.nc"}})",
                             "job.json");
  EXPECT_FALSE(plain.cutting.teeth());
  EXPECT_EQ(plain.cutting.feedPerTooth, 0);
  EXPECT_EQ(plain.tools.at(1).teeth.flutes, 2);
  EXPECT_EQ(plain.tools.at(1).teeth.runout, 0);
  EXPECT_EQ(plain.tools.at(2).teeth.flutes, 4);
  EXPECT_EQ(jobToJson(plain)["cutting"], (json{{"model", "envelope"}, {"phase_deg", 0.0}}));
  EXPECT_FALSE(plain.pathOptions().teeth);
  EXPECT_TRUE(parseJob(kRaster, "job.json").pathOptions().teeth);
  EXPECT_EQ(parseJob(kRaster, "job.json").pathOptions().flutes, 3);
}

// G-code read with the teeth model: `flutes` for the one tool, or the job's tools.
ToolPathFile readTeeth(const std::string& text, int flutes = 2,
                       const std::map<int64_t, Cutter>& tools = {}, bool teeth = true) {
  std::istringstream in(text);
  ToolPathFile out;
  PathFileOptions options;
  options.teeth = teeth;
  options.flutes = flutes;
  options.tools = tools;
  readGcode(in, "p.nc", options, out);
  return out;
}

bool ignored(const ToolPathFile& f, const std::string& word) {
  for (const IgnoredWords::Entry& e : f.ignored.entries)
    if (e.word == word) return true;
  return false;
}

TEST(TeethJob, GcodeFeedPerToothIsFeedOverSpeedAndFlutes) {
  // G94 (the default): fz = F / (S flutes), F and S modal; rapids carry none.
  const ToolPathFile f = readTeeth("G0 X0 Y0 Z1\nS10000 M3\nG1 Z-0.2 F2000\nX5\nF500\nX6\nG0 Z5\n");
  ASSERT_EQ(f.path.moves.size(), 4u);  // the first G0 only sets the position
  EXPECT_EQ(f.path.moves[0].feedPerTooth, 2000.0 / (10000 * 2));
  EXPECT_EQ(f.path.moves[1].feedPerTooth, 2000.0 / (10000 * 2));
  EXPECT_EQ(f.path.moves[2].feedPerTooth, 500.0 / (10000 * 2));
  EXPECT_EQ(f.path.moves[3].feedPerTooth, 0);  // the rapid
  EXPECT_FALSE(ignored(f, "F"));
  EXPECT_FALSE(ignored(f, "S"));
  EXPECT_TRUE(f.warnings.kept.empty());
  // Inches per minute; 4 flutes; the arc, one exact move, carries it.
  const ToolPathFile inch = readTeeth("G20 G0 X0 Y0 Z0\nS1000\nG2 X1 Y0 R0.5 F10\n", 4);
  ASSERT_EQ(inch.path.moves.size(), 1u);
  EXPECT_EQ(inch.path.moves[0].arc, 1u);
  for (const Move& m : inch.path.moves) EXPECT_EQ(m.feedPerTooth, 10 * 25.4 / (1000 * 4));
  // G95: F per revolution, no S needed; G93 (inverse time) and no S give none.
  EXPECT_EQ(readTeeth("G95 G0 X0 Y0 Z0\nG1 X1 F0.2\n").path.moves[0].feedPerTooth, 0.1);
  EXPECT_EQ(readTeeth("G93 S9000 G0 X0 Y0 Z0\nG1 X1 F60\n").path.moves[0].feedPerTooth, 0);
  EXPECT_EQ(readTeeth("G0 X0 Y0 Z0\nG1 X1 F600\n").path.moves[0].feedPerTooth, 0);
  // Without the teeth model feeds are ignored words and no move carries one.
  const ToolPathFile envelope = readTeeth("S10000 G0 X0 Y0 Z0\nG1 X1 F2000\n", 2, {}, false);
  EXPECT_EQ(envelope.path.moves[0].feedPerTooth, 0);
  EXPECT_TRUE(ignored(envelope, "F"));
  EXPECT_TRUE(ignored(envelope, "S"));
}

TEST(TeethJob, GcodeFeedPerToothUsesTheFlutesOfTheToolInTheSpindle) {
  std::map<int64_t, Cutter> tools;
  tools[1] = Cutter::make(CutterType::Ball, 1);
  tools[2] = Cutter::make(CutterType::Flat, 2);
  tools[2].teeth.flutes = 4;
  const ToolPathFile f =
      readTeeth("S8000 M3\nT1 M6\nG0 X0 Y0 Z1\nG1 Z0 F1600\nT2 M6\nG0 X5 Y0 Z1\nG1 Z0\n", 2, tools);
  ASSERT_EQ(f.path.moves.size(), 3u);
  EXPECT_EQ(f.path.moves[0].feedPerTooth, 1600.0 / (8000 * 2));
  EXPECT_EQ(f.path.moves[2].feedPerTooth, 1600.0 / (8000 * 4));
}

TEST(TeethJob, M3AndM4SetTheSpindleOfTheMovesAfterThem) {
  const ToolPathFile teeth =
      readTeeth("S9000\nG0 X0 Y0 Z0\nG1 X1 F900\nM4\nX2\nM3\nX3\nM4\nG0 Z1\n");
  ASSERT_EQ(teeth.path.moves.size(), 4u);
  EXPECT_EQ(teeth.path.moves[0].spindle, 0);  // the job's direction
  EXPECT_EQ(teeth.path.moves[1].spindle, -1);
  EXPECT_EQ(teeth.path.moves[2].spindle, 1);
  EXPECT_EQ(teeth.path.moves[3].spindle, -1);
  EXPECT_TRUE(teeth.warnings.kept.empty());
  EXPECT_FALSE(ignored(teeth, "M4"));
  EXPECT_FALSE(ignored(teeth, "M3"));
  const ToolPathFile envelope = readTeeth("S9000 M4\nG0 X0 Y0 Z0\nG1 X1 F900\n", 2, {}, false);
  EXPECT_TRUE(envelope.warnings.kept.empty());
  EXPECT_TRUE(ignored(envelope, "M4"));
}

TEST(TeethJob, ToothGeometryAndSpindleAreReadEchoedAndChecked) {
  const std::string tool = R"("tool": {"type": "bull", "radius": 5, "corner_radius": 2.5,
      "flutes": 2, "tooth_angles_deg": [0, 170], "tooth_offsets": [[-0.026, 0.003], [0.011, 0]]})";
  const std::string rest = R"("cutting": {"model": "teeth", "feed_per_tooth": 0.4},
      "stock": {"min": [0, 0, -2], "max": [4, 4, 0]}, "grid": {"spacing": 0.1},
      "path": {"file": "p.nc"})";
  const Job job = parseJob("{" + tool + ", " + rest + R"(, "spindle": "ccw"})", "job.json");
  const CutterTeeth& t = job.cutter.teeth;
  EXPECT_EQ(t.toothAnglesDeg(), (std::vector<double>{0, 170}));
  ASSERT_EQ(t.toothOffsets().size(), 2u);
  EXPECT_EQ(t.toothOffsets()[0].radial, -0.026);
  EXPECT_EQ(t.toothOffsets()[0].axial, 0.003);
  EXPECT_TRUE(job.cutting.counterClockwise);
  const json echo = jobToJson(job);
  EXPECT_EQ(echo["tool"]["tooth_offsets"], json::parse("[[-0.026, 0.003], [0.011, 0]]"));
  EXPECT_EQ(echo["tool"]["tooth_angles_deg"], json::parse("[0, 170]"));
  EXPECT_EQ(echo["spindle"], "ccw");
  EXPECT_FALSE(parseJob("{" + tool + ", " + rest + "}", "job.json").cutting.counterClockwise);

  auto refused = [&](const std::string& toolKeys, const std::string& field,
                     const std::string& extra = "") {
    const std::string text = R"({"tool": {"type": "ball", "radius": 3, "flutes": 2, )" + toolKeys +
                             "}, " + rest + extra + "}";
    try {
      parseJob(text, "job.json");
      ADD_FAILURE() << "accepted " << toolKeys << extra;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  refused(R"("tooth_offsets": [[0, 0]])", "tool.tooth_offsets");
  refused(R"("tooth_offsets": [[0, 0], [0, 0], [0, 0]])", "tool.tooth_offsets");
  refused(R"("tooth_offsets": [[0, 0], [0, "a"]])", "tool.tooth_offsets[1][1]");
  refused(R"("tooth_offsets": [[0, 0], [0.001]])", "tool.tooth_offsets[1]");
  refused(R"("tooth_offsets": {"0": [0, 0]})", "tool.tooth_offsets");
  refused(R"("tooth_offsets": [[0, 0], [-0.001, 0]])", "tool.tooth_offsets[1][0]");
  refused(R"("tooth_angles_deg": [0, "x"])", "tool.tooth_angles_deg[1]");
  refused(R"("tooth_angles_deg": [0, 200, 100])", "tool.tooth_angles_deg");
  refused(R"("tooth_angles_deg": [0, 0])", "tool.tooth_angles_deg[1]");
  refused(R"("tooth_angles_deg": [5, 180])", "tool.tooth_angles_deg[0]");
  refused(R"("helix_deg": 0)", "spindle", R"(, "spindle": "left")");
  refused(R"("helix_deg": 0)", "spindle", R"(, "spindle": 3)");
}

// The edge-span and rake tests' job: a face mill (bull R 10, r 5, two flutes) with `keys`
// on its tool (faceMillTool), then the rest of the job (kFaceMillRest).
const char* const kFaceMillRest = R"("cutting": {"model": "teeth", "feed_per_tooth": 0.4},
      "stock": {"min": [0, 0, -2], "max": [4, 4, 0]}, "grid": {"spacing": 0.1},
      "path": {"file": "p.nc"})";
std::string faceMillTool(const std::string& keys) {
  return R"({"tool": {"type": "bull", "radius": 10, "corner_radius": 5, "flute_length": 8,
        "flutes": 2, )" +
         keys + "}, ";
}

// Edge spans: "edge_span" for every tooth, "tooth_edge_spans" one per flute, echoed as
// given (one span when all are equal); every wrong shape or value names its field.
TEST(TeethJob, EdgeSpansAreReadEchoedAndChecked) {
  const std::string rest = kFaceMillRest;
  auto tool = [](const std::string& keys) { return faceMillTool(keys); };
  const Job one = parseJob(tool(R"("edge_span": [5, 12.85])") + rest + "}", "job.json");
  ASSERT_EQ(one.cutter.teeth.edgeSpans().size(), 2u);
  EXPECT_EQ(one.cutter.teeth.edgeSpans()[1].from, 5);
  EXPECT_EQ(one.cutter.teeth.edgeSpans()[1].to, 12.85);
  EXPECT_EQ(jobToJson(one)["tool"]["edge_span"], json::parse("[5, 12.85]"));
  const Job each =
      parseJob(tool(R"("tooth_edge_spans": [[5, 12.85], [0, 15]])") + rest + "}", "job.json");
  EXPECT_EQ(each.cutter.teeth.edgeSpans()[1].to, 15);
  EXPECT_EQ(jobToJson(each)["tool"]["tooth_edge_spans"], json::parse("[[5, 12.85], [0, 15]]"));
  EXPECT_TRUE(parseJob(tool(R"("helix_deg": 0)") + rest + "}", "job.json")
                  .cutter.teeth.edgeSpans()
                  .empty());
  // The whole edge: Rb + r pi / 2 + L - r = 5 + 7.853981... + 3.
  auto refused = [&](const std::string& keys, const std::string& field) {
    expectRejected([&] { parseJob(tool(keys) + rest + "}", "job.json"); }, field);
  };
  refused(R"("edge_span": [5, 15.86])", "tool.edge_span");
  refused(R"("edge_span": [-1, 3])", "tool.edge_span");
  refused(R"("edge_span": [3, 3])", "tool.edge_span");
  refused(R"("edge_span": [3])", "tool.edge_span");
  refused(R"("edge_span": [3, "x"])", "tool.edge_span[1]");
  refused(R"("edge_span": 3)", "tool.edge_span");
  refused(R"("tooth_edge_spans": [[0, 3]])", "tool.tooth_edge_spans");
  refused(R"("tooth_edge_spans": [[0, 3], [4, 2]])", "tool.tooth_edge_spans[1]");
  refused(R"("tooth_edge_spans": [[0, 3], [1, 2, 3]])", "tool.tooth_edge_spans[1]");
  refused(R"("edge_span": [0, 3], "tooth_edge_spans": [[0, 3], [0, 3]])", "tool.tooth_edge_spans");
}

// Rakes: "rake_deg" for every tooth, "tooth_rakes_deg" one per flute, echoed as given;
// an angle out of range, a wrong shape, both keys, or a face that leaves the cutter's
// surface on the edge's span names its field (and the tooth and height).
TEST(TeethJob, RakesAreReadEchoedAndChecked) {
  const std::string rest = kFaceMillRest;
  auto tool = [](const std::string& keys) {
    return faceMillTool(R"("edge_span": [5, 12.85], )" + keys);
  };
  const Job one = parseJob(tool(R"("rake_deg": [6, -4])") + rest + "}", "job.json");
  ASSERT_EQ(one.cutter.teeth.toothRakes().size(), 2u);
  EXPECT_EQ(one.cutter.teeth.toothRakes()[1].axialDeg, 6);
  EXPECT_EQ(one.cutter.teeth.toothRakes()[1].radialDeg, -4);
  EXPECT_EQ(jobToJson(one)["tool"]["rake_deg"], json::parse("[6, -4]"));
  const Job each =
      parseJob(tool(R"("tooth_rakes_deg": [[6, -4], [0, 0]])") + rest + "}", "job.json");
  EXPECT_EQ(jobToJson(each)["tool"]["tooth_rakes_deg"], json::parse("[[6, -4], [0, 0]]"));
  auto refused = [&](const std::string& keys, const std::string& field) {
    expectRejected([&] { parseJob(tool(keys) + rest + "}", "job.json"); }, field);
  };
  refused(R"("rake_deg": [46, 0])", "tool.rake_deg");
  refused(R"("rake_deg": [0, -50])", "tool.rake_deg");
  refused(R"("rake_deg": [3])", "tool.rake_deg");
  refused(R"("rake_deg": [3, "x"])", "tool.rake_deg[1]");
  refused(R"("tooth_rakes_deg": [[0, 3]])", "tool.tooth_rakes_deg");
  refused(R"("tooth_rakes_deg": [[0, 3], [0, 90]])", "tool.tooth_rakes_deg[1]");
  refused(R"("rake_deg": [0, 3], "tooth_rakes_deg": [[0, 3], [0, 3]])", "tool.tooth_rakes_deg");
  // A ball's whole edge with an axial rake of 30 deg: the face through the tip's axis
  // rises as h tan(30 deg) and leaves the flank (radius 2) near h = 2 sin(60 deg) /
  // tan(30 deg) = 3 mm, below the flute top at 8 mm.
  const std::string message = inputErrorMessage([&] {
    parseJob(R"({"tool": {"type": "ball", "radius": 2, "flute_length": 8, "rake_deg": [30, 0]}, )" +
                 rest + "}",
             "job.json");
  });
  EXPECT_NE(message.find("tool.rake_deg"), std::string::npos) << message;
  EXPECT_NE(message.find("tooth 0's rake face leaves the cutter's surface at height 3"),
            std::string::npos)
      << message;
}

class TeethJobFiles : public scallop::test::CliFixture {};

TEST_F(TeethJobFiles, AMoveWithoutFeedPerToothNamesTheFieldAndTheLine) {
  write("p.nc", "G0 X0 Y0 Z1\nS10000\nG1 Z-0.2 F2000\nG94\nG93 X3 F60\n");
  const std::string job = R"({"tool": {"type": "ball", "radius": 1},
      "cutting": {"model": "teeth"},
      "stock": {"min": [0, 0, -2], "max": [4, 4, 0]}, "grid": {"spacing": 0.1},
      "path": {"file": "p.nc"}})";
  const std::string source = path("job.json");
  const std::string message = inputErrorMessage([&] { loadJob(job, source); });
  EXPECT_NE(message.find(source + ": cutting.feed_per_tooth"), std::string::npos) << message;
  EXPECT_NE(message.find("p.nc:5"), std::string::npos) << message;  // the G93 move
  // The job's feed per tooth covers the moves without their own.
  std::string withFz = job;
  withFz.replace(withFz.find("\"teeth\"}"), 8, "\"teeth\", \"feed_per_tooth\": 0.1}");
  EXPECT_EQ(inputErrorMessage([&] { loadJob(withFz, source); }), "");
  // A raster's moves carry none: the job must give it.
  std::string raster = kRaster;
  raster.replace(raster.find(", \"feed_per_tooth\": 0.05"), 24, "");
  const std::string r = inputErrorMessage([&] { loadJob(raster, source); });
  EXPECT_NE(r.find(source + ": cutting.feed_per_tooth"), std::string::npos) << r;
}

}  // namespace
}  // namespace scallop
