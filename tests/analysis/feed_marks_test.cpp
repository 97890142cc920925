// Feed marks measured on synthetic profiles (analysis/feed_marks.h): arcs whose peak-to-
// valley and valley positions are known in closed form, two teeth of different depth,
// and profiles with no marks at all.
#include "analysis/feed_marks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace scallop {
namespace {

// Samples z(x) at x = k step, k = 0..n-1.
Profile sampled(const std::function<double(double)>& z, double step, int n) {
  Profile p;
  p.x1 = step * (n - 1);
  p.stepMm = step;
  for (int k = 0; k < n; ++k) p.height.push_back(z(k * step));
  return p;
}

// Arcs of the circle of radius rho, one every `spacing`, bottoms at offset + m spacing:
// the lower envelope of the circles, as a tooth leaves them.
double arcs(double x, double rho, double spacing, double offset) {
  const double u = std::remainder(x - offset, spacing);  // in [-spacing/2, spacing/2]
  return rho - std::sqrt(rho * rho - u * u);
}

TEST(FeedMarks, CircularArcsGiveTheirHeightAndSpacing) {
  // Cusps on samples (bottoms at 0.05 + 0.1 m): the PV is the circle's height over the
  // chord, rho - sqrt(rho^2 - s^2 / 4).
  const double rho = 3, s = 0.1, step = 0.002;
  const double cusp = rho - std::sqrt(rho * rho - 0.25 * s * s);
  EXPECT_NEAR(measureFeedMarks(sampled([&](double x) { return arcs(x, rho, s, 0.05); }, step, 1001))
                  .peakToValleyMm,
              cusp, 1e-15);
  // 50 samples a mark, 0.3 of a sample off the lattice: the highest samples are up to
  // half a step from the cusps, below them by at most the arcs' slope there x step / 2.
  const double offset = 0.0506;
  const Profile p = sampled([&](double x) { return arcs(x, rho, s, offset); }, step, 1001);
  const FeedMarks m = measureFeedMarks(p);
  const double slope = 0.5 * s / std::sqrt(rho * rho - 0.25 * s * s);
  EXPECT_LE(m.peakToValleyMm, cusp);
  EXPECT_GE(m.peakToValleyMm, cusp - slope * step / 2);
  ASSERT_EQ(m.valleysMm.size(), 20u);  // bottoms at 0.0506 + 0.1 m inside [0, 2]
  // Each bottom from the parabola through three samples of a circle: the quartic term
  // x^4 / (8 rho^3) moves the vertex by ~1e-7 of a step here.
  for (size_t k = 0; k < m.valleysMm.size(); ++k)
    EXPECT_NEAR(m.valleysMm[k], offset + s * double(k), 1e-6 * step) << k;
  EXPECT_NEAR(m.meanSpacingMm, s, 1e-12);
}

TEST(FeedMarks, ParabolicArcsAreLocatedExactly) {
  // The three-point parabola through a parabola is the parabola: every bottom exact.
  const double s = 0.07, step = 0.003, offset = 0.0123;
  const Profile p = sampled(
      [&](double x) {
        const double u = std::remainder(x - offset, s);
        return u * u / 2;
      },
      step, 500);
  const FeedMarks m = measureFeedMarks(p);
  ASSERT_GE(m.valleysMm.size(), 20u);
  for (size_t k = 0; k < m.valleysMm.size(); ++k)
    EXPECT_NEAR(m.valleysMm[k], offset + s * double(k), 1e-12) << k;
}

// Two teeth: the lower leaves arcs every 2 s, the higher (dz above) between them at
// s - d from the one before (runout shifts them). Heights: the lower envelope.
double twoTeeth(double x, double rho, double s, double d, double dz) {
  const double lower = std::remainder(x, 2 * s), higher = std::remainder(x - (s - d), 2 * s);
  return std::min(lower * lower / (2 * rho), dz + higher * higher / (2 * rho));
}

TEST(FeedMarks, BothTeethCountWhileTheHigherCutsDeeperThanTheHysteresis) {
  const double rho = 3, s = 0.1, d = 0.004, step = 0.001;
  // dz = 0.2 um: the higher tooth's dimple is ~0.8 um deep, far above 1% of the PV.
  const Profile p = sampled([&](double x) { return twoTeeth(x, rho, s, d, 2e-4); }, step, 2001);
  const FeedMarks m = measureFeedMarks(p);
  // The profile starts at a lower bottom (an end: not counted); then the valleys are the
  // higher tooth's at s - d, the lower's at 2 s, ... alternately s + d and s - d apart,
  // and over an even number of gaps their mean is s.
  ASSERT_GE(m.valleysMm.size(), 3u);
  EXPECT_NEAR(m.valleysMm[0], s - d, 1e-12);
  for (size_t k = 1; k < m.valleysMm.size(); ++k)
    EXPECT_NEAR(m.valleysMm[k] - m.valleysMm[k - 1], k % 2 ? s + d : s - d, 1e-12) << k;
  const size_t n = m.valleysMm.size() % 2 ? m.valleysMm.size() : m.valleysMm.size() - 1;
  EXPECT_NEAR((m.valleysMm[n - 1] - m.valleysMm[0]) / double(n - 1), s, 1e-12);
}

TEST(FeedMarks, ADimpleShallowerThanTheHysteresisIsNoMark) {
  // The higher tooth's bottom e below the lower teeth's cusp s^2 / (2 rho) (d = 0): it
  // meets the lower arcs at x = s -+ rho e / s, leaving cusps at PV = s^2 / (2 rho) - e +
  // rho e^2 / (2 s^2) and a dimple D = rho e^2 / (2 s^2) deep; here D = 0.58% of the PV.
  const double rho = 3, s = 0.1, step = 0.001, e = 2.35e-4;
  const double dz = s * s / (2 * rho) - e;
  const double pv = s * s / (2 * rho) - e + rho * e * e / (2 * s * s);
  const double dimple = rho * e * e / (2 * s * s);
  ASSERT_LT(dimple, kFeedMarkHysteresis * pv);
  ASSERT_GT(dimple, 1e-3 * pv);
  const Profile p = sampled([&](double x) { return twoTeeth(x, rho, s, 0, dz); }, step, 2001);
  const FeedMarks m = measureFeedMarks(p);
  const double slope = (s - rho * e / s) / rho;  // at the cusps
  EXPECT_LE(m.peakToValleyMm, pv + 1e-15);
  EXPECT_GE(m.peakToValleyMm, pv - slope * step / 2);
  EXPECT_NEAR(m.meanSpacingMm, 2 * s, 1e-12);  // the lower tooth's marks
  // With a hysteresis below the dimple's depth both teeth's valleys count.
  EXPECT_NEAR(measureFeedMarks(p, 1e-3).meanSpacingMm, s, 1e-12);
}

TEST(FeedMarks, EndsAndSlopesAreNotMarks) {
  // A profile starting at a bottom and ending inside a descent: neither end is a valley.
  const double rho = 3, s = 0.1, step = 0.002;
  const FeedMarks m =
      measureFeedMarks(sampled([&](double x) { return arcs(x, rho, s, 0); }, step, 276));
  ASSERT_EQ(m.valleysMm.size(), 5u);  // bottoms at 0.1 .. 0.5; 0 and the end are not
  EXPECT_NEAR(m.valleysMm.front(), s, 1e-6 * step);
  // A monotone profile and a level one have no marks; the level one no PV either.
  const FeedMarks ramp = measureFeedMarks(sampled([](double x) { return 0.01 * x; }, 0.01, 100));
  EXPECT_TRUE(ramp.valleysMm.empty());
  EXPECT_EQ(ramp.meanSpacingMm, 0);
  EXPECT_NEAR(ramp.peakToValleyMm, 0.0099, 1e-15);
  const FeedMarks level = measureFeedMarks(sampled([](double) { return -0.5; }, 0.01, 100));
  EXPECT_EQ(level.peakToValleyMm, 0);
  EXPECT_TRUE(level.valleysMm.empty());
  // One valley: a PV, no spacing.
  const FeedMarks one =
      measureFeedMarks(sampled([](double x) { return (x - 0.5) * (x - 0.5); }, 0.01, 101));
  EXPECT_EQ(one.valleysMm.size(), 1u);
  EXPECT_NEAR(one.valleysMm[0], 0.5, 1e-12);
  EXPECT_EQ(one.meanSpacingMm, 0);
}

}  // namespace
}  // namespace scallop
