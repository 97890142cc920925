// Path interval (step-over) procedures of the literature, as pure functions.
//
// Seed 000 (Sekine & Kameya, "Comparative study on path interval determinations in
// filleted end milling"): a filleted (torus, "bull") end mill of radius R and corner
// radius Rcr, Rb = R - Rcr, inclined by rho along the feed (lead) and milling a plane.
// L/2 is the cross-feed distance from the tool centre to where the cutter's section
// reaches the scallop height h above the plane. Four procedures give L/2 from h:
//   computational  3D algorithm of Fig. 1 with Eqs. (1)-(3)           (Sec. 2.1)
//   sekine         effective radius of Eqs. (4)-(7), then Eq. (8)     (Sec. 2.2)
//   redonnet       effective radius of Eq. (9), then Eq. (8)          (Sec. 2.3)
//   bedi           elliptic projection, Eqs. (10)-(11)                (Sec. 2.4)
// and Eqs. (12)-(13) give h back from L/2. Seed 001 Eq. (1) is the ball end mill.
//
// Units: lengths in mm, the lead angle in degrees (CONVENTIONS.md). Every procedure
// returns a ProcedureResult: outside its domain it says so in `reason` and never
// returns NaN or a silently clamped number.
#pragma once

#include <string>
#include <vector>

namespace scallop {

struct ProcedureResult {
  bool applicable = false;
  double value = 0;    // mm (L/2 or h); 0 when not applicable
  std::string reason;  // why not applicable; empty when applicable
};

// Convergence of the iterations of Fig. 1 (lines 11 and 25), mm.
constexpr double kComputationalEpsilonMm = 1e-9;

// ---- L/2 from h -------------------------------------------------------------------

// Seed 000 Fig. 1, Eqs. (1)-(3): the farthest cross-feed point of the intersection of
// the inclined torus with the "h pseudo plane", found as in the paper's pseudo-code.
ProcedureResult halfIntervalComputational(double radiusMm, double cornerRadiusMm, double leadDeg,
                                          double scallopHeightMm,
                                          double epsilonMm = kComputationalEpsilonMm);
// Seed 000 Eqs. (4)-(8).
ProcedureResult halfIntervalSekine(double radiusMm, double cornerRadiusMm, double leadDeg,
                                   double scallopHeightMm);
// Seed 000 Eq. (9) with Eq. (8).
ProcedureResult halfIntervalRedonnet(double radiusMm, double cornerRadiusMm, double leadDeg,
                                     double scallopHeightMm);
// Seed 000 Eqs. (10)-(11).
ProcedureResult halfIntervalBedi(double radiusMm, double cornerRadiusMm, double leadDeg,
                                 double scallopHeightMm);
// Seed 001 Eq. (1): L/2 = sqrt(2 R h - h^2), independent of the inclination.
ProcedureResult halfIntervalBall(double radiusMm, double scallopHeightMm);

// ---- h from L/2 -------------------------------------------------------------------

// The inverse of halfIntervalComputational (bisection on h to epsilonMm).
ProcedureResult scallopHeightComputational(double radiusMm, double cornerRadiusMm, double leadDeg,
                                           double halfIntervalMm,
                                           double epsilonMm = kComputationalEpsilonMm);
// Seed 000 Eq. (12), true-circular, with R_eff of Eq. (4).
ProcedureResult scallopHeightSekine(double radiusMm, double cornerRadiusMm, double leadDeg,
                                    double halfIntervalMm);
// Seed 000 Eq. (12), true-circular, with R_eff of Eq. (9).
ProcedureResult scallopHeightRedonnet(double radiusMm, double cornerRadiusMm, double leadDeg,
                                      double halfIntervalMm);
// Seed 000 Eq. (13), elliptic, with R_long of Eq. (10).
ProcedureResult scallopHeightBedi(double radiusMm, double cornerRadiusMm, double leadDeg,
                                  double halfIntervalMm);
// Inverse of seed 001 Eq. (1): h = R - sqrt(R^2 - (L/2)^2).
ProcedureResult scallopHeightBall(double radiusMm, double halfIntervalMm);

// ---- The radii the 2D procedures use ------------------------------------------------

ProcedureResult effectiveRadiusSekine(double radiusMm, double cornerRadiusMm,
                                      double leadDeg);  // Eqs. (4)-(7), mm
ProcedureResult effectiveRadiusRedonnet(double radiusMm, double cornerRadiusMm,
                                        double leadDeg);  // Eq. (9), mm
ProcedureResult longRadiusBedi(double radiusMm, double cornerRadiusMm,
                               double leadDeg);  // Eq. (10), mm

// ---- The circle of an effective radius ------------------------------------------------

// Eq. (8): L/2 = sqrt(2 R_eff h - h^2) for an applicable `reff` (else `reff` itself);
// not applicable when h > R_eff or L/2 > `radiusMm`, the tool's largest radius.
// `name` prefixes the reasons.
ProcedureResult circularHalfInterval(const char* name, const ProcedureResult& reff,
                                     double scallopHeightMm, double radiusMm);
// Eq. (12): h = R_eff - sqrt(R_eff^2 - (L/2)^2), same rules.
ProcedureResult circularScallopHeight(const char* name, const ProcedureResult& reff,
                                      double halfIntervalMm, double radiusMm);

// ---- All procedures, for a CLI to iterate over ---------------------------------------

enum class ProcedureToolType { Ball, Bull };

struct ProcedureTool {
  ProcedureToolType type = ProcedureToolType::Bull;
  double radiusMm = 0;        // R
  double cornerRadiusMm = 0;  // Rcr; ignored for Ball
};

// The procedures, in the order every listing (interval, validate, the tests) uses.
// The first four are seed 000's, for filleted end mills; "ball" is seed 001 Eq. (1).
enum class Procedure { kComputational, kSekine, kRedonnet, kBedi, kBall };
constexpr int kProcedureCount = 5;

// One row of the procedure table: what a listing names and cites, and the two
// directions as plain functions of (R, Rcr, lead in degrees, h or L/2, epsilon for the
// iterated computational procedure). For "ball", Rcr and the lead are ignored.
struct ProcedureInfo {
  Procedure id;
  const char* name;    // "computational", "sekine", "redonnet", "bedi", "ball"
  const char* source;  // "seed 000 Eqs. (4)-(8), (12)", ...
  ProcedureResult (*halfInterval)(double r, double rcr, double leadDeg, double h, double eps);
  ProcedureResult (*scallopHeight)(double r, double rcr, double leadDeg, double l2, double eps);
};

// The table, indexed by int(Procedure).
extern const ProcedureInfo kProcedures[kProcedureCount];

struct NamedProcedureResult {
  std::string name;    // kProcedures[i].name
  std::string source;  // kProcedures[i].source
  ProcedureResult result;
};

// L/2 by every procedure, in table order. For a ball tool, "computational"
// runs Fig. 1 on the degenerate torus Rb = 0 (the ball's sphere) and the three
// filleted-end formulas are not applicable; for a bull tool "ball" is not applicable.
std::vector<NamedProcedureResult> halfIntervalProcedures(
    const ProcedureTool& tool, double leadDeg, double scallopHeightMm,
    double epsilonMm = kComputationalEpsilonMm);
// h back from L/2 by every procedure, same order and rules.
std::vector<NamedProcedureResult> scallopHeightProcedures(
    const ProcedureTool& tool, double leadDeg, double halfIntervalMm,
    double epsilonMm = kComputationalEpsilonMm);

}  // namespace scallop
