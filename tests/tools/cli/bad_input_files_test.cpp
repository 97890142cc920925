// Bad-input matrix, part 2: binary inputs: STL surfaces (gouge, and a job's design
// STL) and height maps (stats, export; GSF and OpenEXR). See bad_input_matrix.h.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "tests/tools/cli/bad_input_matrix.h"

namespace scallop::test {
namespace {

void putU32(std::string& s, uint32_t v) {
  for (int k = 0; k < 4; ++k) s += char((v >> (8 * k)) & 0xff);
}
void putF32(std::string& s, float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  putU32(s, u);
}

// A binary STL of `tris` triangles, each with the given vertices (9 floats).
std::string binaryStl(const std::vector<std::vector<float>>& tris, uint32_t declared) {
  std::string s(80, ' ');
  putU32(s, declared);
  for (const auto& t : tris) {
    for (int k = 0; k < 3; ++k) putF32(s, 0);
    for (float v : t) putF32(s, v);
    s += std::string(2, '\0');
  }
  return s;
}
const std::vector<float> kTri = {0, 0, 0, 1, 0, 0, 0, 1, 0};

std::string asciiStl(const std::string& vertex2) {
  return "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n" + vertex2 +
         "\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n";
}

// A GSF header (with its NUL padding) followed by `values`.
std::string gsf(const std::string& fields, const std::vector<float>& values) {
  std::string s = "Gwyddion Simple Field 1.0\n" + fields;
  s += std::string(4 - s.size() % 4, '\0');
  for (float v : values) putF32(s, v);
  return s;
}
const std::string kGsfFields =
    "XRes = 2\nYRes = 2\nXReal = 2e-4\nYReal = 2e-4\nXYUnits = m\nZUnits = m\n";

const std::string kGarbage("\x89\x00\xff\x13solid\x01\x7f\xfe\n\x1b[2J", 15);

BadInputRow stlRow(const std::string& name, const std::string& bytes,
                   std::vector<std::string> mentions) {
  return {name,
          {{"s.stl", bytes}},
          "gouge @/s.stl --radius 1 --length 5 -o @/out",
          1,
          std::move(mentions)};
}

TEST_F(BadInputMatrix, StlSurfaces) {
  const std::vector<BadInputRow> rows = {
      stlRow("empty file", "", {"@/s.stl"}),
      stlRow("binary garbage", kGarbage, {"@/s.stl"}),
      stlRow("truncated binary", binaryStl({kTri, kTri}, 2).substr(0, 150),
             {"@/s.stl", "truncated"}),
      stlRow("count larger than the file", binaryStl({kTri}, 4000000000u), {"@/s.stl"}),
      stlRow("NaN vertex (binary)", binaryStl({{0, 0, 0, std::nanf(""), 0, 0, 0, 1, 0}}, 1),
             {"@/s.stl", "triangle 1"}),
      stlRow("huge vertex (binary, inf)",
             binaryStl({{0, 0, 0, std::numeric_limits<float>::infinity(), 0, 0, 0, 1, 0}}, 1),
             {"@/s.stl", "triangle 1"}),
      stlRow("NaN vertex (ASCII)", asciiStl("vertex nan 0 0"), {"@/s.stl:5"}),
      stlRow("number beyond double (ASCII)", asciiStl("vertex 1e400 0 0"), {"@/s.stl:5"}),
      stlRow("truncated ASCII", asciiStl("vertex 1 0 0").substr(0, 60), {"@/s.stl:"}),
      stlRow("four vertices (ASCII)", asciiStl("vertex 1 0 0\nvertex 1 1 0"), {"@/s.stl:"}),
      stlRow("only degenerate triangles", binaryStl({{0, 0, 0, 1, 1, 1, 2, 2, 2}}, 1),
             {"@/s.stl", "degenerate"}),
      stlRow("no triangles", binaryStl({}, 0), {"@/s.stl"}),
      {"missing file", {}, "gouge @/none.stl --radius 1 --length 5", 1, {"@/none.stl"}},
      {"a folder", {{"d.stl/x", ""}}, "gouge @/d.stl --radius 1 --length 5", 1, {"@/d.stl"}},
  };
  for (const BadInputRow& row : rows) check(row);
}

BadInputRow mapRow(const std::string& name, const std::string& file, const std::string& bytes,
                   std::vector<std::string> mentions) {
  return {name, {{file, bytes}}, "stats @/" + file, 1, std::move(mentions)};
}

TEST_F(BadInputMatrix, HeightMaps) {
  const std::vector<BadInputRow> rows = {
      mapRow("empty GSF", "h.gsf", "", {"@/h.gsf"}),
      mapRow("garbage GSF", "h.gsf", kGarbage, {"@/h.gsf"}),
      mapRow("truncated GSF data", "h.gsf", gsf(kGsfFields, {0, 0, 0}), {"@/h.gsf", "bytes"}),
      mapRow("GSF header without NUL", "h.gsf", "Gwyddion Simple Field 1.0\nXRes = 2\n",
             {"@/h.gsf"}),
      mapRow("GSF zero size", "h.gsf", gsf("XRes = 0\nYRes = 2\n", {}), {"@/h.gsf", "XRes"}),
      mapRow("GSF negative size", "h.gsf", gsf("XRes = -2\nYRes = 2\n", {}), {"@/h.gsf"}),
      mapRow("GSF huge size", "h.gsf", gsf("XRes = 2000000000\nYRes = 2000000000\n", {0}),
             {"@/h.gsf"}),
      mapRow("GSF NaN extent", "h.gsf",
             gsf("XRes = 2\nYRes = 2\nXReal = nan\nYReal = nan\n", {0, 0, 0, 0}), {"@/h.gsf"}),
      mapRow("GSF not a header line", "h.gsf", gsf("XRes 2\n", {}), {"@/h.gsf:2"}),
      mapRow("GSF unknown unit", "h.gsf", gsf(kGsfFields + "ZUnits = furlong\n", {0, 0, 0, 0}),
             {"@/h.gsf", "ZUnits"}),
      mapRow("empty EXR", "h.exr", "", {"@/h.exr"}),
      mapRow("garbage EXR", "h.exr", kGarbage, {"@/h.exr"}),
      mapRow("EXR magic, then nothing", "h.exr", std::string("\x76\x2f\x31\x01\x02\0\0\0", 8),
             {"@/h.exr"}),
      {"missing map", {}, "stats @/none.gsf", 1, {"@/none.gsf"}},
      {"unknown extension", {{"h.txt", "1 2 3"}}, "stats @/h.txt", 1, {"@/h.txt"}},
      {"export: garbage GSF", {{"h.gsf", kGarbage}}, "export @/h.gsf --to @/o.x3p", 1, {"@/h.gsf"}},
  };
  for (const BadInputRow& row : rows) check(row);
}

// A job's design surface (design.stl) goes through the same STL reader; one row
// shows the message leads with the job file's field.
TEST_F(BadInputMatrix, DesignStlOfAJob) {
  const std::string job = R"({"tool": {"type": "ball", "radius": 1},
    "stock": {"min": [0, 0, -1], "max": [2, 2, 0]}, "grid": {"spacing": 0.1},
    "design": {"stl": "d.stl"},
    "path": {"raster": {"direction": "x", "step_over": 0.8, "depth": 0.2}}})";
  check({"truncated design STL",
         {{"job.json", job}, {"d.stl", binaryStl({kTri, kTri}, 2).substr(0, 150)}},
         "simulate @/job.json -o @/out",
         1,
         {"d.stl", "truncated"}});
}

}  // namespace
}  // namespace scallop::test
