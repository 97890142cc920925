// The exact path interval of any cutter (analysis/pass_section) against the seeds'
// closed forms (seed 001 Eq. (1), the inclined flat's ellipse), the exact computational
// procedure of seed 000 Fig. 1, a brute-force reference written from the cutter's
// definition, and the simulated truth. Every expectation is computed.
#include "analysis/pass_section.h"

#include <gtest/gtest.h>

#include <cmath>

#include "analysis/path_interval.h"
#include "analysis/simulated_interval.h"
#include "base/constants.h"
#include "sweep/brute_force_reference.h"
#include "sweep/raster.h"

namespace scallop {
namespace {

constexpr double kExactMm = 1e-9;  // the procedure's claim

struct Posture {
  double leadDeg, tiltDeg;
};

// The enclosure is certified: narrow, and the exact value lies in it (up to round-off).
void expectEncloses(const Enclosure& e, double want, const char* what) {
  EXPECT_LE(e.width(), kExactMm) << what;
  EXPECT_GE(want, e.low - 1e-12) << what;
  EXPECT_LE(want, e.high + 1e-12) << what;
}

// Seed 001 Eq. (1): a ball leaves the circle of its sphere, centred on the ball's
// centre, in any posture: both sides sqrt(2 R h - h^2) from the centre line.
TEST(PassSection, BallMatchesSeed001Eq1InAnyPosture) {
  for (double R : {3.0, 5.0}) {
    for (const Posture& p : {Posture{0, 0}, Posture{10, 0}, Posture{0, 15}, Posture{20, -10}}) {
      const PassSection section =
          PassSection::of(Cutter::make(CutterType::Ball, R), p.leadDeg, p.tiltDeg);
      for (double h : {1e-6, 0.01, 0.05, 0.5, 2.0}) {
        const double want = std::sqrt(2 * R * h - h * h);
        for (int sign : {+1, -1}) {
          const SectionSide s = section.sideFromCentre(h, sign);
          ASSERT_TRUE(s.reachable);
          expectEncloses(s.offset, want, "ball side");
        }
      }
    }
  }
}

// An inclined flat end mill (lead only) leaves the ellipse of its bottom disk:
// L/2 = R sqrt(1 - ((R sin rho - h) / (R sin rho))^2) up to h = R sin rho, where its
// flank starts; above that h is beyond the cutter.
TEST(PassSection, InclinedFlatEndMillMatchesTheEllipse) {
  const double R = 3;
  for (double rho : {5.0, 10.0, 20.0, 45.0}) {
    const PassSection section = PassSection::of(Cutter::make(CutterType::Flat, R), rho, 0);
    const double depth = R * std::sin(degToRad(rho));
    for (double h : {1e-4, 0.02, 0.05, 0.2, 0.9 * depth}) {
      if (h >= depth) continue;
      const double want = R * std::sqrt(1 - std::pow((depth - h) / depth, 2));
      for (int sign : {+1, -1}) {
        const SectionSide s = section.sideFromCentre(h, sign);
        ASSERT_TRUE(s.reachable) << rho << " " << h;
        expectEncloses(s.offset, want, "flat side");
      }
    }
    EXPECT_FALSE(section.side(1.01 * depth, +1).reachable);
    EXPECT_FALSE(section.side(1.01 * depth, -1).reachable);
  }
  // Untilted, the flank starts at the floor: no h is reachable.
  EXPECT_FALSE(PassSection::of(Cutter::make(CutterType::Flat, R), 0, 0).side(0.01, 1).reachable);
}

// For lead only, seed 000 Fig. 1 (our implementation, path_interval.h) is exact
// geometry of the inclined torus: the two agree to 1e-9 mm.
TEST(PassSection, BullWithLeadMatchesTheComputationalProcedure) {
  struct Case {
    double R, r, lead, h;
  };
  for (const Case& c :
       {Case{3, 1, 5, 0.05}, Case{3, 1, 5, 0.10}, Case{3, 1, 10, 0.05}, Case{3, 1, 10, 0.10},
        Case{6, 2, 5, 0.05}, Case{6, 2, 10, 0.10}, Case{5, 1, 5, 0.05}, Case{7, 3, 5, 0.10},
        Case{4, 2, 45, 0.5}, Case{3, 1, -10, 0.05}, Case{3, 1, 0, 0.05}, Case{3, 1, 2, 1e-4}}) {
    const Cutter cutter = Cutter::make(CutterType::Bull, c.R, c.r);
    const ProcedureResult want = halfIntervalComputational(c.R, c.r, c.lead, c.h);
    ASSERT_TRUE(want.applicable) << want.reason;
    const PassSection section = PassSection::of(cutter, c.lead, 0);
    // Fig. 1 converges to its own epsilon (1e-9 mm), so only the distance is checked.
    for (int sign : {+1, -1})
      EXPECT_NEAR(section.sideFromCentre(c.h, sign).offset.mid(), want.value, kExactMm);
    const ProcedureResult got = halfIntervalExact(cutter, c.lead, 0, c.h);
    ASSERT_TRUE(got.applicable) << got.reason;
    EXPECT_NEAR(got.value, want.value, kExactMm) << c.R << " " << c.r << " " << c.lead;
  }
}

// With tilt only, the shadow along the feed is the cutter's meridian section itself:
// near the contact a bull leaves its corner arc, L/2 = sqrt(2 r h - h^2) on both sides
// of the contact while h <= r (1 - cos tilt) (the arc's lower end).
TEST(PassSection, BullWithTiltOnlyLeavesItsCornerArc) {
  const double R = 4, r = 1.5;
  for (double tilt : {10.0, 30.0, -45.0}) {
    const double limit = r * (1 - std::cos(degToRad(tilt)));
    for (double h : {1e-3 * limit, 0.5 * limit, limit}) {
      const ProcedureResult got =
          halfIntervalExact(Cutter::make(CutterType::Bull, R, r), 0, tilt, h);
      ASSERT_TRUE(got.applicable) << got.reason;
      EXPECT_NEAR(got.value, std::sqrt(2 * r * h - h * h), kExactMm) << tilt << " " << h;
    }
  }
}

// h back from L/2 inverts L/2 from h, in any posture.
TEST(PassSection, ScallopOfTheStepOverInvertsTheStepOver) {
  struct Case {
    CutterType type;
    double R, r, lead, tilt, h;
  };
  for (const Case& c :
       {Case{CutterType::Bull, 3, 1, 5, 7, 0.05}, Case{CutterType::Bull, 4, 1.5, 15, -8, 0.1},
        Case{CutterType::Ball, 3, 0, 20, 30, 0.02}, Case{CutterType::Flat, 3, 0, 10, 10, 0.1}}) {
    const Cutter cutter = Cutter::make(c.type, c.R, c.r);
    const ProcedureResult l2 = halfIntervalExact(cutter, c.lead, c.tilt, c.h);
    ASSERT_TRUE(l2.applicable) << l2.reason;
    const ProcedureResult h = scallopHeightExact(cutter, c.lead, c.tilt, l2.value);
    ASSERT_TRUE(h.applicable) << h.reason;
    EXPECT_NEAR(h.value, c.h, kExactMm);
  }
  // Passes wider apart than the shadow leave an uncut strip.
  EXPECT_FALSE(scallopHeightExact(Cutter::make(CutterType::Ball, 3), 0, 0, 3.5).applicable);
}

// Brute force from the definition (tests/sweep/brute_force_reference.h, no code
// shared): F(y) = min over x of the stationary cutter's lowest point on the vertical
// line (x, y), by a dense scan of x refined by golden section (convex in x); the
// root of F = h by bisection on y.
double bruteForceSection(const ref::RefCutter& rc, const Vec3& axis, double y, double reach) {
  auto f = [&](double x) {
    const ref::RefHit hit = ref::stationaryLowest(rc, Vec3{}, axis, x, y);
    return hit.hit ? hit.z : HUGE_VAL;
  };
  constexpr int kScan = 400;
  double bestX = 0, best = HUGE_VAL;
  for (int k = 0; k <= kScan; ++k) {
    const double x = -reach + 2 * reach * k / kScan;
    if (f(x) < best) best = f(x), bestX = x;
  }
  const double step = 2 * reach / kScan;
  return -ref::goldenMax([&](double x) { return -f(x); }, bestX - step, bestX + step).second;
}

TEST(PassSection, BullMatchesBruteForceInAnyPosture) {
  struct Case {
    double R, r, lead, tilt, h;
  };
  for (const Case& c : {Case{3, 1, 5, 7, 0.05}, Case{3, 1, 0, 10, 0.05}, Case{4, 1.5, 15, -8, 0.1},
                        Case{3, 0.5, 30, 20, 0.2}}) {
    const Cutter cutter = Cutter::make(CutterType::Bull, c.R, c.r);
    const ref::RefCutter rc = ref::makeRefCutter(CutterType::Bull, c.R, c.r);
    const Vec3 axis = leadTiltAxis(Vec3{1, 0, 0}, c.lead, c.tilt);
    const double floor = -ref::supportValue(rc, axis, Vec3{0, 0, -1});
    const double reach = 2 * c.R + cutter.fluteLength;
    const PassSection section = PassSection::of(cutter, c.lead, c.tilt);
    EXPECT_NEAR(section.floorZ(), floor, 1e-12);
    for (int sign : {+1, -1}) {
      const SectionSide s = section.side(c.h, sign);
      ASSERT_TRUE(s.reachable);
      // Bisection on y between points 1e-3 mm inside and outside the root.
      double in = sign * (s.offset.mid() - 1e-3), out = sign * (s.offset.mid() + 1e-3);
      ASSERT_LT(bruteForceSection(rc, axis, in, reach) - floor, c.h);
      ASSERT_GT(bruteForceSection(rc, axis, out, reach) - floor, c.h);
      for (int i = 0; i < 50; ++i) {
        const double m = 0.5 * (in + out);
        (bruteForceSection(rc, axis, m, reach) - floor < c.h ? in : out) = m;
      }
      EXPECT_NEAR(sign * 0.5 * (in + out), s.offset.mid(), kExactMm)
          << c.lead << " " << c.tilt << " side " << sign;
    }
  }
}

// The simulated truth (a swept pass ray-cast and refined on the exact heights) and
// this procedure share only the cutter's support map.
TEST(PassSection, AgreesWithTheSimulatedPass) {
  struct Case {
    CutterType type;
    double R, r, lead, tilt, h;
  };
  for (const Case& c :
       {Case{CutterType::Bull, 3, 1, 5, 7, 0.05}, Case{CutterType::Bull, 4, 1.5, 15, -8, 0.1},
        Case{CutterType::Flat, 3, 0, 10, 5, 0.1}}) {
    const Cutter cutter = Cutter::make(c.type, c.R, c.r);
    const SimulatedPass pass(cutter, c.lead, c.tilt);
    const SideIntervals sim = pass.halfIntervals(c.h);
    ASSERT_TRUE(sim.reachable) << sim.reason;
    const PassSection section = PassSection::of(cutter, c.lead, c.tilt);
    EXPECT_NEAR(section.sideFromCentre(c.h, +1).offset.mid(), sim.plusMm, kExactMm);
    EXPECT_NEAR(section.sideFromCentre(c.h, -1).offset.mid(), sim.minusMm, kExactMm);
  }
}

}  // namespace
}  // namespace scallop
