// The teeth tests' shared cases: a teeth cutting model, one move swept, and the check of
// a random move of a cutter with teeth against the independent reference
// (tooth_reference.h), used by tooth_span_test.cpp and tooth_rake_test.cpp.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "base/constants.h"
#include "sweep/tool_path_sweep.h"
#include "sweep/tooth_reference.h"

namespace scallop {

inline CuttingModel teethModel(double fz, double phaseDeg, bool ccw = false) {
  CuttingModel model;
  model.kind = CuttingModelKind::Teeth;
  model.feedPerTooth = fz;
  model.phaseDeg = phaseDeg;
  model.counterClockwise = ccw;
  return model;
}

inline SweptMove sweepOne(const Cutter& c, const Vec3& p0, const Vec3& p1, const Vec3& a0,
                          const Vec3& a1, const CuttingModel& model) {
  ToolPath path;
  path.moves.push_back(Move{{p0, a0}, {p1, a1}});
  std::vector<SweptMove> moves = sweepToolPath(c, path, model);
  EXPECT_EQ(moves.size(), 1u);
  return std::move(moves[0]);
}

// One random move of cutter `c` (its teeth set; case n: tilted unless n % 5 == 0, its
// axis turning if `turns`, CCW when n % 3 == 2) against the reference at four points
// of its footprint, hits and misses alike. The draws come in a fixed order, so a test's
// cases stay the same.
struct ReferenceCheck {
  int hits = 0, misses = 0;
  double worst = 0;
};
inline void checkAgainstReference(const Cutter& c, int n, bool turns, std::mt19937_64& rng,
                                  ReferenceCheck* check) {
  std::uniform_real_distribution<double> u(0, 1);
  const double R = c.radius;
  const int flutes = c.teeth.flutes;
  const double tilt = n % 5 == 0 ? 0 : 0.5 * u(rng), az = 2 * kPi * u(rng);
  const Vec3 a0{std::sin(tilt) * std::cos(az), std::sin(tilt) * std::sin(az), std::cos(tilt)};
  const Vec3 a1 = turns ? normalize(a0 + Vec3{0.15, -0.1, 0}) : a0;
  const Vec3 p0{0, 0, 0}, p1{0.8 * std::cos(az + 1), 0.8 * std::sin(az + 1), 0.1 * (u(rng) - 0.5)};
  const double fz = 0.05 + 0.1 * u(rng), phaseDeg = 360 * u(rng);
  const bool counter = n % 3 == 2;
  const SweptMove move = sweepOne(c, p0, p1, a0, a1, teethModel(fz, phaseDeg, counter));
  const ref::ToothMove m{
      p0, p1, a0, a1, degToRad(phaseDeg), 2 * kPi * length(p1 - p0) / (flutes * fz), counter};
  for (int q = 0; q < 4; ++q) {
    const double t = u(rng), ang = 2 * kPi * u(rng), rho = 1.05 * R * std::sqrt(u(rng));
    const Vec3 at = p0 + (p1 - p0) * t;
    const double x = at.x + rho * std::cos(ang), y = at.y + rho * std::sin(ang);
    const LowestPoint got = move.lowestPoint(x, y);
    const ref::ToothHit want = ref::toothLowest(c, m, x, y);
    ASSERT_EQ(got.hit, want.hit) << n << " " << q << " " << got.z << " " << want.z;
    if (!got.hit) {
      ++check->misses;
      continue;
    }
    ++check->hits;
    check->worst = std::max(check->worst, std::fabs(got.z - want.z));
    EXPECT_NEAR(got.z, want.z, kHeightToleranceMm) << n << " " << q;
    // A span's crossing is one of the whole edge's: never below the envelope.
    EXPECT_GE(got.z, move.envelopeLowestPoint(x, y).z - 1e-9) << n;
  }
}

// Random cutter n of the teeth tests: a ball, bull or flat cutter (n % 3, teethCaseType) of radius
// 1-2 mm, 1 + n % 3 flutes, a helix when n % 4 == 2, runout when n % 5 == 1.
inline CutterType teethCaseType(int n) {
  return n % 3 == 0 ? CutterType::Ball : n % 3 == 1 ? CutterType::Bull : CutterType::Flat;
}

inline Cutter randomTeethCutter(int n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  const double R = 1 + u(rng);
  Cutter c = Cutter::make(teethCaseType(n), R, 0.4 * R, 2 * R);
  const int flutes = 1 + n % 3;
  c.teeth = CutterTeeth::make(flutes, n % 4 == 2 ? 30 * u(rng) : 0, n % 5 == 1 ? 0.02 * R : 0,
                              360 * u(rng), R);
  return c;
}

// Its tooth errors: offsets of up to 10 um when n is odd (a ball's edge moved out only:
// radial >= -(R - r) = 0; raised only on a turning move, which refuses a tooth below the
// tip), unequal pitch when n % 4 == 3.
inline void addRandomToothErrors(Cutter& c, int n, bool turns, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  const int flutes = c.teeth.flutes;
  if (n % 2) {
    for (int k = 0; k < flutes; ++k) {
      const double radial = c.type == CutterType::Ball ? 0.01 * u(rng) : 0.02 * (u(rng) - 0.5);
      const double axial = turns ? -0.01 * u(rng) : 0.02 * (u(rng) - 0.5);
      c.teeth.editToothOffsets().push_back({radial, axial});
    }
  }
  if (n % 4 == 3 && flutes > 1)
    for (int k = 0; k < flutes; ++k)
      c.teeth.editToothAnglesDeg().push_back(k == 0 ? 0 : 360.0 * k / flutes + 40 * (u(rng) - 0.5));
}

}  // namespace scallop
