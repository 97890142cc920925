// Constants that more than one folder needs: pi and the unit factors, and the named
// tolerances and bounds of the contract (docs/CONVENTIONS.md). This is their one owner:
// scripts/check-owners.sh fails CI if pi or the version is spelt out anywhere else. A
// tolerance that only one algorithm uses stays beside that algorithm.
#pragma once

namespace scallop {

constexpr double kPi = 3.14159265358979323846;

// Unit factors: multiply a value in the first unit to get the second.
constexpr double kRadPerDeg = kPi / 180.0;  // degrees -> radians
constexpr double kMetrePerMm = 1e-3;        // mm -> m (X3P and GSF store metres)

// Every height that reaches a z-map or a report is exact to this against the
// mathematical swept solid, mm (CONVENTIONS.md "Units and frames").
constexpr double kHeightToleranceMm = 1e-6;

// Every length, coordinate and tolerance a user gives is within +-1 km: nothing is
// meaningful beyond it, and the bound keeps squares, products and the float32 heights
// written far from overflow, where a wrong map would be silent. mm.
constexpr double kMaxMagnitudeMm = 1e6;

}  // namespace scallop
