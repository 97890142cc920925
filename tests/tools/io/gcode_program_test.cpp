// G-code as CAM posts write it (tools/io/gcode_reader.h): program structure, modes and
// offsets, tools, canned cycles as their moves, 5-axis machine moves, and the words
// that are refused, each named by its line.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "base/constants.h"
#include "sweep/pose_curve.h"
#include "sweep/tool_path_sweep.h"
#include "tests/support/input_error_message.h"
#include "tools/io/gcode_cycles.h"
#include "tools/io/gcode_reader.h"

namespace scallop {
namespace {

ToolPathFile parse(const std::string& text, const PathFileOptions& options = {}) {
  std::istringstream in(text);
  ToolPathFile out;
  readGcode(in, "p.nc", options, out);
  return out;
}

std::string error(const std::string& text, const PathFileOptions& options = {}) {
  return inputErrorMessage([&] { parse(text, options); });
}

const IgnoredWords::Entry* ignored(const ToolPathFile& f, const std::string& word) {
  for (const IgnoredWords::Entry& e : f.ignored.entries)
    if (e.word == word) return &e;
  return nullptr;
}

// A program as a post writes it: every line but the moves is structure or modes.
const char* kPost =
    "%\n"                              // 1
    "O1000 (FINISH)\n"                 // 2
    "N10 G90 G94 G17 G49 G40 G80\n"    // 3
    "N20 G21\n"                        // 4
    "N30 T1 M6\n"                      // 5
    "N40 S10000 M3\n"                  // 6
    "N50 G54 G0 X-2. Y0.\n"            // 7
    "N60 G43 Z15. H1\n"                // 8
    "N70 M8\n"                         // 9
    "N80 Z5.\n"                        // 10
    "N90 G1 Z-0.25 F500.\n"            // 11
    "N100 X8.\n"                       // 12
    "N110 G0 Z15.\n"                   // 13
    "N120 M9\n"                        // 14
    "N130 G28 G91 Z0.\n"               // 15
    "N140 G90\n"                       // 16
    "N150 M5\n"                        // 17
    "N160 M30\n"                       // 18
    "G1 X100 (after M30: not read)\n"  // 19
    "%\n";                             // 20

TEST(GcodeProgram, APostsProgramRunsAndListsTheWordsItIgnored) {
  const ToolPathFile f = parse(kPost);
  // Cutting moves: the plunge and the pass; rapids to Z5 and Z15 around them.
  ASSERT_EQ(f.path.cuttingMoves(), 2u);
  std::vector<Move> cuts;
  for (const Move& m : f.path.moves)
    if (!m.rapid) cuts.push_back(m);
  EXPECT_EQ(cuts[0].from.tip, (Vec3{-2, 0, 5}));
  EXPECT_EQ(cuts[0].to.tip, (Vec3{-2, 0, -0.25}));
  EXPECT_EQ(cuts[1].to.tip, (Vec3{8, 0, -0.25}));
  for (const char* w :
       {"F", "S", "M3", "M5", "M8", "M9", "G43", "G49", "G40", "G94", "H", "T", "M6", "M30"})
    EXPECT_NE(ignored(f, w), nullptr) << w;
  EXPECT_EQ(ignored(f, "M8")->lines, (std::vector<int64_t>{9}));
  EXPECT_EQ(ignored(f, "F")->lines, (std::vector<int64_t>{11}));
  // G28: a warning with its line, and no move (the intermediate point is here).
  ASSERT_EQ(f.warnings.total, 1u);
  EXPECT_NE(f.warnings.kept[0].find("p.nc:15: G28 (return home)"), std::string::npos);
  for (const Move& m : f.path.moves) EXPECT_NE(m.to.tip.x, 100);
}

TEST(GcodeProgram, AfterG28TheHomedAxisMustBeGivenAgain) {
  EXPECT_NE(error("G0 X0 Y0 Z5\nG28 G91 Z0\nG90 G1 X3\n")
                .find("p.nc:3: cutting move from an "
                      "unknown position"),
            std::string::npos);
  EXPECT_EQ(error("G0 X0 Y0 Z5\nG28 G91 Z0\nG90 G0 Z5\nG1 X3\n"), "");
}

TEST(GcodeProgram, BlockDeleteIsOffByDefault) {
  const std::string program = "G0 X0 Y0 Z1\n/G1 X5\nG1 Y5\n";
  EXPECT_EQ(parse(program).path.moves.size(), 2u);
  PathFileOptions on;
  on.blockDelete = true;
  const ToolPathFile f = parse(program, on);
  ASSERT_EQ(f.path.moves.size(), 1u);
  EXPECT_EQ(f.path.moves[0].to.tip, (Vec3{0, 5, 1}));
}

TEST(GcodeProgram, WorkOffsetsShiftTheProgramAndG53IsTheJobFrame) {
  PathFileOptions o;
  o.workOffsets[0] = {10, 20, -1};  // G54
  o.workOffsets[1] = {-5, 0, 0};    // G55
  const ToolPathFile f = parse("G0 X0 Y0 Z1\nG1 X2\nG55 G1 X2\nG91 X1\nG90 G53 G1 X7 Y8 Z9\n", o);
  ASSERT_EQ(f.path.moves.size(), 4u);
  EXPECT_EQ(f.path.moves[0].to.tip, (Vec3{12, 20, 0}));
  EXPECT_EQ(f.path.moves[1].to.tip, (Vec3{-3, 20, 0}));  // G55: x offset -5, y, z kept
  EXPECT_EQ(f.path.moves[2].to.tip, (Vec3{-2, 20, 0}));  // incremental: no offset
  EXPECT_EQ(f.path.moves[3].to.tip, (Vec3{7, 8, 9}));
}

TEST(GcodeProgram, UnknownMCodesAreWarningsAndG64PToo) {
  const ToolPathFile f = parse("G0 X0 Y0 Z1\nM110\nG64 P0.01\nG1 X1\n");
  ASSERT_EQ(f.warnings.total, 2u);
  EXPECT_NE(f.warnings.kept[0].find("p.nc:2: M-code M110 ignored"), std::string::npos);
  EXPECT_NE(f.warnings.kept[1].find("p.nc:3: G64 P0.01"), std::string::npos);
}

TEST(GcodeProgram, WhatCannotBeSimulatedIsRefusedWithItsLine) {
  const std::string s = "G21 G0 X0 Y0 Z1\n";
  EXPECT_NE(error(s + "G41 D1 G1 X1\n").find("p.nc:2: G41 (cutter radius compensation)"),
            std::string::npos);
  EXPECT_NE(error(s + "G42\n").find("p.nc:2: G42"), std::string::npos);
  EXPECT_NE(error(s + "#1=2\n").find("p.nc:2: parameters"), std::string::npos);
  EXPECT_NE(error(s + "G1 X#1\n").find("p.nc:2: parameters"), std::string::npos);
  EXPECT_NE(error(s + "M98 P100\n").find("p.nc:2: M98 (subprogram"), std::string::npos);
  EXPECT_NE(error(s + "M99\n").find("p.nc:2: M99"), std::string::npos);
  EXPECT_NE(error(s + "O100 sub\n").find("p.nc:2: O-word"), std::string::npos);
  EXPECT_NE(error(s + "o<probe> call\n").find("p.nc:2: O-word"), std::string::npos);
  EXPECT_NE(error(s + "G1 X[1+2]\n").find("p.nc:2: expressions"), std::string::npos);
  EXPECT_NE(error(s + "G92 X0\n").find("p.nc:2: G92"), std::string::npos);
  EXPECT_NE(error(s + "G87 X1 Z-1 R1\n").find("p.nc:2: G87"), std::string::npos);
  EXPECT_NE(error(s + "G12\n").find("p.nc:2: unsupported G-word G12"), std::string::npos);
  EXPECT_NE(error(s + "G1 X1\nG20\n").find("p.nc:3: mixed units"), std::string::npos);
  EXPECT_NE(error(s + "G0 G1 X1\n").find("p.nc:2: two motion words"), std::string::npos);
  EXPECT_NE(error(s + "G80 X1\n").find("p.nc:2: axis words with G80"), std::string::npos);
  EXPECT_NE(error(s + "G18 G81 Z-1 R1\n").find("p.nc:2: G81: drilling cycles are read in G17"),
            std::string::npos);
  EXPECT_NE(error(s + "G81 X1 Z2 R1\n").find("p.nc:2: G81: the hole bottom"), std::string::npos);
  EXPECT_NE(error(s + "G83 X1 Z-2 R1\n").find("p.nc:2: G83 needs a peck depth Q"),
            std::string::npos);
  EXPECT_NE(error(s + "G81 X1 Z-2\n").find("p.nc:2: G81 needs Z"), std::string::npos);
  // A hang-sized cycle is refused before its moves are made.
  EXPECT_NE(error(s + "G83 X1 Z-2 R1 Q0.000001\n").find("p.nc:2: G83: more than a million moves"),
            std::string::npos);
  EXPECT_NE(error(s + "G73 X1 Z-2 R1 Q0.01 L10000\n").find("p.nc:2: G73: more than a million"),
            std::string::npos);
  EXPECT_EQ(error("O1000\n%\n" + s + "G1 X1\n%\n"), "");
}

// --- Tools. -------------------------------------------------------------------------

PathFileOptions twoTools() {
  PathFileOptions o;
  o.tools[1] = Cutter::make(CutterType::Ball, 1);
  o.tools[7] = Cutter::make(CutterType::Flat, 2);
  return o;
}

TEST(GcodeProgram, EveryMoveCutsWithTheToolInTheSpindle) {
  const ToolPathFile f =
      parse("T7 M6\nG0 X0 Y0 Z1\nG1 X1\nT1\nG1 X2\nM6\nG1 X3\nG0 Z5\nT7 M6\nG1 Z0\n", twoTools());
  ASSERT_EQ(f.toolNumbers, (std::vector<int64_t>{7, 1}));
  ASSERT_EQ(f.path.cutters.size(), 2u);
  EXPECT_EQ(f.path.cutters[0].type, CutterType::Flat);
  EXPECT_EQ(f.path.cutters[1].type, CutterType::Ball);
  std::vector<int> tools;
  for (const Move& m : f.path.moves)
    if (!m.rapid) tools.push_back(m.tool);
  // T1 alone only selects: X2 is still cut by T7; M6 loads T1.
  EXPECT_EQ(tools, (std::vector<int>{0, 0, 1, 0}));
  const std::vector<SweptMove> swept = sweepToolPath(f.path.cutters, f.path);
  EXPECT_EQ(swept.size(), 3u);  // X1 and X2 are collinear with one cutter: merged
  EXPECT_EQ(swept[1].cutter().type, CutterType::Ball);
}

TEST(GcodeProgram, ToolsAreCheckedAgainstTheJob) {
  EXPECT_NE(error("G0 X0 Y0 Z1\nT3 M6\n", twoTools())
                .find("p.nc:2: T3 is not in the job's "
                      "\"tools\" (it has 1, 7)"),
            std::string::npos);
  EXPECT_NE(error("G0 X0 Y0 Z1\nG1 X1\n", twoTools()).find("p.nc:2: cutting move with no tool"),
            std::string::npos);
  EXPECT_NE(error("M6\n", twoTools()).find("p.nc:1: M6"), std::string::npos);
  // One tool in "tools": it is the spindle's from the start.
  PathFileOptions one;
  one.tools[4] = Cutter::make(CutterType::Ball, 1);
  EXPECT_EQ(parse("G0 X0 Y0 Z1\nG1 X1\n", one).toolNumbers, (std::vector<int64_t>{4}));
}

// --- Canned cycles: the moves of LinuxCNC's cycles, closed form. ----------------------

struct Step {
  Vec3 to;
  bool rapid;
};

std::vector<Step> steps(const ToolPathFile& f) {
  std::vector<Step> out;
  for (const Move& m : f.path.moves) out.push_back({m.to.tip, m.rapid});
  return out;
}

void expectSteps(const std::string& program, const std::vector<Step>& want) {
  SCOPED_TRACE(program);
  const std::vector<Step> got = steps(parse(program));
  ASSERT_EQ(got.size(), want.size());
  for (size_t k = 0; k < got.size(); ++k) {
    EXPECT_EQ(got[k].to, want[k].to) << k;
    EXPECT_EQ(got[k].rapid, want[k].rapid) << k;
  }
}

TEST(GcodeProgram, DrillingCyclesMakeTheirMoves) {
  const std::string start = "G0 X0 Y0 Z10\n";
  // G81, G98: rapid over the hole, to R, feed to Z, rapid back to the initial level.
  expectSteps(start + "G98 G81 X5 Y2 Z-3 R1 F100\n",
              {{{5, 2, 10}, true}, {{5, 2, 1}, true}, {{5, 2, -3}, false}, {{5, 2, 10}, true}});
  // G99 retracts to R; a modal repeat drills the next hole from there.
  expectSteps(start + "G99 G82 X5 Y2 Z-3 R1 P0.5\nX7\nG80\n", {{{5, 2, 10}, true},
                                                               {{5, 2, 1}, true},
                                                               {{5, 2, -3}, false},
                                                               {{5, 2, 1}, true},
                                                               {{7, 2, 1}, true},
                                                               {{7, 2, -3}, false},
                                                               {{7, 2, 1}, true}});
  // G85: feed in and out.
  expectSteps(start + "G99 G85 X5 Y2 Z-3 R1\n",
              {{{5, 2, 10}, true}, {{5, 2, 1}, true}, {{5, 2, -3}, false}, {{5, 2, 1}, false}});
  // G73: pecks of Q with a chip-breaking rapid up by kPeckClearance.
  const double c = kPeckClearance;
  expectSteps(start + "G99 G73 X5 Y2 Z-2 R1 Q1.5\n", {{{5, 2, 10}, true},
                                                      {{5, 2, 1}, true},
                                                      {{5, 2, -0.5}, false},
                                                      {{5, 2, -0.5 + c}, true},
                                                      {{5, 2, -2}, false},
                                                      {{5, 2, 1}, true}});
  // G83: out to R after each peck, back down inside the hole, on to the next depth.
  expectSteps(start + "G99 G83 X5 Y2 Z-2 R1 Q1.5\n", {{{5, 2, 10}, true},
                                                      {{5, 2, 1}, true},
                                                      {{5, 2, -0.5}, false},
                                                      {{5, 2, 1}, true},
                                                      {{5, 2, -0.5 + c}, false},
                                                      {{5, 2, -2}, false},
                                                      {{5, 2, 1}, true}});
  // L repeats in G91: R from the current Z, Z from R, X Y steps from hole to hole.
  expectSteps(start + "G91 G99 G81 X2 Z-4 R-9 L2\n", {{{2, 0, 10}, true},
                                                      {{2, 0, 1}, true},
                                                      {{2, 0, -3}, false},
                                                      {{2, 0, 1}, true},
                                                      {{4, 0, 1}, true},
                                                      {{4, 0, -3}, false},
                                                      {{4, 0, 1}, true}});
  // Below R at the start: up to R first.
  expectSteps("G0 X0 Y0 Z-1\nG98 G81 X5 Z-3 R1\n",
              {{{0, 0, 1}, true}, {{5, 0, 1}, true}, {{5, 0, -3}, false}, {{5, 0, 1}, true}});
}

// --- 5-axis machines. ------------------------------------------------------------

PathFileOptions machine(RotaryKinematics kin) {
  PathFileOptions o;
  MachineSpec m;
  m.geometry.kinematics = kin;
  m.geometry.pivot = {1, 2, -3};
  m.geometry.offset = {0.5, 0.25, 4};
  o.machine = m;
  return o;
}

TEST(GcodeProgram, TcpOnMovesAreTheRotaryPoseCurve) {
  const PathFileOptions o = machine(RotaryKinematics::TableBC);
  const ToolPathFile f = parse("G43.4 H1\nG0 X0 Y0 Z1 B0 C0\nG1 X2 B10 C-20\nG1 Y1\n", o);
  ASSERT_EQ(f.path.moves.size(), 2u);
  const Move& turn = f.path.moves[0];
  ASSERT_EQ(turn.rotary, 1u);
  const RotaryMotion& r = f.path.rotary[0];
  EXPECT_TRUE(r.tcp);
  EXPECT_EQ(r.tilt1, degToRad(10));
  EXPECT_EQ(r.spin1, degToRad(-20));
  EXPECT_EQ(turn.to.tip, (Vec3{2, 0, 1}));  // TCP on: X Y Z are the tip
  const PoseCurve curve = PoseCurve::ofMove(f.path, turn);
  const Vec3 half = curve.axis(0.5);
  const double B = degToRad(5), C = degToRad(-10);
  EXPECT_NEAR(half.x, -std::cos(C) * std::sin(B), 1e-15);
  EXPECT_NEAR(half.y, std::sin(C) * std::sin(B), 1e-15);
  // The next move keeps the angles: a constant axis, no rotary motion.
  EXPECT_EQ(f.path.moves[1].rotary, 0u);
  EXPECT_EQ(f.path.moves[1].from.axis, f.path.moves[1].to.axis);
  // One move apart from the path (the design report's gouge finder) keeps its motion.
  const ToolPath one = f.path.single(0);
  const std::vector<SweptMove> swept = sweepToolPath(Cutter::make(CutterType::Ball, 1), one);
  ASSERT_EQ(swept.size(), 1u);
  EXPECT_EQ(swept[0].curve().axis(0.5), half);
}

TEST(GcodeProgram, TcpOffMovesFollowTheForwardKinematics) {
  const PathFileOptions o = machine(RotaryKinematics::TableAC);
  // TCP off at the start; constant angles: a straight move between FK tips, sweepable.
  const ToolPathFile f = parse("G0 X0 Y0 Z1 A15 C30\nG1 X2\nG1 X3 C40\n", o);
  ASSERT_EQ(f.path.moves.size(), 2u);
  const TableMachine& m = o.machine->geometry;
  const double A = degToRad(15), C = degToRad(30);
  EXPECT_EQ(f.path.moves[0].to.tip, machineTip(m, {2, 0, 1}, A, C));
  EXPECT_EQ(f.path.moves[0].rotary, 0u);
  // The angles change with TCP off: the joints move linearly, the tip follows the forward
  // kinematics along a curve (tests/sweep/tcp_off_sweep_test.cpp sweeps such moves).
  EXPECT_FALSE(f.path.rotary.at(0).tcp);
  const PoseCurve curve = PoseCurve::ofMove(f.path, f.path.moves[1]);
  EXPECT_FALSE(curve.linearTip());
  EXPECT_EQ(curve.tip(0.5), machineTip(m, {2.5, 0, 1}, A, degToRad(35)));
  const std::vector<SweptMove> swept = sweepToolPath(Cutter::make(CutterType::Ball, 1), f.path);
  ASSERT_EQ(swept.size(), 2u);
  EXPECT_TRUE(swept[1].turning());
}

TEST(GcodeProgram, RotaryWordsNeedTheirMachine) {
  EXPECT_NE(error("G0 X0 Y0 Z1 B10\n").find("p.nc:1: rotary word B10: the job has no"),
            std::string::npos);
  EXPECT_NE(error("G0 X0 Y0 Z1 A10\n", machine(RotaryKinematics::TableBC))
                .find("p.nc:1: rotary word A: the machine (xyzbc-trt) has axes B and C"),
            std::string::npos);
  EXPECT_NE(error("G43.4\nG0 X0 Y0 Z1 B100\n", machine(RotaryKinematics::TableBC))
                .find("p.nc:2: the tilt 100 deg points the tool below the horizontal"),
            std::string::npos);
  EXPECT_NE(error("G43.4\nG0 X0 Y0 Z1\nG2 X1 Y1 R1 B5\n", machine(RotaryKinematics::TableBC))
                .find("p.nc:3: an arc (G2/G3) cannot move the rotary axes"),
            std::string::npos);
  // Switching TCP changes what X Y Z mean: they must be given again.
  EXPECT_NE(error("G0 X0 Y0 Z1\nG43.4\nG1 X1\n", machine(RotaryKinematics::TableBC))
                .find("p.nc:3: cutting move from an unknown position"),
            std::string::npos);
}

}  // namespace
}  // namespace scallop
