// Tool condition parameters of seed 001 (Sekine, "Comparative study on path interval
// and two tool condition parameters in ball and filleted end milling"): the
// predominant frictional distance sl_fd(n) of one cutting edge in one revolution and
// the predominant cutting speed v_cs(n), for the first pass (n = 1, a full slot of
// depth ap) and for the second pass or later (n = 2, the edge cuts down to the scallop
// height h of the previous pass). Eqs. (2)-(6) ball end mill, Eqs. (7)-(15) filleted.
//
// Units: lengths in mm, the inclination in degrees, the spindle speed S in min^-1, the
// cutting speed in m/min, angles of the result in radians (they are internal values
// the paper defines in rad). Outside the domain `applicable` is false and `reason`
// says why; no field is ever NaN.
#pragma once

#include <string>

namespace scallop {

struct ToolConditions {
  bool applicable = false;
  std::string reason;               // empty when applicable
  double laMm = 0;                  // l_a(n), Eq. (7) (filleted only)
  double lbMm = 0;                  // l_b(n), Eq. (8) (filleted only)
  double alphaTzRad = 0;            // alpha_tz(n), Eq. (2)/(5) or (9)
  double rTzMm = 0;                 // R_tz(n), Eq. (3) or (10)
  double betaTzRad = 0;             // sliding contact angle used in sl_fd(n)
  double frictionalDistanceMm = 0;  // sl_fd(n), Eq. (4) or (12)/(14)
  double cuttingSpeedMPerMin = 0;   // v_cs(n), Eq. (6) or (15)
};

// Ball end mill, first pass, depth of cut ap: Eqs. (2), (3), (4) with beta = 180 deg, (6).
ToolConditions ballFirstPass(double radiusMm, double depthOfCutMm, double spindleRpm);
// Ball end mill, second pass or later: Eq. (5) (ap -> h), (3), (4) with beta = 180 deg, (6).
ToolConditions ballLaterPass(double radiusMm, double scallopHeightMm, double spindleRpm);

// Filleted end mill inclined by theta along the feed, first pass: Eqs. (7)-(12), (15).
ToolConditions filletedFirstPass(double radiusMm, double cornerRadiusMm, double inclinationDeg,
                                 double depthOfCutMm, double spindleRpm);
// Filleted end mill, second pass or later, the reading that reproduces Table 4: Eqs.
// (7)-(12) with ap -> h ("the similar manner used in ball end milling"), i.e. Eq. (14)
// with both half angles equal to beta_tz(1)/2 taken at the heights of pass 2; Eq. (15)
// with R_tz(2). The path interval does not enter (see tool_conditions.cpp).
ToolConditions filletedLaterPass(double radiusMm, double cornerRadiusMm, double inclinationDeg,
                                 double scallopHeightMm, double spindleRpm);
// The same pass with Eqs. (13)-(14) as printed: beta_tz(2) = asin((L/2) / (Rb + R_tz)).
// Does not reproduce Table 4 (it gives larger distances); kept for comparison.
ToolConditions filletedLaterPassEq13(double radiusMm, double cornerRadiusMm, double inclinationDeg,
                                     double scallopHeightMm, double halfIntervalMm,
                                     double spindleRpm);

}  // namespace scallop
