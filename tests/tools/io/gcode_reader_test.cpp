// G-code reader (tools/io/gcode_reader.h): motion, units, distance modes, arcs against
// their closed-form circles, and malformed input named by line.
#include "tools/io/gcode_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "base/constants.h"
#include "base/input_error.h"
#include "tests/support/input_error_message.h"

namespace scallop {
namespace {

// `chordTolerance` > 0: arcs as chords (the --arc-chords baseline) within it; 0: each
// arc one exact move (the default).
ToolPathFile parse(const std::string& text, double chordTolerance = 0) {
  std::istringstream in(text);
  ToolPathFile out;
  PathFileOptions options;
  options.arcChords = chordTolerance > 0;
  if (chordTolerance > 0) options.arcTolerance = chordTolerance;
  readGcode(in, "t.nc", options, out);
  return out;
}

// The message of the InputError `text` raises ("" when it parses).
std::string error(const std::string& text) {
  return inputErrorMessage([&] { parse(text); });
}

TEST(GcodeReader, LinearRapidUnitsAndIncrementalMoves) {
  const ToolPathFile f = parse(
      "%\n(program) G21 G90 G17\nG0 X0 Y0 Z5\nG1 Z-1 F300 ; plunge\nX10\nG91 Y2.5\nG90 G0 Z5\n"
      "%\n");
  ASSERT_EQ(f.path.moves.size(), 4u);
  EXPECT_FALSE(f.path.moves[0].rapid);
  EXPECT_EQ(f.path.moves[0].to.tip, (Vec3{0, 0, -1}));
  EXPECT_EQ(f.moveLines[0], 4);
  EXPECT_EQ(f.path.moves[1].to.tip, (Vec3{10, 0, -1}));  // modal G1
  EXPECT_EQ(f.path.moves[2].to.tip, (Vec3{10, 2.5, -1}));
  EXPECT_EQ(f.moveLines[2], 6);
  EXPECT_TRUE(f.path.moves[3].rapid);
  EXPECT_EQ(f.path.moves[3].to.axis, (Vec3{0, 0, 1}));
}

TEST(GcodeReader, InchesAreConvertedToMillimetres) {
  const ToolPathFile f = parse("G20\nG0 X0 Y0 Z0\nG1 X1 Y-0.5\n");
  ASSERT_EQ(f.path.moves.size(), 1u);
  EXPECT_DOUBLE_EQ(f.path.moves[0].to.tip.x, 25.4);
  EXPECT_DOUBLE_EQ(f.path.moves[0].to.tip.y, -12.7);
}

// Every chord end lies on the true circle and no chord's midpoint is farther from it
// than the tolerance (sagitta); the sweep angle and direction are the G-code's.
void expectOnCircle(const ToolPathFile& f, double cx, double cy, double radius, double tol) {
  for (const Move& mv : f.path.moves) {
    const Vec3 p = mv.to.tip, m = (mv.from.tip + mv.to.tip) * 0.5;
    EXPECT_NEAR(std::hypot(p.x - cx, p.y - cy), radius, 1e-12);
    const double sag = radius - std::hypot(m.x - cx, m.y - cy);
    EXPECT_GE(sag, 0);
    EXPECT_LE(sag, tol);
  }
}

TEST(GcodeReader, FullCircleG2IsChordedWithinTheTolerance) {
  const double tol = 1e-4, radius = 5;
  const ToolPathFile f = parse("G0 X5 Y0 Z-1\nG2 X5 Y0 I-5 J0\n", tol);
  // n = ceil(2 pi / (2 acos(1 - tol / r))) chords.
  const int n = int(std::ceil(2 * kPi / (2 * std::acos(1 - tol / radius))));
  ASSERT_EQ(int(f.path.moves.size()), n);
  expectOnCircle(f, 0, 0, radius, tol);
  // Clockwise seen from +Z: from (5, 0) the first step goes towards -y.
  EXPECT_LT(f.path.moves[0].to.tip.y, 0);
  EXPECT_EQ(f.path.moves.back().to.tip, (Vec3{5, 0, -1}));
  for (int64_t line : f.moveLines) EXPECT_EQ(line, 2);
}

TEST(GcodeReader, RadiusFormPicksTheShortOrLongArc) {
  // Quarter circle counter-clockwise from (1, 0) to (0, 1) about the origin.
  const ToolPathFile shortArc = parse("G0 X1 Y0 Z0\nG3 X0 Y1 R1\n", 1e-4);
  expectOnCircle(shortArc, 0, 0, 1, 1e-4);
  EXPECT_GT(shortArc.path.moves[0].to.tip.x, 0);
  // R < 0: the three-quarter arc, about (1, 1).
  const ToolPathFile longArc = parse("G0 X1 Y0 Z0\nG3 X0 Y1 R-1\n", 1e-4);
  expectOnCircle(longArc, 1, 1, 1, 1e-4);
  EXPECT_GT(longArc.path.moves.size(), 2 * shortArc.path.moves.size());
}

// The exact arc of one move: its centre, radius, start angle and sweep.
void expectArc(const ToolPathFile& f, size_t move, const Vec3& centre, double radius, double angle0,
               double sweep, double rise) {
  ASSERT_LT(move, f.path.moves.size());
  const Move& m = f.path.moves[move];
  ASSERT_GT(m.arc, 0u);
  const ArcMotion& a = f.path.arcs.at(m.arc - 1);
  EXPECT_LT(length(a.centre - centre), 1e-12);
  EXPECT_NEAR(a.radius0, radius, 1e-12);
  EXPECT_NEAR(a.radius1, radius, 1e-12);
  EXPECT_NEAR(a.angle0, angle0, 1e-12);
  EXPECT_NEAR(a.sweep, sweep, 1e-12);
  EXPECT_NEAR(a.rise, rise, 1e-12);
  EXPECT_LT(length(a.at(0) - m.from.tip), 1e-12);
  EXPECT_LT(length(a.at(1) - m.to.tip), 1e-12);
}

TEST(GcodeReader, ArcsAreSingleExactMovesInEveryPlaneAndForm) {
  // IJK and R forms, short and long, in G17; a full circle; helices in G18 and G19.
  const ToolPathFile f = parse(
      "G0 X1 Y0 Z0\nG3 X0 Y1 R1\nG0 X1 Y0\nG3 X0 Y1 R-1\nG0 X5 Y0 Z-1\nG2 X5 Y0 I-5 J0\n"
      "G18\nG0 X2 Y0 Z0\nG2 X-2 Y2 Z0 I-2 K0\nG19\nG0 X0 Y0 Z3\nG3 X-1 Y0 Z-3 J0 K-3\n");
  ASSERT_EQ(f.path.arcs.size(), 5u);
  expectArc(f, 0, {0, 0, 0}, 1, 0, kPi / 2, 0);
  expectArc(f, 2, {1, 1, 0}, 1, -kPi / 2, 1.5 * kPi, 0);
  expectArc(f, 4, {0, 0, -1}, 5, 0, -2 * kPi, 0);  // G2 from (5, 0): clockwise, whole
  EXPECT_EQ(f.path.moves[4].from.tip, f.path.moves[4].to.tip);
  // G18: u = z, v = x, the normal y: from (z, x) = (0, 2) to (0, -2) clockwise, y 0 -> 2.
  expectArc(f, 6, {0, 0, 0}, 2, kPi / 2, -kPi, 2);
  // G19: u = y, v = z, the normal x: from (y, z) = (0, 3) to (0, -3) counter-clockwise.
  expectArc(f, 8, {0, 0, 0}, 3, kPi / 2, kPi, -1);
  for (const Move& m : f.path.moves) EXPECT_EQ(m.arc > 0, !m.rapid);
}

TEST(GcodeReader, HelixInG18MovesYLinearly) {
  // ZX plane: centre offset K (z) and I (x); half circle with y rising 0 -> 2.
  const ToolPathFile f = parse("G18\nG0 X2 Y0 Z0\nG2 X-2 Y2 Z0 I-2 K0\n", 1e-4);
  const size_t n = f.path.moves.size();
  ASSERT_GT(n, 10u);
  for (size_t k = 0; k < n; ++k) {
    const Vec3 p = f.path.moves[k].to.tip;
    EXPECT_NEAR(std::hypot(p.x, p.z), 2, 1e-12);
    EXPECT_NEAR(p.y, 2.0 * double(k + 1) / double(n), 1e-12);
  }
}

TEST(GcodeReader, MalformedInputIsNamedByLine) {
  const std::string start = "G21\nG0 X0 Y0 Z0\n";
  EXPECT_NE(error(start + "G1 X1.2.3\n").find("t.nc:3"), std::string::npos);
  EXPECT_NE(error(start + "G43.7\n").find("t.nc:3: unsupported G-word G43.7"), std::string::npos);
  // Numbers beyond int (a fuzzer finding: the conversion was undefined behaviour).
  EXPECT_NE(error(start + "G99999999999\n").find("t.nc:3: unsupported G-word G1e+11"),
            std::string::npos);
  EXPECT_NE(error(start + "M-99999999999\n").find("t.nc:3: unsupported M-word"), std::string::npos);
  EXPECT_NE(error(start + "G1 X\n").find("t.nc:3: word X has no number"), std::string::npos);
  EXPECT_NE(error(start + "G1 Xnan\n").find("t.nc:3"), std::string::npos);
  // An exponent is named as written, not as a word E (G-code numbers have none).
  const std::string exponent = error(start + "G1 X1e300\n");
  EXPECT_NE(exponent.find("t.nc:3: \"X1e300\": G-code numbers have no exponent"),
            std::string::npos)
      << exponent;
  EXPECT_EQ(exponent.find("unsupported word"), std::string::npos) << exponent;
  EXPECT_NE(error(start + "G1 X0 Y2E5\n").find("t.nc:3: \"Y2E5\": G-code numbers have no exponent"),
            std::string::npos);
  EXPECT_NE(error(start + "G1 x-1.5e-3 (a comment 2e5)\n").find("\"x-1.5e-3\": G-code numbers"),
            std::string::npos);
  // An E word after a space is a word, refused as one; "G1X2" is two words.
  EXPECT_NE(error(start + "G1 X1 E5\n").find("t.nc:3: unsupported word E5"), std::string::npos);
  EXPECT_EQ(error(start + "G1X2Y1\n"), "");
  EXPECT_NE(error(start + "G1 X1\nG20\n").find("t.nc:4: mixed units"), std::string::npos);
  EXPECT_NE(error(start + "G2 X2 Y0 I1.5 J0\n").find("t.nc:3: arc radii differ"),
            std::string::npos);
  EXPECT_NE(error(start + "G2 X4 Y0 R1\n").find("t.nc:3"), std::string::npos);
  EXPECT_NE(error(start + "G1 A10\n").find("t.nc:3: rotary word A10: the job has no \"machine\""),
            std::string::npos);
  EXPECT_NE(error(start + "G1 U10\n").find("t.nc:3: unsupported word U10"), std::string::npos);
  EXPECT_NE(error(start + "G1 X1 X2\n").find("t.nc:3: word X appears twice"), std::string::npos);
  EXPECT_NE(error(start + "G1 X1 (unclosed\n").find("t.nc:3"), std::string::npos);
  EXPECT_NE(error("G1 X1 Y1 Z1\n").find("t.nc:1: cutting move from an unknown position"),
            std::string::npos);
  EXPECT_NE(error("G20 G21\n").find("t.nc:1"), std::string::npos);
  EXPECT_NE(error("(nothing)\n").find("no moves"), std::string::npos);
  EXPECT_EQ(error(start + "G1 X1 M3 S1000 F200 (ok)\n"), "");
}

}  // namespace
}  // namespace scallop
