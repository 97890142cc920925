// Bad-input matrix, part 1: job files, tool-path files and command-line options
// (tests/tools/cli/bad_input_matrix.h says what every row must satisfy).
#include "tests/tools/cli/bad_input_matrix.h"

#include <string>
#include <vector>

namespace scallop::test {
namespace {

// A small valid job (0.1 s); rows replace one piece of it.
const std::string kJob = R"({
  "tool":  {"type": "ball", "radius": 1.0},
  "stock": {"min": [0, 0, -2], "max": [4, 4, 0]},
  "grid":  {"spacing": 0.1},
  "path":  {"raster": {"direction": "x", "step_over": 0.8, "depth": 0.3}}
})";
const std::string kFileJob = R"({
  "tool":  {"type": "ball", "radius": 1.0},
  "stock": {"min": [0, 0, -2], "max": [4, 4, 0]},
  "grid":  {"spacing": 0.1},
  "path":  {"file": "part.txt"}
})";

const std::string kGarbage("\x89\x00\xff\x13{\x01\"tool\x00\x7f\xfe\n\x1b[2J", 17);

BadInputRow jobRow(const std::string& name, const std::string& text,
                   std::vector<std::string> mentions, const std::string& extra = "") {
  return {
      name, {{"job.json", text}}, "simulate @/job.json -o @/out" + extra, 1, std::move(mentions)};
}

TEST_F(BadInputMatrix, JobFiles) {
  const std::vector<BadInputRow> rows = {
      jobRow("empty file", "", {"job.json:1:1", "malformed JSON"}),
      jobRow("binary garbage", kGarbage, {"job.json:1:1", "malformed JSON"}),
      jobRow("truncated", kJob.substr(0, 70), {"job.json:3:", "malformed JSON"}),
      jobRow("number beyond double", replaced(kJob, "1.0}", "1e400}"),
             {"job.json", "number overflow"}),
      jobRow("huge length", replaced(kJob, "1.0}", "1e300}"), {"tool.radius", "1e6"}),
      jobRow("huge coordinate", replaced(kJob, "[4, 4, 0]", "[4e9, 4, 0]"), {"stock.max", "1e6"}),
      jobRow("huge depth", replaced(kJob, "\"depth\": 0.3", "\"depth\": 1e300"),
             {"path.raster.depth"}),
      jobRow("NaN", replaced(kJob, "1.0}", "NaN}"), {"job.json:2:", "malformed JSON"}),
      jobRow("Infinity", replaced(kJob, "0.1}", "Infinity}"), {"job.json:4:", "malformed JSON"}),
      jobRow("negative spacing", replaced(kJob, "0.1}", "-0.1}"), {"grid.spacing", "> 0"}),
      jobRow("zero spacing", replaced(kJob, "0.1}", "0}"), {"grid.spacing", "> 0"}),
      jobRow("zero radius", replaced(kJob, "1.0}", "0}"), {"tool.radius"}),
      jobRow("negative radius", replaced(kJob, "1.0}", "-1}"), {"tool.radius"}),
      jobRow("empty stock", replaced(kJob, "[4, 4, 0]", "[4, 4, -2]"), {"stock.max"}),
      jobRow("inverted stock", replaced(kJob, "[4, 4, 0]", "[-4, 4, 0]"), {"stock.max"}),
      jobRow("negative step-over", replaced(kJob, "0.8", "-0.8"), {"path.raster.step_over"}),
      jobRow("zero step-over", replaced(kJob, "0.8", "0"), {"path.raster.step_over"}),
      jobRow("too many passes", replaced(kJob, "0.8", "1e-9"), {"path.raster.step_over"}),
      // 2.4e10 moves: refused before generating them, naming the bytes.
      jobRow("raster moves larger than memory",
             replaced(replaced(kJob, "0.8", "0.001"), "0.3}", "0.3, \"segment_length\": 1e-6}"),
             {"path.raster.segment_length", "bytes"}),
      jobRow("lead of 90 deg", replaced(kJob, "0.3}", "0.3, \"lead_deg\": 90}"),
             {"path.raster.lead_deg"}),
      jobRow("axis tolerance (no longer used)",
             replaced(kJob, "{\n", "{\"sweep\": {\"axis_tolerance\": 1e-4},\n"),
             {"sweep.axis_tolerance", "no longer used"}),
      jobRow("unknown top-level key", replaced(kJob, "{\n", "{\"colour\": 1,\n"),
             {"colour", "unknown key"}),
      jobRow("unknown nested key", replaced(kJob, "1.0}", "1.0, \"colour\": 1}"),
             {"tool.colour", "unknown key"}),
      jobRow("string for a number", replaced(kJob, "1.0}", "\"1.0\"}"),
             {"tool.radius", "expected a number"}),
      jobRow("two coordinates", replaced(kJob, "[0, 0, -2]", "[0, 0]"), {"stock.min"}),
      jobRow("object for a string", replaced(kJob, "\"ball\"", "{}"), {"tool.type"}),
      jobRow("unknown cutter type", replaced(kJob, "\"ball\"", "\"drill\""), {"tool.type"}),
      jobRow("array at the top", "[1, 2]", {"job.json", "JSON object"}),
      jobRow("missing section", replaced(kJob, "\"grid\":  {\"spacing\": 0.1},", ""),
             {"grid", "missing"}),
      jobRow("duplicated key", replaced(kJob, "0.1}", "0.1, \"spacing\": 0.2}"),
             {"grid.spacing", "duplicate key"}),
      jobRow("duplicated section", replaced(kJob, "{\n", "{\"grid\": {\"spacing\": 1},\n"),
             {"grid", "duplicate key"}),
      jobRow("raster and file", replaced(kJob, "0.3}}", "0.3}, \"file\": \"a.txt\"}"),
             {"path", "exactly one"}),
      // The map would need 48 TB: refused before allocating, naming the bytes and --tiled.
      jobRow("grid larger than memory (stamp)", replaced(kJob, "0.1}", "2e-6}"),
             {"grid.spacing", "bytes", "--tiled"}, " --method stamp"),
      {"job file missing", {}, "simulate @/nope.json -o @/out", 1, {"@/nope.json", "cannot open"}},
      {"job file is a folder", {{"d/x", ""}}, "simulate @/d -o @/out", 1, {"@/d", "folder"}},
      {"output folder cannot be created",
       {{"job.json", kJob}},
       "simulate @/job.json -o /proc/scallop-bad-input",
       1,
       {"/proc/scallop-bad-input"}},
      {"output is a file",
       {{"job.json", kJob}},
       "simulate @/job.json -o @/job.json",
       1,
       {"@/job.json", "not a folder"}},
  };
  for (const BadInputRow& row : rows) check(row);
}

// The teeth model's keys (docs/formats.md "Cutting model"): the cutter's teeth and the
// job's "cutting", and what the teeth refuse around the run.
TEST_F(BadInputMatrix, TeethKeys) {
  auto tool = [](const std::string& keys) { return replaced(kJob, "1.0}", "1.0, " + keys + "}"); };
  auto cutting = [](const std::string& value) {
    return replaced(kJob, "{\n", "{\"cutting\": " + value + ",\n");
  };
  const std::string teeth = R"({"model": "teeth", "feed_per_tooth": 0.1})";
  const std::vector<BadInputRow> rows = {
      jobRow("flutes a string", tool(R"("flutes": "two")"), {"tool.flutes", "whole number"}),
      jobRow("flutes zero", tool(R"("flutes": 0)"), {"tool.flutes", "1 to 16"}),
      jobRow("flutes not whole", tool(R"("flutes": 2.5)"), {"tool.flutes", "whole number"}),
      jobRow("helix a string", tool(R"("helix_deg": "30")"), {"tool.helix_deg", "number"}),
      jobRow("helix beyond 60 deg", tool(R"("helix_deg": 61)"), {"tool.helix_deg", "60"}),
      jobRow("runout a string", tool(R"("runout_mm": "0.01")"), {"tool.runout_mm", "number"}),
      jobRow("runout beyond R / 10", tool(R"("runout_mm": 0.2)"), {"tool.runout_mm", "0.1"}),
      jobRow("runout phase a string", tool(R"("runout_phase_deg": "up")"),
             {"tool.runout_phase_deg", "number"}),
      jobRow("cutting not an object", cutting("\"teeth\""), {"cutting", "object"}),
      jobRow("unknown cutting model", cutting(R"({"model": "saw"})"),
             {"cutting.model", "envelope", "teeth"}),
      jobRow("cutting model a number", cutting(R"({"model": 2})"), {"cutting.model", "string"}),
      jobRow("cutting unknown key", cutting(R"({"model": "teeth", "rpm": 9000})"),
             {"cutting.rpm", "unknown key"}),
      jobRow("zero feed per tooth", cutting(R"({"model": "teeth", "feed_per_tooth": 0})"),
             {"cutting.feed_per_tooth", "> 0"}),
      jobRow("feed per tooth a string", cutting(R"({"model": "teeth", "feed_per_tooth": "0.1"})"),
             {"cutting.feed_per_tooth", "number"}),
      jobRow("phase a string", cutting(R"({"model": "teeth", "phase_deg": "0"})"),
             {"cutting.phase_deg", "number"}),
      jobRow("teeth without a feed per tooth", cutting(R"({"model": "teeth"})"),
             {"job.json: cutting.feed_per_tooth", "missing"}),
      jobRow("stamping with teeth", cutting(teeth), {"--method", "teeth"}, " --method stamp"),
      {"G-code without S for teeth",
       {{"job.json", replaced(kFileJob, "{\n", "{\"cutting\": {\"model\": \"teeth\"},\n")},
        {"p.nc", "G0 X0 Y0 Z1\nG1 Z-0.2 F300\nX1\n"}},
       "simulate @/job.json -o @/out --path @/p.nc",
       1,
       {"cutting.feed_per_tooth", "p.nc:2"}},
      {"G-code negative spindle speed with teeth",
       {{"job.json", cutting(teeth)}, {"p.nc", "G0 X0 Y0 Z1\nS-100\nG1 Z-0.2 F300\n"}},
       "simulate @/job.json -o @/out --path @/p.nc",
       1,
       {"p.nc:2", "S-100"}},
      {"interval: zero feed per tooth",
       {},
       "interval --tool ball --radius 3 --lead 15 --scallop 0.01 --feed-per-tooth 0",
       1,
       {"--feed-per-tooth", "> 0"}},
      {"interval: zero flutes",
       {},
       "interval --tool ball --radius 3 --lead 15 --scallop 0.01 --feed-per-tooth 0.1 --flutes 0",
       1,
       {"--flutes", "1 to 16"}},
      {"interval: runout beyond R / 10",
       {},
       "interval --tool ball --radius 3 --lead 15 --scallop 0.01 --feed-per-tooth 0.1 --runout 1",
       1,
       {"--runout", "0.3"}},
  };
  for (const BadInputRow& row : rows) check(row);
}

BadInputRow pathRow(const std::string& name, const std::string& text,
                    std::vector<std::string> mentions) {
  return {name,
          {{"job.json", kFileJob}, {"part.txt", text}},
          "simulate @/job.json -o @/out",
          1,
          std::move(mentions)};
}

BadInputRow pathRow(const std::string& name, const std::string& file, const std::string& text,
                    std::vector<std::string> mentions) {
  return {name,
          {{"job.json", replaced(kFileJob, "part.txt", file)}, {file, text}},
          "simulate @/job.json -o @/out",
          1,
          std::move(mentions)};
}

// Tool-path files of every format, through a job's path.file (format by extension:
// tools/io/tool_path_file.h). Each reader's own tests hold its finer cases.
TEST_F(BadInputMatrix, ToolPathFiles) {
  const std::vector<BadInputRow> rows = {
      pathRow("beyond 1 km", "part.txt", "0 0 -0.2\n1e300 1 -0.2\n", {"part.txt:2", "1 km"}),
      pathRow("APT: empty", "p.apt", "", {"p.apt", "GOTO"}),
      pathRow("APT: garbage", "p.apt", kGarbage, {"p.apt:1"}),
      pathRow("APT: truncated GOTO", "p.apt", "GOTO/1,2", {"p.apt:1", "GOTO"}),
      pathRow("APT: continuation past the end", "p.apt", "GOTO/1,2,3,$\n", {"p.apt:1"}),
      pathRow("APT: NaN", "p.apt", "GOTO/1,2,nan\n", {"p.apt:1"}),
      pathRow("APT: beyond double", "p.apt", "GOTO/1,2,1e400\n", {"p.apt:1"}),
      pathRow("APT: beyond 1 km", "p.apt", "GOTO/0,0,0\nGOTO/1,2,-3e9\n", {"p.apt:2", "1 km"}),
      pathRow("APT: zero axis", "p.apt", "GOTO/0,0,-0.2,0,0,0\nGOTO/1,0,-0.2\n", {"p.apt:1"}),
      pathRow("G-code: empty", "p.nc", "", {"p.nc"}),
      pathRow("G-code: garbage", "p.nc", kGarbage, {"p.nc:1"}),
      pathRow("G-code: truncated word", "p.nc", "G1 X1 Y", {"p.nc:1", "Y"}),
      pathRow("G-code: exponent", "p.nc", "G1 X1e400 Y0 Z-0.2\n",
              {"p.nc:1", "\"X1e400\"", "no exponent"}),
      pathRow("G-code: beyond 1 km", "p.nc", "G0 X0 Y0 Z-0.2\nG1 X9000000\n", {"p.nc:2", "1 km"}),
      pathRow("G-code: arc radius below half the chord", "p.nc", "G0 X0 Y0 Z-0.2\nG2 X1 Y0 R0.1\n",
              {"p.nc:2"}),
      pathRow("G-code: unclosed comment", "p.nc", "G1 X1 (no end", {"p.nc:1"}),
      pathRow("empty file", "", {"part.txt"}),
      pathRow("only comments", "# nothing\n\n", {"part.txt"}),
      pathRow("binary garbage", kGarbage, {"part.txt:1"}),
      pathRow("truncated line", "0 0 -0.2\n1 2", {"part.txt:2"}),
      pathRow("four numbers", "0 0 -0.2 1\n", {"part.txt:1"}),
      pathRow("NaN", "0 0 -0.2\nnan 1 -0.2\n", {"part.txt:2"}),
      pathRow("infinity", "0 0 -0.2\n1 inf -0.2\n", {"part.txt:2"}),
      pathRow("number beyond double", "0 0 -0.2\n1 1e400 -0.2\n", {"part.txt:2"}),
      pathRow("zero axis", "0 0 -0.2 0 0 0\n", {"part.txt:1"}),
      pathRow("words", "0 0 -0.2\nGOTO the shop\n", {"part.txt:2"}),
      pathRow("axis below the horizontal", "0 0 -0.2 0 0 1\n1 0 -0.2 0.6 0 -0.8\n",
              {"part.txt:2", "below the horizontal", "k >= 0"}),
      pathRow("APT: axis below the horizontal", "p.apt",
              "GOTO/0,0,-0.2,0,0,1\nGOTO/1,0,-0.2,0,0.6,-0.8\n",
              {"p.apt:2", "below the horizontal"}),
      {"path file missing",
       {{"job.json", kFileJob}},
       "simulate @/job.json -o @/out",
       1,
       {"part.txt"}},
      {"path file is a folder",
       {{"job.json", kFileJob}, {"part.txt/x", ""}},
       "simulate @/job.json -o @/out",
       1,
       {"part.txt"}},
  };
  for (const BadInputRow& row : rows) check(row);
}

TEST_F(BadInputMatrix, CommandLineOptions) {
  const std::vector<std::pair<std::string, std::string>> job = {{"job.json", kJob}};
  const std::vector<BadInputRow> rows = {
      {"no command", {}, "", 2, {}},
      {"unknown command", {}, "frobnicate", 2, {}},
      {"unknown option", job, "simulate @/job.json --no-such-option", 2, {"--no-such-option"}},
      {"negative threads", job, "simulate @/job.json -o @/out --threads -1", 2, {"--threads"}},
      {"threads not a number", job, "simulate @/job.json -o @/out --threads two", 2, {"--threads"}},
      {"huge threads", job, "simulate @/job.json -o @/out --threads 99999999999", 2, {"--threads"}},
      {"unknown method", job, "simulate @/job.json -o @/out --method guess", 2, {"--method"}},
      {"zero tile rows", job, "simulate @/job.json -o @/out --tile-rows 0", 2, {"--tile-rows"}},
      {"bad band range", job, "simulate @/job.json -o @/out --bands 3:1", 1, {"--bands"}},
      {"bands not numbers", job, "simulate @/job.json -o @/out --bands a:b", 1, {"--bands"}},
      {"option without value", job, "simulate @/job.json -o", 2, {"-o"}},
      {"interval: zero radius",
       {},
       "interval --tool ball --radius 0 --scallop 0.01",
       1,
       {"--radius"}},
      {"interval: NaN radius",
       {},
       "interval --tool ball --radius nan --scallop 0.01",
       1,
       {"--radius"}},
      {"interval: infinite scallop",
       {},
       "interval --tool ball --radius 1 --scallop 1e400",
       1,
       {"--scallop"}},
      {"interval: radius beyond 1 km",
       {},
       "interval --tool ball --radius 1e300 --scallop 0.01",
       1,
       {"--radius"}},
      {"gouge: radius beyond 1 km",
       {},
       "gouge @/none.stl --radius 1e300 --length 20",
       1,
       {"--radius"}},
      {"surface: size beyond 1 km", {}, "surface --size 1e300 1 -o @/s.stl", 1, {"--size"}},
      {"interval: unknown tool",
       {},
       "interval --tool drill --radius 1 --scallop 0.01",
       1,
       {"--tool"}},
      {"surface: negative size", {}, "surface --size -1 1 -o @/s.stl", 1, {"--size"}},
      {"surface: zero facets", {}, "surface --facets 0 -o @/s.stl", 1, {"--facets"}},
      {"surface: unwritable output",
       {},
       "surface -o /proc/scallop-bad.stl",
       1,
       {"/proc/scallop-bad.stl"}},
      {"bench: zero area", {}, "bench --area 0", 2, {"--area"}},
      {"bench: unknown case", {}, "bench --case B10", 2, {"--case"}},
      {"merge: missing folder", {}, "merge @/none", 1, {"@/none"}},
      {"merge: folder without bands", {{"d/readme", "x"}}, "merge @/d", 1, {"@/d"}},
      {"validate: unwritable output",
       {},
       "validate -o /proc/scallop-bad",
       1,
       {"/proc/scallop-bad"}},
  };
  for (const BadInputRow& row : rows) check(row);
}

}  // namespace
}  // namespace scallop::test
