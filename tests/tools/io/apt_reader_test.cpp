// APT / CL data reader (tools/io/apt_reader.h): statements, continuation lines, cutters,
// units, warnings for unknown statements and errors named by line.
#include "tools/io/apt_reader.h"

#include <gtest/gtest.h>

#include <sstream>

#include "base/input_error.h"
#include "tests/support/input_error_message.h"

namespace scallop {
namespace {

ToolPathFile parse(const std::string& text) {
  std::istringstream in(text);
  ToolPathFile out;
  readApt(in, "t.cl", out);
  return out;
}

std::string error(const std::string& text) {
  return inputErrorMessage([&] { parse(text); });
}

TEST(AptReader, MovesRapidsAxesAndContinuationLines) {
  const ToolPathFile f = parse(
      "PARTNO/TEST $$ a comment\n"
      "CUTTER/6.0,1.0\n"
      "MULTAX\n"
      "FROM/0,0,10\n"
      "RAPID\n"
      "GOTO/1,2,3\n"
      "goto/4, 5, $\n"
      "  6\n"
      "FEDRAT/300,MMPM\n"
      "GOTO/4,5,7,0,0.6,0.8\n"
      "CIRCLE/0,0,0,0,0,1,5\n"
      "FINI\n");
  ASSERT_EQ(f.path.moves.size(), 3u);
  EXPECT_TRUE(f.path.moves[0].rapid);
  EXPECT_EQ(f.path.moves[0].from.tip, (Vec3{0, 0, 10}));
  EXPECT_FALSE(f.path.moves[1].rapid);
  EXPECT_EQ(f.path.moves[1].to.tip, (Vec3{4, 5, 6}));
  EXPECT_EQ(f.moveLines[1], 7);  // a continued statement is named by its first line
  EXPECT_EQ(f.path.moves[2].to.axis, (Vec3{0, 0.6, 0.8}));
  EXPECT_EQ(f.moveLines[2], 10);
  ASSERT_TRUE(f.cutter.has_value());
  EXPECT_EQ(f.cutter->type, CutterType::Bull);
  EXPECT_EQ(f.cutter->radius, 3.0);
  EXPECT_EQ(f.cutter->cornerRadius, 1.0);
  // The unknown CIRCLE statement is reported, never silently dropped.
  ASSERT_EQ(f.warnings.total, 1u);
  EXPECT_NE(f.warnings.kept[0].find("t.cl:11: unknown statement \"CIRCLE\""), std::string::npos);
}

TEST(AptReader, CutterFormsAndInches) {
  EXPECT_EQ(parse("CUTTER/6\nGOTO/0,0,0\n").cutter->type, CutterType::Flat);
  EXPECT_EQ(parse("CUTTER/6,3\nGOTO/0,0,0\n").cutter->type, CutterType::Ball);
  const ToolPathFile seven = parse("CUTTER/6,1,2,1,0,0,30\nGOTO/0,0,0\n");
  EXPECT_EQ(seven.cutter->fluteLength, 30.0);
  const ToolPathFile inches = parse("UNITS/INCHES\nCUTTER/0.5\nGOTO/0,0,0\nGOTO/1,0,0\n");
  EXPECT_DOUBLE_EQ(inches.cutter->radius, 6.35);
  EXPECT_DOUBLE_EQ(inches.path.moves[0].to.tip.x, 25.4);
}

TEST(AptReader, MalformedInputIsNamedByLine) {
  EXPECT_NE(error("GOTO/1,2\n").find("t.cl:1: GOTO expects 3 values"), std::string::npos);
  EXPECT_NE(error("GOTO/0,0,0\nGOTO/1,x,2\n").find("t.cl:2: y: expected a finite decimal"),
            std::string::npos);
  EXPECT_NE(error("GOTO/0,0,0\nGOTO/1,nan,2\n").find("t.cl:2"), std::string::npos);
  EXPECT_NE(error("GOTO/0,0,0\nGOTO/1,0,$\n").find("t.cl:2: the statement continues"),
            std::string::npos);
  EXPECT_NE(error("GOTO/0,0,0,0,0,0\n").find("t.cl:1: the tool axis"), std::string::npos);
  EXPECT_NE(error("GOTO/0,0,0\nGOTO/1,0,0\nUNITS/INCHES\n").find("t.cl:3: mixed units"),
            std::string::npos);
  EXPECT_NE(error("CUTTER/6,4\nGOTO/0,0,0\n").find("t.cl:1"), std::string::npos);
  EXPECT_NE(error("LOADTL/x\nGOTO/0,0,0\n").find("t.cl:1: LOADTL expects a tool number"),
            std::string::npos);
  EXPECT_NE(error("1 2 3\n").find("t.cl:1: expected an APT statement"), std::string::npos);
  EXPECT_NE(error("PARTNO/X\n").find("no GOTO"), std::string::npos);
}

// A new CUTTER/ is a new tool for the moves after it; the same one again is not.
TEST(AptReader, EachCutterCutsTheMovesAfterIt) {
  const ToolPathFile f = parse(
      "LOADTL/4\nCUTTER/6\nGOTO/0,0,0\nGOTO/1,0,0\nCUTTER/2,1\nGOTO/2,0,0\nCUTTER/6\n"
      "GOTO/3,0,0\n");
  ASSERT_EQ(f.path.cutters.size(), 2u);
  EXPECT_EQ(f.path.cutters[0].type, CutterType::Flat);
  EXPECT_EQ(f.path.cutters[1].type, CutterType::Ball);
  EXPECT_EQ(f.toolNumbers, (std::vector<int64_t>{4, 2}));  // LOADTL's number, then the order
  ASSERT_EQ(f.path.moves.size(), 3u);
  EXPECT_EQ(f.path.moves[0].tool, 0);
  EXPECT_EQ(f.path.moves[1].tool, 1);
  EXPECT_EQ(f.path.moves[2].tool, 0);
  // One cutter throughout: a single-tool file, as before.
  EXPECT_TRUE(parse("CUTTER/6\nGOTO/0,0,0\nCUTTER/6\nGOTO/1,0,0\n").path.cutters.empty());
}

TEST(AptReader, LoadtlPicksTheJobsTools) {
  PathFileOptions o;
  o.tools[1] = Cutter::make(CutterType::Ball, 1);
  o.tools[2] = Cutter::make(CutterType::Flat, 3);
  auto read = [&](const std::string& text) {
    std::istringstream in(text);
    ToolPathFile out;
    readApt(in, "t.cl", o, out);
    return out;
  };
  const ToolPathFile f = read("LOADTL/2\nGOTO/0,0,0\nGOTO/1,0,0\nLOADTL/1\nGOTO/2,0,0\n");
  EXPECT_EQ(f.toolNumbers, (std::vector<int64_t>{2, 1}));
  EXPECT_EQ(f.path.moves[0].tool, 0);
  EXPECT_EQ(f.path.moves[1].tool, 1);
  EXPECT_EQ(f.path.cutters[0].radius, 3);
  EXPECT_NE(inputErrorMessage([&] {
              read("GOTO/0,0,0\nLOADTL/3\n");
            }).find("t.cl:2: LOADTL/3: tool 3 is not in the job's \"tools\" (it has 1, 2)"),
            std::string::npos);
  EXPECT_NE(inputErrorMessage([&] {
              read("GOTO/0,0,0\nGOTO/1,0,0\n");
            }).find("t.cl:2: a cutting move before any LOADTL/"),
            std::string::npos);
}

}  // namespace
}  // namespace scallop
