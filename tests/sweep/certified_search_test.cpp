// The certified search on its own (certifiedLowestPoint, without SweptMove's fast
// paths: the cutoff's ray clearance, the rim and face contacts), so that every line runs
// its steps 5 and 3 with the four bounds of interval_bounds.h: heights against the
// independent turning brute force (brute_force_reference.h), every proof closed, and
// the cutoff deciding only hit or miss.
#include "sweep/certified_search.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "base/constants.h"
#include "sweep/brute_force_reference.h"
#include "sweep/pose_curve.h"

namespace scallop {
namespace {

// The bounds SweptMove keeps for a turning move (swept_move.cpp), with the top of the
// solid from the chord bound and its round-off as SweptMove::support adds it.
TurningBounds boundsOf(const Cutter& cutter, const PoseCurve& curve) {
  TurningBounds b;
  b.reach = std::hypot(cutter.fluteLength, cutter.radius);
  b.tipSpeed = curve.tipSpeedBound();
  const double top = turningSupport(cutter, curve, b, {0, 0, 1});
  b.zTop = top + 1e-12 * (1 + std::fabs(top));
  return b;
}

TEST(CertifiedSearch, AloneAgreesWithTheTurningBruteForce) {
  std::mt19937_64 rng(32);
  std::uniform_real_distribution<double> u(0, 1);
  const unsigned long long unprovenBefore = unprovenCertifiedSearches();
  int hits = 0, misses = 0, compared = 0;
  double worst = 0;
  for (int k = 0; k < 36; ++k) {
    // Ball, bull and flat (whose rim is a kink of f: the test below); the axis leaned up
    // to 60 degrees and turned by up to ~30 in the move; a level feed, a ramp or a
    // standing tip.
    const CutterType type =
        k % 3 == 0 ? CutterType::Ball : (k % 3 == 1 ? CutterType::Bull : CutterType::Flat);
    const double R = 1 + 3 * u(rng);
    const double r = type == CutterType::Bull ? 0.4 * R : (type == CutterType::Ball ? R : 0);
    const Cutter cutter = Cutter::make(type, R, r, 3 * R);
    const double lean = kPi / 3 * u(rng), azimuth = 2 * kPi * u(rng);
    const Vec3 a0 = ref::unitFromAngles(lean, azimuth);
    const Vec3 a1 = ref::unitFromAngles(std::max(0.0, lean + 0.5 * (u(rng) - 0.5)),
                                        azimuth + 0.5 * (u(rng) - 0.5));
    const Vec3 p0{0, 0, 0};
    const Vec3 p1 =
        k % 4 == 3 ? p0 : Vec3{2 * (u(rng) - 0.5), 2 * (u(rng) - 0.5), k % 4 == 1 ? 0.5 : 0};
    const PoseCurve curve = PoseCurve::linear({p0, a0}, {p1, a1});
    ASSERT_FALSE(curve.constantAxis());
    const TurningBounds bounds = boundsOf(cutter, curve);
    const ref::RefCutter refCutter = ref::makeRefCutter(type, R, r, 3 * R);
    const ref::RefCurve refCurve{p0, p1, [&](double t) { return ref::slerp(a0, a1, t); }};
    for (int q = 0; q < 5; ++q) {
      // Lines round the tip's path, out past the footprint's edge.
      const double s = u(rng), rho = 1.3 * R * std::sqrt(u(rng)), phi = 2 * kPi * u(rng);
      const double x = p0.x + s * (p1.x - p0.x) + rho * std::cos(phi);
      const double y = p0.y + s * (p1.y - p0.y) + rho * std::sin(phi);
      const LowestPoint lp = certifiedLowestPoint(cutter, curve, bounds, x, y, HUGE_VAL);
      double depth = 0;
      const ref::RefHit want = ref::turningLowest(refCutter, refCurve, x, y, 401, &depth);
      if (std::fabs(depth) < 1e-5) continue;  // grazing: hit or miss is resolution
      ++compared;
      ASSERT_EQ(lp.hit, want.hit) << "case " << k << " (" << x << ", " << y << ")";
      if (!lp.hit) {
        ++misses;
        continue;
      }
      ++hits;
      // The reference errs only upwards (every value it takes is a real height).
      EXPECT_LE(lp.z, want.z + 1e-9) << "case " << k << " (" << x << ", " << y << ")";
      EXPECT_NEAR(lp.z, want.z, 1e-6) << "case " << k << " (" << x << ", " << y << ")";
      worst = std::max(worst, std::fabs(lp.z - want.z));
      // The cutoff decides hit or miss and nothing else.
      const LowestPoint above = certifiedLowestPoint(cutter, curve, bounds, x, y, lp.z + 1e-6);
      EXPECT_TRUE(above.hit);
      EXPECT_EQ(above.z, lp.z);
      EXPECT_FALSE(certifiedLowestPoint(cutter, curve, bounds, x, y, lp.z - 1e-6).hit);
    }
  }
  std::printf("certified search alone: %d of %d lines hit, %d missed; worst %.3g mm\n", hits,
              compared, misses, worst);
  EXPECT_GE(hits, 80);
  EXPECT_GE(misses, 5);
  EXPECT_EQ(unprovenCertifiedSearches(), unprovenBefore);
}

// A flat cutter's line near its rim: f falls gently along the bottom face to where the
// line reaches the rim, then rises steeply up the flank. The secant root of such a
// bracket hugs its gentle end, so the search used to crawl (1 024 samples, 0.37 of the
// way) and return a height 5.5 um too high; across an edge it now bisects (28 samples).
TEST(CertifiedSearch, FlatCutterLineNearItsRimClosesItsProof) {
  const double R = 1.2615650891517423;
  const Cutter cutter = Cutter::make(CutterType::Flat, R, 0, 3 * R);
  const Vec3 a0{0.0028117604593629526, -0.023831210548709878, 0.99971204224361643};
  const Vec3 a1{-0.0013874373919742422, -0.071717721562369788, 0.99742400383757845};
  const Vec3 p0{0, 0, 0}, p1{0.71339002900510962, 0.37600372794152559, 0};
  const double x = -0.72086123429637261, y = -0.50131176228286223;
  const PoseCurve curve = PoseCurve::linear({p0, a0}, {p1, a1});
  const unsigned long long unprovenBefore = unprovenCertifiedSearches();
  const LowestPoint lp =
      certifiedLowestPoint(cutter, curve, boundsOf(cutter, curve), x, y, HUGE_VAL);
  const ref::RefHit want =
      ref::turningLowest(ref::makeRefCutter(CutterType::Flat, R, 0, 3 * R),
                         {p0, p1, [&](double t) { return ref::slerp(a0, a1, t); }}, x, y);
  ASSERT_TRUE(lp.hit && want.hit);
  EXPECT_NEAR(lp.z, want.z, 1e-6);  // now -0.0254693 against -0.0309867
  EXPECT_EQ(unprovenCertifiedSearches(), unprovenBefore);
}

}  // namespace
}  // namespace scallop
