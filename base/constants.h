// Constants that more than one folder needs: pi and the unit factors, and the named
// tolerances and bounds of the contract (docs/CONVENTIONS.md). This is their one owner:
// scripts/check-owners.sh fails CI if pi or the version is spelt out anywhere else. A
// tolerance that only one algorithm uses stays beside that algorithm.
#pragma once

namespace scallop {

constexpr double kPi = 3.14159265358979323846;

// Unit factors: multiply a value in the first unit to get the second.
constexpr double kRadPerDeg = kPi / 180.0;  // degrees -> radians
constexpr double kDegPerRad = 180.0 / kPi;  // radians -> degrees
constexpr double kMetrePerMm = 1e-3;        // mm -> m (X3P and GSF store metres)

// An angle in degrees in radians, as deg * pi / 180: two roundings, not deg * kRadPerDeg's
// one, so its last bit can differ from deg * kRadPerDeg. The sweep, the cast and the
// analysis convert with this one where they always have, which keeps their heights the
// same bits (scripts/example-heights.sh, scripts/perf-guard.sh).
constexpr double degToRad(double deg) {
  return deg * kPi / 180;
}
// An angle in radians in degrees, as rad * 180 / pi.
constexpr double radToDeg(double rad) {
  return rad * 180 / kPi;
}

// Every height that reaches a z-map or a report is exact to this against the
// mathematical swept solid, mm (CONVENTIONS.md "Units and frames").
constexpr double kHeightToleranceMm = 1e-6;

// Every length, coordinate and tolerance a user gives is within +-1 km: nothing is
// meaningful beyond it, and the bound keeps squares, products and the float32 heights
// written far from overflow, where a wrong map would be silent. mm.
constexpr double kMaxMagnitudeMm = 1e6;

}  // namespace scallop
