// Predominant frictional distance and cutting speed, seed 001 Eqs. (2)-(15).
//
// Readings of the extracted text (each checked against every cell of Tables 3 and 4,
// see tests/analysis/tool_conditions_test.cpp):
//  * Eqs. (2) and (5) print alpha_tz = (R - ap)/R, a ratio, not an angle: the inverse
//    sine was lost. alpha_tz = asin((R - ap)/R) is the angle, seen from the ball's
//    centre, between the horizontal and the point at depth ap, so that Eq. (3) gives
//    R_tz = R cos(alpha_tz) = sqrt(2 R ap - ap^2), the radius of the cutting circle at
//    height ap (arccos would give R_tz = R - ap, which misses Table 3 by far).
//  * "Depth of cut ap was also set to a half of 0.5 mm": the tables are reproduced with
//    ap = 0.5 mm for both tools (ap = 0.25 mm gives sl_fd(1) = 3.77 mm, not 5.21 mm, for
//    R = 3 mm). The functions take ap as a parameter.
//  * Filleted, second pass: Table 4's sl_fd(2) is Eqs. (7)-(12) with ap replaced by h,
//    i.e. Eq. (14) with beta_tz(2) equal to the half angle beta_tz(1)/2 of Eq. (11) at
//    the second pass's heights. Eq. (13) as printed, asin((L/2)/(Rb + R_tz)), gives
//    2.62 mm instead of 2.13 mm for condition F1a and is kept as filletedLaterPassEq13.
#include "analysis/tool_conditions.h"

#include <cmath>
#include <utility>

#include "base/constants.h"
#include "base/number_text.h"

namespace scallop {
namespace {

ToolConditions notApplicable(std::string reason) {
  ToolConditions c;
  c.reason = std::move(reason);
  return c;
}

std::string checkPositive(const char* name, double v, const char* unit) {
  if (!std::isfinite(v)) return std::string(name) + " is not a finite number";
  if (v <= 0) return std::string(name) + " = " + formatNumber(v) + " " + unit + " must be > 0";
  return {};
}

// A depth (ap or h) that the corner of radius `corner` can cut: 0 < depth <= corner.
std::string checkDepth(const char* name, double depth, const char* cornerName, double corner) {
  if (auto why = checkPositive(name, depth, "mm"); !why.empty()) return why;
  if (depth > corner)
    return std::string(name) + " = " + formatNumber(depth) + " mm exceeds " + cornerName + " = " +
           formatNumber(corner) + " mm: the cutting point would leave the rounded edge";
  return {};
}

// Eq. (6) / (15): v_cs = 2 pi r S / 1000, r in mm, S in min^-1, v_cs in m/min.
double cuttingSpeed(double radiusOfCutMm, double spindleRpm) {
  return 2 * kPi * radiusOfCutMm * spindleRpm / 1000;
}

// Ball end mill at depth d (ap for pass 1, h for later passes).
ToolConditions ballPass(double radius, double depth, double spindleRpm, const char* depthName) {
  if (auto why = checkPositive("tool radius R", radius, "mm"); !why.empty())
    return notApplicable(why);
  if (auto why = checkDepth(depthName, depth, "the ball radius R", radius); !why.empty())
    return notApplicable(why);
  if (auto why = checkPositive("spindle speed S", spindleRpm, "min^-1"); !why.empty())
    return notApplicable(why);
  ToolConditions c;
  c.applicable = true;
  c.alphaTzRad = std::asin((radius - depth) / radius);  // Eq. (2) / (5), asin restored
  c.rTzMm = radius * std::cos(c.alphaTzRad);            // Eq. (3)
  // "In the first tool path, the value of beta_tz is 180 deg"; for later passes "it is
  // reasonable that the result is regarded as 180 deg".
  c.betaTzRad = kPi;
  c.frictionalDistanceMm = c.rTzMm * c.betaTzRad;             // Eq. (4)
  c.cuttingSpeedMPerMin = cuttingSpeed(c.rTzMm, spindleRpm);  // Eq. (6)
  return c;
}

// Filleted end mill, Eqs. (7)-(11) at depth d; leaves beta_tz = beta_tz(1) of Eq. (11).
ToolConditions filletedPass(double radius, double cornerRadius, double inclinationDeg, double depth,
                            double spindleRpm, const char* depthName) {
  if (auto why = checkPositive("tool radius R", radius, "mm"); !why.empty())
    return notApplicable(why);
  if (auto why = checkPositive("corner radius Rcr", cornerRadius, "mm"); !why.empty())
    return notApplicable(why);
  if (cornerRadius >= radius)
    return notApplicable("corner radius Rcr = " + formatNumber(cornerRadius) +
                         " mm must be < R = " + formatNumber(radius) + " mm");
  if (!std::isfinite(inclinationDeg) || std::fabs(inclinationDeg) >= 90)
    return notApplicable("inclination theta = " + formatNumber(inclinationDeg) +
                         " deg must be finite with |theta| < 90 deg");
  if (auto why = checkDepth(depthName, depth, "the corner radius Rcr", cornerRadius); !why.empty())
    return notApplicable(why);
  if (auto why = checkPositive("spindle speed S", spindleRpm, "min^-1"); !why.empty())
    return notApplicable(why);
  // The sign of theta mirrors the pass along the feed and changes none of the values.
  const double theta = std::fabs(inclinationDeg) * kRadPerDeg;
  const double rb = radius - cornerRadius;
  ToolConditions c;
  c.applicable = true;
  c.laMm = (cornerRadius - depth) * std::cos(theta);  // Eq. (7)
  c.lbMm = (cornerRadius - depth) * std::sin(theta);  // Eq. (8)
  c.alphaTzRad = std::asin(c.laMm / cornerRadius);    // Eq. (9)
  c.rTzMm = cornerRadius * std::cos(c.alphaTzRad);    // Eq. (10)
  // Eq. (11); lb <= R_tz always holds for 0 < depth <= Rcr, so the ratio is <= 1.
  c.betaTzRad = 2 * std::acos((rb + c.lbMm) / (rb + c.rTzMm));
  c.frictionalDistanceMm = (rb + c.rTzMm) * c.betaTzRad;           // Eq. (12)
  c.cuttingSpeedMPerMin = cuttingSpeed(rb + c.rTzMm, spindleRpm);  // Eq. (15)
  return c;
}

}  // namespace

ToolConditions ballFirstPass(double radiusMm, double depthOfCutMm, double spindleRpm) {
  return ballPass(radiusMm, depthOfCutMm, spindleRpm, "depth of cut ap");
}

ToolConditions ballLaterPass(double radiusMm, double scallopHeightMm, double spindleRpm) {
  return ballPass(radiusMm, scallopHeightMm, spindleRpm, "scallop height h");
}

ToolConditions filletedFirstPass(double radiusMm, double cornerRadiusMm, double inclinationDeg,
                                 double depthOfCutMm, double spindleRpm) {
  return filletedPass(radiusMm, cornerRadiusMm, inclinationDeg, depthOfCutMm, spindleRpm,
                      "depth of cut ap");
}

ToolConditions filletedLaterPass(double radiusMm, double cornerRadiusMm, double inclinationDeg,
                                 double scallopHeightMm, double spindleRpm) {
  // Eq. (14) with beta_tz(2) = beta_tz(1)/2 at the heights of pass 2 is Eq. (12) itself.
  return filletedPass(radiusMm, cornerRadiusMm, inclinationDeg, scallopHeightMm, spindleRpm,
                      "scallop height h");
}

ToolConditions filletedLaterPassEq13(double radiusMm, double cornerRadiusMm, double inclinationDeg,
                                     double scallopHeightMm, double halfIntervalMm,
                                     double spindleRpm) {
  ToolConditions c = filletedPass(radiusMm, cornerRadiusMm, inclinationDeg, scallopHeightMm,
                                  spindleRpm, "scallop height h");
  if (!c.applicable) return c;
  if (auto why = checkPositive("half interval L/2", halfIntervalMm, "mm"); !why.empty())
    return notApplicable(why);
  const double reach = radiusMm - cornerRadiusMm + c.rTzMm;  // Rb + R_tz(2)
  if (halfIntervalMm > reach)
    return notApplicable("half interval L/2 = " + formatNumber(halfIntervalMm) +
                         " mm exceeds Rb + R_tz = " + formatNumber(reach) +
                         " mm, the radius of the cutting circle (Eq. 13)");
  double beta2 = std::asin(halfIntervalMm / reach);  // Eq. (13)
  c.betaTzRad = 0.5 * c.betaTzRad + beta2;           // beta_tz(1)/2 + beta_tz(2)
  c.frictionalDistanceMm = reach * c.betaTzRad;      // Eq. (14)
  return c;
}

}  // namespace scallop
