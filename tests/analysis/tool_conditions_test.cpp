// Seed 001 (Sekine) Tables 3 and 4: predominant frictional distance and cutting speed,
// reproduced by analysis/tool_conditions with ap = 0.5 mm, theta = 5 deg.
#include "analysis/tool_conditions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "analysis/seed_tables.h"
#include "base/constants.h"

namespace scallop {
namespace {

constexpr double kTwoDecimals = 0.005;  // half a unit of the printed last digit
constexpr double kDepthOfCut = kSeed001DepthOfCutMm;
constexpr double kInclination = kSeed001InclinationDeg;

// One column of Table 3 (ball) or Table 4 (filleted), as printed.
// Seed 001 Tables 1-4 as printed (analysis/seed_tables.h): ball (Table 3) and filleted
// (Table 4) columns; a filleted column's halfInterval is its Table 2 L/2.
using Column = Seed001Column;
const auto& kTable3 = kSeed001Ball;
const auto& kTable4 = kSeed001Filleted;

void expectNotApplicable(const ToolConditions& c, const std::string& what) {
  EXPECT_FALSE(c.applicable) << what;
  EXPECT_FALSE(c.reason.empty()) << what;
  for (double v : {c.laMm, c.lbMm, c.alphaTzRad, c.rTzMm, c.betaTzRad, c.frictionalDistanceMm,
                   c.cuttingSpeedMPerMin})
    EXPECT_FALSE(std::isnan(v)) << what;
}

TEST(ToolConditionsSeed001, Table3_Ball_Eqs2to6) {
  for (const Column& c : kTable3) {
    ToolConditions first = ballFirstPass(c.radius, kDepthOfCut, c.spindle);
    ToolConditions later = ballLaterPass(c.radius, c.h, c.spindle);
    ASSERT_TRUE(first.applicable && later.applicable) << c.name;
    EXPECT_NEAR(first.frictionalDistanceMm, c.sl1, kTwoDecimals) << c.name;
    EXPECT_NEAR(later.frictionalDistanceMm, c.sl2, kTwoDecimals) << c.name;
    EXPECT_NEAR(first.cuttingSpeedMPerMin, c.v1, kTwoDecimals) << c.name;
    EXPECT_NEAR(later.cuttingSpeedMPerMin, c.v2, kTwoDecimals) << c.name;
  }
}

// Independent derivation of the restored inverse sine: R_tz is the radius of the
// ball's circle at height ap above its tip, sqrt(2 R ap - ap^2), and beta = pi.
TEST(ToolConditionsSeed001, Ball_RtzIsTheCircleAtDepth) {
  ToolConditions c = ballFirstPass(3, 0.5, 1400);
  EXPECT_NEAR(c.rTzMm, std::sqrt(2 * 3 * 0.5 - 0.25), 1e-12);
  EXPECT_NEAR(c.betaTzRad, kPi, 1e-15);
  EXPECT_NEAR(c.alphaTzRad, std::asin(2.5 / 3), 1e-15);
}

// The text's ratios sl_fd(2)(b) / sl_fd(2)(a) in ball end milling: 1.408, 1.411, 1.411,
// 1.412 — three decimals, so a finer check than the table.
TEST(ToolConditionsSeed001, Text_BallLaterPassRatios) {
  const double printed[] = {1.408, 1.411, 1.411, 1.412};
  for (int k = 0; k < 4; ++k) {
    const Column& a = kTable3[2 * k];
    const Column& b = kTable3[2 * k + 1];
    double ratio = ballLaterPass(b.radius, b.h, b.spindle).frictionalDistanceMm /
                   ballLaterPass(a.radius, a.h, a.spindle).frictionalDistanceMm;
    EXPECT_NEAR(ratio, printed[k], 0.0005) << a.name;
  }
}

TEST(ToolConditionsSeed001, Table4_Filleted_Eqs7to15) {
  for (const Column& c : kTable4) {
    ToolConditions first =
        filletedFirstPass(c.radius, c.cornerRadius, kInclination, kDepthOfCut, c.spindle);
    ToolConditions later =
        filletedLaterPass(c.radius, c.cornerRadius, kInclination, c.h, c.spindle);
    ASSERT_TRUE(first.applicable) << c.name << ": " << first.reason;
    ASSERT_TRUE(later.applicable) << c.name << ": " << later.reason;
    EXPECT_NEAR(first.frictionalDistanceMm, c.sl1, kTwoDecimals) << c.name;
    EXPECT_NEAR(later.frictionalDistanceMm, c.sl2, kTwoDecimals) << c.name;
    EXPECT_NEAR(first.cuttingSpeedMPerMin, c.v1, kTwoDecimals) << c.name;
    EXPECT_NEAR(later.cuttingSpeedMPerMin, c.v2, kTwoDecimals) << c.name;
  }
}

// The text's ratios sl_fd(2)(b) / sl_fd(2)(a) in filleted end milling: 1.268, 1.251,
// 1.281, 1.300 — reproduced to three decimals by the Table 4 reading.
TEST(ToolConditionsSeed001, Text_FilletedLaterPassRatios) {
  const double printed[] = {1.268, 1.251, 1.281, 1.300};
  for (int k = 0; k < 4; ++k) {
    const Column& a = kTable4[2 * k];
    const Column& b = kTable4[2 * k + 1];
    double ratio = filletedLaterPass(b.radius, b.cornerRadius, kInclination, b.h, b.spindle)
                       .frictionalDistanceMm /
                   filletedLaterPass(a.radius, a.cornerRadius, kInclination, a.h, a.spindle)
                       .frictionalDistanceMm;
    EXPECT_NEAR(ratio, printed[k], 0.0005) << a.name;
  }
}

// Independent derivation for F1a: la = 0.95 cos 5, R_tz = sqrt(1 - la^2),
// sl = (2 + R_tz) * 2 acos((2 + 0.95 sin 5) / (2 + R_tz)).
TEST(ToolConditionsSeed001, Filleted_F1aByHand) {
  const double t = degToRad(5);
  const double la = 0.95 * std::cos(t), lb = 0.95 * std::sin(t);
  const double rtz = std::sqrt(1 - la * la);
  const double sl = (2 + rtz) * 2 * std::acos((2 + lb) / (2 + rtz));
  ToolConditions c = filletedLaterPass(3, 1, 5, 0.05, 1400);
  EXPECT_NEAR(c.laMm, la, 1e-15);
  EXPECT_NEAR(c.lbMm, lb, 1e-15);
  EXPECT_NEAR(c.rTzMm, rtz, 1e-12);
  EXPECT_NEAR(c.frictionalDistanceMm, sl, 1e-12);
}

// Not reproduced: Eqs. (13)-(14) as printed, with beta_tz(2) = asin((L/2)/(Rb + R_tz))
// and Table 2's L/2. Printed sl_fd(2) vs this reading (beta_tz(1) of Eq. 11 at the
// heights of pass 2):
//   F1a 2.13 vs 2.622, F1b 2.70 vs 3.495, F2a 2.90 vs 3.629, F2b 3.62 vs 4.897,
//   F3a 3.33 vs 3.867, F3b 4.26 vs 5.243, F4a 3.59 vs 4.022, F4b 4.67 vs 5.478.
// (With beta_tz(1) of the first pass instead, F1a gives 3.362.) The function is checked
// against its own formula and shown to exceed the table reading.
TEST(ToolConditionsSeed001, Table4_Eq13AsPrinted_NotReproduced_Documented) {
  const double eq13[] = {2.622, 3.495, 3.629, 4.897, 3.867, 5.243, 4.022, 5.478};
  for (int i = 0; i < 8; ++i) {
    const Column& c = kTable4[i];
    ToolConditions table =
        filletedLaterPass(c.radius, c.cornerRadius, kInclination, c.h, c.spindle);
    ToolConditions printed = filletedLaterPassEq13(c.radius, c.cornerRadius, kInclination, c.h,
                                                   kTable4[i].halfInterval, c.spindle);
    ASSERT_TRUE(printed.applicable) << c.name << ": " << printed.reason;
    const double reach = c.radius - c.cornerRadius + table.rTzMm;
    const double expected =
        reach * (0.5 * table.betaTzRad + std::asin(kTable4[i].halfInterval / reach));
    EXPECT_NEAR(printed.frictionalDistanceMm, expected, 1e-12) << c.name;
    EXPECT_NEAR(printed.frictionalDistanceMm, eq13[i], 0.0005) << c.name;
    EXPECT_GT(printed.frictionalDistanceMm - c.sl2, 0.4) << c.name;
    EXPECT_NEAR(printed.cuttingSpeedMPerMin, c.v2, kTwoDecimals) << c.name;
  }
}

TEST(ToolConditionsDomain, NotApplicable) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expectNotApplicable(ballFirstPass(0, 0.5, 1400), "ball R = 0");
  expectNotApplicable(ballFirstPass(3, 0, 1400), "ball ap = 0");
  expectNotApplicable(ballFirstPass(3, 3.5, 1400), "ball ap > R");
  expectNotApplicable(ballFirstPass(3, nan, 1400), "ball ap NaN");
  expectNotApplicable(ballFirstPass(3, 0.5, 0), "ball S = 0");
  expectNotApplicable(ballLaterPass(3, -0.05, 1400), "ball h < 0");
  expectNotApplicable(filletedFirstPass(3, 1, 5, 1.5, 1400), "filleted ap > Rcr");
  expectNotApplicable(filletedFirstPass(3, 3, 5, 0.5, 1400), "filleted Rcr = R");
  expectNotApplicable(filletedFirstPass(3, 0, 5, 0.5, 1400), "filleted Rcr = 0");
  expectNotApplicable(filletedFirstPass(3, 1, 90, 0.5, 1400), "filleted theta = 90");
  expectNotApplicable(filletedFirstPass(3, 1, nan, 0.5, 1400), "filleted theta NaN");
  expectNotApplicable(filletedLaterPass(3, 1, 5, 0, 1400), "filleted h = 0");
  expectNotApplicable(filletedLaterPass(3, 1, 5, 0.05, nan), "filleted S NaN");
  expectNotApplicable(filletedLaterPassEq13(3, 1, 5, 0.05, 2.5, 1400), "L/2 > Rb + R_tz");
  expectNotApplicable(filletedLaterPassEq13(3, 1, 5, 0.05, 0, 1400), "L/2 = 0");
  // The sign of theta is a mirror image of the pass.
  EXPECT_NEAR(filletedFirstPass(3, 1, -5, 0.5, 1400).frictionalDistanceMm,
              filletedFirstPass(3, 1, 5, 0.5, 1400).frictionalDistanceMm, 1e-15);
}

}  // namespace
}  // namespace scallop
