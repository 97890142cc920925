// Raked edges (ToothRake, RakeLag: sweep/tooth_geometry.h): the kernel against the
// independent reference (tooth_reference.h, which finds each edge point's angle on the
// rake face by bisection) on random cutters and moves; a radial rake through the axis
// is a turn of the tooth (the same heights as the spindle phase turned back); the
// closed form of the lag against the plane's definition; a rake that changes nothing
// where it should not.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "base/constants.h"
#include "base/input_error.h"
#include "sweep/profile_cases.h"
#include "sweep/tooth_cases.h"
#include "sweep/tooth_sweep.h"

namespace scallop {
namespace {

// Random rakes within +-maxDeg, one for every tooth (`shared`) or one each; halved until
// the faces meet every point of their spans (Cutter::checkRakes), so a draw that would be
// refused is kept as a smaller rake rather than dropped.
void giveRakes(Cutter& c, double maxDeg, bool shared, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  const int flutes = c.teeth.flutes;
  c.teeth.editToothRakes().clear();
  const ToothRake one{maxDeg * u(rng), maxDeg * u(rng)};
  for (int k = 0; k < flutes; ++k)
    c.teeth.editToothRakes().push_back(shared ? one : ToothRake{maxDeg * u(rng), maxDeg * u(rng)});
  for (int tries = 0; tries < 8; ++tries) {
    try {
      c.checkRakes("tool.tooth_rakes_deg");
      return;
    } catch (const InputError&) {
      for (ToothRake& r : c.teeth.editToothRakes()) r = {0.5 * r.axialDeg, 0.5 * r.radialDeg};
    }
  }
  FAIL() << "no rake found that the profile accepts";
}

// The acceptance test of item 2's rake: ball, bull and flat cutters with edge spans
// (inserts, rings, random pieces), offsets, helix, unequal pitch, runout, constant and
// turning axes, both spindle directions, every tooth raked by up to 25 degrees.
TEST(ToothRake, RakedEdgesAgreeWithTheReference) {
  std::mt19937_64 rng(3502);
  std::uniform_real_distribution<double> u(0, 1);
  const unsigned long long unprovenBefore = ToothSweep::unprovenSearches();
  ReferenceCheck check;
  for (int n = 0; n < 24; ++n) {
    Cutter c = randomTeethCutter(n, rng);
    const double R = c.radius;
    const int flutes = c.teeth.flutes;
    const bool turns = n % 6 == 5;
    const double U = c.edgeLength(), rb = c.bottomRadius(), r = c.cornerRadius;
    for (int k = 0; k < flutes; ++k) {
      EdgeSpan s;
      switch ((n + k) % 3) {
        case 0:  // the corner arc: a round insert (a ball's arc from a ring; a flat's rim)
          s = {std::max(rb, 0.2 * R), std::min(U, rb + std::max(r * kPi / 2, 0.3 * R))};
          break;
        case 1:  // an outer ring of the bottom and the corner
          s = {0.3 * R, std::min(U, rb + r * kPi / 4 + 0.3 * R)};
          break;
        default:  // a random piece away from the axis
          s.from = 0.2 * R + U * 0.5 * u(rng);
          s.to = s.from + (U - s.from) * (0.1 + 0.6 * u(rng));
      }
      c.teeth.editEdgeSpans().push_back(s);
    }
    addRandomToothErrors(c, n, turns, rng);
    checkEdgeSpans(c.teeth.edgeSpans(), flutes, U, "tool.tooth_edge_spans", true);
    checkToothGeometry(c.teeth.toothAnglesDeg(), c.teeth.toothOffsets(), flutes, R, rb, "tool");
    giveRakes(c, 25, n % 4 == 0, rng);
    checkAgainstReference(c, n, turns, rng, &check);
  }
  std::printf("ToothRake random: %d hits, %d misses, worst |kernel - reference| %.3g mm\n",
              check.hits, check.misses, check.worst);
  EXPECT_GE(check.hits, 50);
  EXPECT_GE(check.misses, 3);
  EXPECT_EQ(ToothSweep::unprovenSearches(), unprovenBefore);
}

// The same for the general cutters of the cutter issue (tapered ball and bull, cones,
// barrels, lens, oval, free chains), each tooth's span a random piece of its chain.
TEST(ToothRake, RakedGeneralCuttersAgreeWithTheReference) {
  std::mt19937_64 rng(3503);
  std::uniform_real_distribution<double> u(0, 1);
  const unsigned long long unprovenBefore = ToothSweep::unprovenSearches();
  ReferenceCheck check;
  for (int n = 0; n < 10; ++n) {
    Cutter c = test::randomProfileCase(rng, n).cutter();
    const double R = c.radius, U = c.edgeLength();
    const int flutes = 1 + n % 3;
    c.teeth = CutterTeeth::make(flutes, n % 4 == 2 ? 20 * u(rng) : 0, 0, 360 * u(rng), R);
    for (int k = 0; k < flutes; ++k) {
      EdgeSpan s;
      s.from = U * (0.05 + 0.4 * u(rng));
      s.to = s.from + (U - s.from) * (0.1 + 0.5 * u(rng));
      c.teeth.editEdgeSpans().push_back(s);
    }
    checkEdgeSpans(c.teeth.edgeSpans(), flutes, U, "tool.tooth_edge_spans", true);
    giveRakes(c, 20, n % 2 == 0, rng);
    checkAgainstReference(c, n, n % 5 == 4, rng, &check);
  }
  std::printf("ToothRake general: %d hits, %d misses, worst |kernel - reference| %.3g mm\n",
              check.hits, check.misses, check.worst);
  EXPECT_GE(check.hits, 15);
  EXPECT_EQ(ToothSweep::unprovenSearches(), unprovenBefore);
}

// The lag's closed form (lambda = gr + asin(D / rho)) puts the edge point on the rake
// face as tooth_geometry.h defines it: s = (c - rho0) tan(gr) + (h - h0) tan(ga) with
// c = rho cos(lambda), s = rho sin(lambda); and it is 0 at the face's own point P0.
TEST(ToothRake, LagPutsThePointOnTheRakeFace) {
  std::mt19937_64 rng(3504);
  std::uniform_real_distribution<double> u(0, 1);
  for (int n = 0; n < 200; ++n) {
    const ToothRake rake{90 * (u(rng) - 0.5), 90 * (u(rng) - 0.5)};
    const double rho0 = 3 * u(rng), h0 = 2 * u(rng);
    const RakeLag lag(rake, rho0, h0);
    EXPECT_NEAR(lag(rho0, h0), 0, 1e-15) << n;
    const double rho = 0.5 + 3 * u(rng), h = 3 * u(rng);
    const double d = lag.offset(h);
    if (std::fabs(d) > 0.9 * rho) continue;
    const double l = lag(rho, h);
    const double gr = degToRad(rake.radialDeg), ga = degToRad(rake.axialDeg);
    EXPECT_NEAR(rho * std::sin(l),
                (rho * std::cos(l) - rho0) * std::tan(gr) + (h - h0) * std::tan(ga), 1e-13)
        << n;
  }
  EXPECT_FALSE(RakeLag(ToothRake{}, 1, 1).active());
}

// A radial rake whose face passes through the axis (a whole edge: P0 is the tip's
// centre) is the radial line turned by gr about the axis, at every point of a ball,
// flat or bull profile (D = 0 there without axial rake): the tooth turned by gr, which
// is the spindle's phase turned back by gr. So the heights are those of the unraked
// cutter with cutting.phase_deg less gr, on tilted and turning moves.
TEST(ToothRake, RadialRakeThroughTheAxisTurnsTheTooth) {
  std::mt19937_64 rng(3505);
  std::uniform_real_distribution<double> u(0, 1);
  double worst = 0;
  int hits = 0;
  for (int n = 0; n < 9; ++n) {
    Cutter plain = Cutter::make(teethCaseType(n), 1, 0.3, 3);
    plain.teeth = CutterTeeth::make(2 + n % 2, 10 * (n % 2), 0, 0, 1);
    Cutter raked = plain;
    const double gr = 40 * (u(rng) - 0.5);
    raked.teeth.editToothRakes().assign(size_t(plain.teeth.flutes), ToothRake{0, gr});
    raked.checkRakes("tool.rake_deg");
    const double tilt = 0.4 * u(rng), az = 2 * kPi * u(rng);
    const Vec3 a0{std::sin(tilt) * std::cos(az), std::sin(tilt) * std::sin(az), std::cos(tilt)};
    const Vec3 a1 = n % 3 == 2 ? normalize(a0 + Vec3{0.1, 0.05, 0}) : a0;
    const Vec3 p0{0, 0, 0}, p1{1, 0.3, -0.05};
    const double phase = 360 * u(rng), fz = 0.08;
    const SweptMove a = sweepOne(raked, p0, p1, a0, a1, teethModel(fz, phase));
    const SweptMove b = sweepOne(plain, p0, p1, a0, a1, teethModel(fz, phase - gr));
    for (int q = 0; q < 12; ++q) {
      const double x = 1.4 * u(rng) - 0.2, y = 1.6 * u(rng) - 0.5;
      const LowestPoint za = a.lowestPoint(x, y), zb = b.lowestPoint(x, y);
      ASSERT_EQ(za.hit, zb.hit) << n << " " << q;
      if (!za.hit) continue;
      ++hits;
      worst = std::max(worst, std::fabs(za.z - zb.z));
      EXPECT_NEAR(za.z, zb.z, 1e-11) << n << " " << q;
    }
  }
  std::printf("ToothRake radial through the axis: %d hits, worst |raked - turned| %.3g mm\n", hits,
              worst);
  EXPECT_GE(hits, 60);
}

}  // namespace
}  // namespace scallop
