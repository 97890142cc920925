// The seeds' tables as printed: the one transcription that the validation run and the
// tests both read. Numbers are copied from the seed papers (README "The seeds");
// nothing here is computed.
#pragma once

namespace scallop {

// Seed 000 (Sekine & Kameya), one condition (column) of Tables 2-5: a filleted end
// mill of radius R and corner radius Rcr inclined by rho along the feed, target h.
// Its procedures are the first four of analysis/path_interval.h's kProcedures, in
// that order.
constexpr int kSeed000Procedures = 4;
struct Seed000Condition {
  int lengthTable, heightTable, condition;  // Table 2|3 (L/2), Table 4|5 (h), column 1-4
  double radius, cornerRadius, leadDeg, h;  // mm, mm, deg, mm
  double halfInterval[kSeed000Procedures];  // printed L/2, mm (Tables 2/3)
  double scallop[kSeed000Procedures];       // printed h from the printed computational L/2, mm
};
constexpr int kSeed000Conditions = 8;
extern const Seed000Condition kSeed000[kSeed000Conditions];

// Seed 001 (Sekine), one tool of Tables 1/3 (ball) or 2/4 (filleted, theta = 5 deg):
// L/2 for scallop h, and the predominant frictional distance sl_fd and cutting speed
// v_cs of the first (1) and a later (2) pass.
struct Seed001Column {
  const char* name;                         // "B1a" ... / "F1a" ...
  double radius, cornerRadius, spindle, h;  // mm, mm (0 for ball), 1/min, mm
  double halfInterval;                      // L/2, mm (Table 1 or 2)
  double sl1, sl2, v1, v2;                  // mm, mm, m/min, m/min (Table 3 or 4)
};
constexpr int kSeed001Columns = 8;
extern const Seed001Column kSeed001Ball[kSeed001Columns];      // Tables 1 and 3
extern const Seed001Column kSeed001Filleted[kSeed001Columns];  // Tables 2 and 4
constexpr double kSeed001InclinationDeg = 5.0;                 // filleted end milling
constexpr double kSeed001DepthOfCutMm = 0.5;  // reading of "a half of ...", see tool_conditions.h

}  // namespace scallop
