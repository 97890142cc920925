// Edges on a span of the profile (EdgeSpan, sweep/tooth_geometry.h): the kernel against
// the independent reference (tooth_reference.h, its search restricted to each tooth's
// span) on random moves; the closed form of a round insert's feed marks on a face
// mill's pass centre line; the arc length of a profile point; the values refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "base/constants.h"
#include "sweep/profile_cases.h"
#include "sweep/tool_path_sweep.h"
#include "sweep/tooth_cases.h"
#include "sweep/tooth_reference.h"
#include "sweep/tooth_sweep.h"
#include "tests/support/input_error_message.h"

namespace scallop {
namespace {

TEST(ToothSpan, BadSpansNameTheirField) {
  const double U = 10;
  expectRejected(
      [&] {
        checkEdgeSpans({{-0.1, 2}}, 2, U, "tool.edge_span", false);
      },
      "tool.edge_span");
  expectRejected(
      [&] {
        checkEdgeSpans({{1, 10.5}}, 2, U, "tool.edge_span", false);
      },
      "tool.edge_span");
  expectRejected(
      [&] {
        checkEdgeSpans({{3, 3}}, 2, U, "tool.edge_span", false);
      },
      "tool.edge_span");
  expectRejected(
      [&] {
        checkEdgeSpans({{NAN, 3}}, 2, U, "tool.edge_span", false);
      },
      "tool.edge_span");
  expectRejected(
      [&] {
        checkEdgeSpans({{0, 1}}, 2, U, "tool.tooth_edge_spans", true);
      },
      "tool.tooth_edge_spans");
  expectRejected(
      [&] {
        checkEdgeSpans({{0, 1}, {4, 2}}, 2, U, "tools.3.tooth_edge_spans", true);
      },
      "tools.3.tooth_edge_spans[1]");
  checkEdgeSpans({{0, 10}, {4, 5}}, 2, U, "tool.tooth_edge_spans", true);
  // The whole edge of a bull R 2 r 0.5 L 4: Rb + r pi / 2 + L - r.
  const Cutter bull = Cutter::make(CutterType::Bull, 2, 0.5, 4);
  EXPECT_NEAR(bull.edgeLength(), 1.5 + 0.25 * kPi + 3.5, 1e-15);
  EXPECT_NEAR(bull.edgeLength(), ref::edgeLength(bull), 1e-14);
}

// The arc length of a profile point (the kernel's) is the reference's parameter.
TEST(ToothSpan, ArcLengthOfAProfilePointIsTheReferences) {
  for (CutterType type : {CutterType::Ball, CutterType::Bull, CutterType::Flat}) {
    const Cutter c = Cutter::make(type, 2, 0.7, 3);
    const double U = ref::edgeLength(c);
    for (int i = 0; i <= 200; ++i) {
      const double u = U * i / 200;
      const ref::EdgeSpot p = ref::edgeSpot(c, u);
      EXPECT_NEAR(profileArcLength(c.bottomRadius(), c.cornerRadius, p.h, p.rho), u, 1e-12)
          << toString(type) << " " << u;
    }
  }
}

// Random cutters whose teeth cover spans (corner arcs, flat-bottom rings, flank pieces,
// one per tooth or shared), with offsets, helix, runout, unequal pitch and either
// spindle direction, on constant and turning axes (a vertical one included: a face
// mill), against the reference within 1e-6 mm, hits and misses alike.
TEST(ToothSpan, SpansAgreeWithTheReference) {
  std::mt19937_64 rng(3501);
  std::uniform_real_distribution<double> u(0, 1);
  const unsigned long long unprovenBefore = ToothSweep::unprovenSearches();
  ReferenceCheck check;
  for (int n = 0; n < 30; ++n) {
    Cutter c = randomTeethCutter(n, rng);
    const double R = c.radius;
    const int flutes = c.teeth.flutes;
    const bool turns = n % 6 == 5;
    const double U = c.edgeLength(), rb = c.bottomRadius(), r = c.cornerRadius;
    for (int k = 0; k < flutes; ++k) {
      EdgeSpan s;
      switch ((n + k * (n % 2)) % 4) {
        case 0:  // the corner arc (a ball's whole arc; a flat end mill's rim and flank foot)
          s = {rb, std::min(U, rb + std::max(r * kPi / 2, 0.3 * R))};
          break;
        case 1:  // an outer ring of the bottom and the corner
          s = {0.5 * rb, rb + r * kPi / 4 + 0.1 * R};
          break;
        case 2:  // a random piece
          s.from = U * 0.6 * u(rng);
          s.to = s.from + (U - s.from) * (0.1 + 0.9 * u(rng));
          break;
        default:  // from the axis
          s = {0, rb + 0.5 * r + 0.2 * R};
      }
      c.teeth.editEdgeSpans().push_back(s);
    }
    addRandomToothErrors(c, n, turns, rng);
    checkEdgeSpans(c.teeth.edgeSpans(), flutes, U, "tool.tooth_edge_spans", true);
    checkAgainstReference(c, n, turns, rng, &check);
  }
  std::printf("ToothSpan random: %d hits, %d misses, worst |kernel - reference| %.3g mm\n",
              check.hits, check.misses, check.worst);
  EXPECT_GE(check.hits, 60);
  EXPECT_GE(check.misses, 3);
  EXPECT_EQ(ToothSweep::unprovenSearches(), unprovenBefore);
}

// A general cutter's chain (tapered balls and bulls, cones, barrels, lenses, ovals, free
// chains): the kernel's arc length of a chain point is the reference's parameter, and
// the radii of a span are those of the chain's points on it (dense sampling).
TEST(ToothSpan, ArcLengthAlongAGeneralChainIsTheReferences) {
  std::mt19937_64 rng(3502);
  for (int n = 0; n < 14; ++n) {
    const Cutter c = test::randomProfileCase(rng, n).cutter();
    const double U = ref::edgeLength(c);
    EXPECT_NEAR(c.edgeLength(), U, 1e-12) << n;
    for (int i = 0; i <= 400; ++i) {
      const double u = U * i / 400;
      const ref::EdgeSpot p = ref::edgeSpot(c, u);
      EXPECT_NEAR(c.edgeArcLength(p.h, p.rho), u, 1e-9) << n << " " << u;
    }
    const EdgeSpan span{0.2 * U, 0.9 * U};
    double lo, hi, sampledLo = HUGE_VAL, sampledHi = -HUGE_VAL;
    c.edgeSpanRadii(span, &lo, &hi);
    for (int i = 0; i <= 4000; ++i) {
      const double rho = ref::edgeSpot(c, span.from + (span.to - span.from) * i / 4000).rho;
      sampledLo = std::min(sampledLo, rho), sampledHi = std::max(sampledHi, rho);
    }
    EXPECT_LE(lo, sampledLo + 1e-12) << n;
    EXPECT_GE(hi, sampledHi - 1e-12) << n;
    EXPECT_NEAR(lo, sampledLo, 1e-5) << n;
    EXPECT_NEAR(hi, sampledHi, 1e-5) << n;
  }
}

// Spans on general cutters against the reference: random chains whose teeth cover a
// random piece or start at the axis, with helix, runout, outward radial and axial
// offsets, unequal pitch and either spindle direction, on constant and turning axes.
TEST(ToothSpan, GeneralCuttersSpansAgreeWithTheReference) {
  std::mt19937_64 rng(3503);
  std::uniform_real_distribution<double> u(0, 1);
  const unsigned long long unprovenBefore = ToothSweep::unprovenSearches();
  ReferenceCheck check;
  for (int n = 0; n < 14; ++n) {
    Cutter c = test::randomProfileCase(rng, n).cutter();
    const double R = c.radius, U = c.edgeLength();
    const int flutes = 1 + n % 3;
    c.teeth = CutterTeeth::make(flutes, n % 4 == 2 ? 30 * u(rng) : 0, n % 5 == 1 ? 0.02 * R : 0,
                                360 * u(rng), R);
    const bool turns = n % 6 == 5;
    for (int k = 0; k < flutes; ++k) {
      EdgeSpan s;
      if ((n + k) % 2) {
        s.from = U * 0.5 * u(rng);
        s.to = s.from + (U - s.from) * (0.1 + 0.9 * u(rng));
      } else {
        s = {0, U * (0.1 + 0.4 * u(rng))};
      }
      c.teeth.editEdgeSpans().push_back(s);
    }
    if (n % 2 && !turns)
      for (int k = 0; k < flutes; ++k)
        c.teeth.editToothOffsets().push_back({0.01 * R * u(rng), 0.01 * (u(rng) - 0.5)});
    if (n % 4 == 3 && flutes > 1)
      for (int k = 0; k < flutes; ++k)
        c.teeth.editToothAnglesDeg().push_back(k == 0 ? 0
                                                      : 360.0 * k / flutes + 40 * (u(rng) - 0.5));
    checkEdgeSpans(c.teeth.edgeSpans(), flutes, U, "tool.tooth_edge_spans", true);
    checkAgainstReference(c, n, turns, rng, &check);
  }
  std::printf("ToothSpan general: %d hits, %d misses, worst |kernel - reference| %.3g mm\n",
              check.hits, check.misses, check.worst);
  EXPECT_GE(check.hits, 25);
  EXPECT_EQ(ToothSweep::unprovenSearches(), unprovenBefore);
}

// A face mill: bull R = Rb + ri, two round inserts (the corner arc of radius ri only,
// the flat bottom and the flank not cutting), a vertical axis and a straight pass along
// X at zero errors. On the pass centre line y = 0 an edge crosses the vertical line at x
// only when its meridian plane holds x (the tooth points along +X or -X), so the
// heights there are the corner arcs, one every fz: tooth k points along +X at
// travel s = k fz + 2 fz n, its arc's bottom then at x = s + Rb (the front) and the
// other tooth's at s - Rb (the back; with 2 Rb a multiple of fz on the same places).
// Each arc z = ri - sqrt(ri^2 - d^2) at distance d from its bottom, so the floor is
// the lower envelope of arcs fz apart: marks of depth ri - sqrt(ri^2 - fz^2 / 4), the
// sagitta, whose small-fz form is fz^2 / (8 ri). With the whole edge the flat bottom
// passes over the line: a flat floor.
TEST(ToothSpan, RoundInsertFeedMarksAreTheSagitta) {
  const double ri = 3, rb = 5, fz = 0.5;  // 2 Rb = 20 fz
  Cutter insert = Cutter::make(CutterType::Bull, rb + ri, ri, 5);
  insert.teeth = CutterTeeth::make(2, 0, 0, 0, insert.radius);
  Cutter whole = insert;
  insert.teeth.editEdgeSpans().assign(2, EdgeSpan{rb, rb + ri * kPi / 2});
  const Vec3 a{0, 0, 1}, p0{0, 0, 0}, p1{20, 0, 0};
  const SweptMove spanned = sweepOne(insert, p0, p1, a, a, teethModel(fz, 0));
  const SweptMove flat = sweepOne(whole, p0, p1, a, a, teethModel(fz, 0));
  const double sagitta = ri - std::sqrt(ri * ri - fz * fz / 4);
  double highest = -HUGE_VAL, lowest = HUGE_VAL, worst = 0;
  for (int i = 0; i <= 40; ++i) {
    // Two marks, at points of every phase of them (the cusp at i = 10, 30).
    const double x = 10 + 2 * fz * i / 40 + 1e-7 * (i % 3);
    const double d = std::fabs(x - fz * std::round(x / fz));
    const double want = ri - std::sqrt(ri * ri - d * d);
    const LowestPoint got = spanned.lowestPoint(x, 0);
    ASSERT_TRUE(got.hit) << x;
    worst = std::max(worst, std::fabs(got.z - want));
    EXPECT_NEAR(got.z, want, 1e-9) << x;
    highest = std::max(highest, got.z);
    lowest = std::min(lowest, got.z);
    const LowestPoint floor = flat.lowestPoint(x, 0);
    ASSERT_TRUE(floor.hit);
    EXPECT_NEAR(floor.z, 0, 1e-12) << x;
  }
  EXPECT_NEAR(highest, sagitta, 1e-9);  // sampled at the cusps
  EXPECT_NEAR(lowest, 0, 1e-6);
  // fz^2 / (8 ri) is the sagitta's leading term: the next is fz^4 / (128 ri^3).
  const double parabola = fz * fz / (8 * ri), next = std::pow(fz, 4) / (128 * std::pow(ri, 3));
  EXPECT_GT(sagitta - parabola, 0.99 * next);
  EXPECT_LT(sagitta - parabola, 1.01 * next);
  std::printf(
      "ToothSpan round insert ri %g, fz %g: marks %.6f um (sagitta %.6f um, fz^2/(8 ri) "
      "%.6f um), worst |kernel - arcs| %.3g mm\n",
      ri, fz, 1e3 * (highest - lowest), 1e3 * sagitta, 1e3 * parabola, worst);
}

}  // namespace
}  // namespace scallop
