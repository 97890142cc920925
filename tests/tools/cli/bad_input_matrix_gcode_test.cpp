// Bad-input matrix, G-code programs and the job keys they use (tools, machine,
// work_offsets): every row exits 1 with one line naming the file:line or field, and
// leaves no file (tests/tools/cli/bad_input_matrix.h).
#include <string>
#include <vector>

#include "tests/tools/cli/bad_input_matrix.h"

namespace scallop::test {
namespace {

const std::string kToolsJob = R"({
  "tools": {"1": {"type": "ball", "radius": 1.0}, "2": {"type": "flat", "radius": 0.5}},
  "stock": {"min": [0, 0, -2], "max": [4, 4, 0]},
  "grid":  {"spacing": 0.1},
  "path":  {"file": "p.nc"}
})";
const std::string kMachineJob = R"({
  "tool":  {"type": "ball", "radius": 1.0},
  "machine": {"kinematics": "xyzbc-trt"},
  "stock": {"min": [0, 0, -2], "max": [4, 4, 0]},
  "grid":  {"spacing": 0.1},
  "path":  {"file": "p.nc"}
})";

BadInputRow program(const std::string& name, const std::string& text,
                    std::vector<std::string> mentions, const std::string& job = kToolsJob) {
  return {name,
          {{"job.json", job}, {"p.nc", text}},
          "simulate @/job.json -o @/out",
          1,
          std::move(mentions)};
}

BadInputRow job(const std::string& name, const std::string& text,
                std::vector<std::string> mentions) {
  return {name,
          {{"job.json", text}, {"p.nc", "T1 M6\nG0 X0 Y0 Z1\nG1 X1\n"}},
          "simulate @/job.json -o @/out",
          1,
          std::move(mentions)};
}

const std::string kStart = "%\nO1000\nG21 G90 T1 M6\nG0 X0 Y0 Z1\n";  // lines 1-4

TEST_F(BadInputMatrix, GcodePrograms) {
  const std::vector<BadInputRow> rows = {
      program("unknown G word", kStart + "G12 X1\n", {"p.nc:5", "unsupported G-word G12"}),
      program("cutter compensation", kStart + "G41 D1\nG1 X1\n", {"p.nc:5", "G41"}),
      program("T missing from tools", kStart + "T5 M6\n", {"p.nc:5", "T5", "\"tools\""}),
      program("mixed units", kStart + "G1 X1\nG20\n", {"p.nc:6", "mixed units"}),
      program("variable", kStart + "#1=2\n", {"p.nc:5", "parameters"}),
      program("subprogram call", kStart + "M98 P1000\n", {"p.nc:5", "M98"}),
      program("O-word subprogram", kStart + "O100 sub\n", {"p.nc:5", "O-word"}),
      program("back boring", kStart + "G87 X1 Z-1 R1\n", {"p.nc:5", "G87"}),
      program("no tool in the spindle", "G0 X0 Y0 Z1\nG1 X1\n", {"p.nc:2", "no tool"}),
      program("rotary word without a machine", kStart + "G1 X1 B5\n",
              {"p.nc:5", "rotary word B5", "\"machine\""}),
      program("tilt below the horizontal", "G43.4\nG0 X0 Y0 Z1 B120\n",
              {"p.nc:2", "below the horizontal"}, kMachineJob),
      program("A on a BC machine", "G43.4\nG0 X0 Y0 Z1 A10\n", {"p.nc:2", "rotary word A"},
              kMachineJob),
      program("teeth with a TCP-off turning move", "S1000\nG0 X0 Y0 Z1\nG1 X1 B10 F200\n",
              {"p.nc:3", "TCP off", "teeth"},
              replaced(kMachineJob, "{\n", "{\"cutting\": {\"model\": \"teeth\"},\n")),
  };
  for (const BadInputRow& row : rows) check(row);
}

TEST_F(BadInputMatrix, GcodeJobKeys) {
  const std::vector<BadInputRow> rows = {
      job("tool and tools",
          replaced(kToolsJob, "\"tools\"",
                   "\"tool\": {\"type\": \"ball\", "
                   "\"radius\": 1}, \"tools\""),
          {"tools", "not both"}),
      job("tools key not a number", replaced(kToolsJob, "\"1\"", "\"one\""), {"tools.one"}),
      job("tools key zero-padded", replaced(kToolsJob, "\"1\"", "\"01\""), {"tools.01"}),
      job("tools cutter invalid", replaced(kToolsJob, "\"radius\": 0.5", "\"radius\": -1"),
          {"tools.2.radius"}),
      job("tools cutter flutes",
          replaced(kToolsJob, "\"radius\": 0.5", "\"radius\": 0.5, \"flutes\": 0"),
          {"tools.2.flutes", "1 to 16"}),
      job("tools cutter runout",
          replaced(kToolsJob, "\"radius\": 0.5", "\"radius\": 0.5, \"runout_mm\": 0.1"),
          {"tools.2.runout_mm", "0.05"}),
      job("tools empty",
          replaced(kToolsJob,
                   R"("1": {"type": "ball", "radius": 1.0}, "2": {"type": "flat", "radius": 0.5})",
                   ""),
          {"tools", "at least one"}),
      job("raster with tools",
          replaced(kToolsJob, R"({"file": "p.nc"})",
                   R"({"raster": {"direction": "x", "step_over": 0.8, "depth": 0.3}})"),
          {"tool", "\"tools\""}),
      job("work offset G60",
          replaced(kToolsJob, "{\n", "{\"work_offsets\": {\"G60\": [0, 0, 0]},\n"),
          {"work_offsets.G60", "unknown key"}),
      job("work offset of two numbers",
          replaced(kToolsJob, "{\n", "{\"work_offsets\": {\"G55\": [0, 0]},\n"),
          {"work_offsets.G55"}),
      job("block delete not a boolean", replaced(kToolsJob, "{\n", "{\"block_delete\": 1,\n"),
          {"block_delete", "true or false"}),
      {"tools with a file without tool changes",
       {{"job.json", replaced(kToolsJob, "p.nc", "p.txt")}, {"p.txt", "0 0 -0.2\n1 0 -0.2\n"}},
       "simulate @/job.json -o @/out",
       1,
       {"tools", "no tool changes"}},
      job("machine kinematics", replaced(kMachineJob, "xyzbc-trt", "xyzbc-hh"),
          {"machine.kinematics", "xyzbc-trt"}),
      job("machine TCP code",
          replaced(kMachineJob, "\"xyzbc-trt\"", "\"xyzbc-trt\", \"tcp_on\": [\"TCP\"]"),
          {"machine.tcp_on"}),
      job("machine unknown key",
          replaced(kMachineJob, "\"xyzbc-trt\"", "\"xyzbc-trt\", \"speed\": 1"),
          {"machine.speed", "unknown key"}),
  };
  for (const BadInputRow& row : rows) check(row);
}

}  // namespace
}  // namespace scallop::test
