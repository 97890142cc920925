// The brute-force reference for moves whose axis turns (brute_force_reference.h,
// turningLowest) and its own checks. Like the rest of the reference it calls nothing
// in sweep/*.cpp: dense t, the stationary reference at each pose, golden-section
// refinement at the lowest local minima.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "sweep/brute_force_reference.h"

namespace scallop {
namespace ref {

RefHit turningLowest(const RefCutter& c, const RefCurve& curve, double x, double y, int samples,
                     double* maxDepth) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  auto tipAt = [&](double t) {
    return curve.tip ? curve.tip(t) : curve.p0 + (curve.p1 - curve.p0) * t;
  };
  auto F = [&](double t) {
    const RefHit h = stationaryLowest(c, tipAt(t), curve.axis(t), x, y);
    return h.hit ? h.z : kInf;
  };
  std::vector<double> z(static_cast<size_t>(samples)), depth(static_cast<size_t>(samples));
  for (int i = 0; i < samples; ++i) {
    const double t = double(i) / (samples - 1);
    z[size_t(i)] = F(t);
    depth[size_t(i)] = deepestDepth(c, tipAt(t), curve.axis(t), x, y);
  }
  if (maxDepth) *maxDepth = *std::max_element(depth.begin(), depth.end());
  // Local minima of the grid (plateaus of misses excluded), lowest first.
  std::vector<int> minima;
  for (int i = 0; i < samples; ++i) {
    const double zi = z[size_t(i)];
    if (!std::isfinite(zi)) continue;
    if ((i == 0 || z[size_t(i - 1)] >= zi) && (i + 1 == samples || z[size_t(i + 1)] >= zi))
      minima.push_back(i);
  }
  std::sort(minima.begin(), minima.end(),
            [&](int a, int b) { return z[size_t(a)] < z[size_t(b)]; });
  RefHit out;
  for (size_t k = 0; k < std::min<size_t>(3, minima.size()); ++k) {
    const int i = minima[k];
    const double lo = double(std::max(0, i - 1)) / (samples - 1);
    const double hi = double(std::min(samples - 1, i + 1)) / (samples - 1);
    const double best =
        std::min(z[size_t(i)], -goldenMax([&](double t) { return -F(t); }, lo, hi).second);
    if (!out.hit || best < out.z) out.hit = true, out.z = best;
  }
  return out;
}

namespace {

// With a constant axis the turning reference must agree with the constant-axis
// reference (sweptLowest), which the closed forms of brute_force_reference_test.cpp
// check: two routes to the same solid.
TEST(TurningReference, ConstantAxisAgreesWithTheSweptReference) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  int compared = 0;
  for (int k = 0; k < 40; ++k) {
    const RefCutter c = makeRefCutter(
        k % 3 == 0 ? CutterType::Ball : (k % 3 == 1 ? CutterType::Flat : CutterType::Bull), 3, 1,
        12);
    const Vec3 axis = [&] {
      Vec3 a{u(rng), u(rng), 1 + u(rng)};
      return a / std::sqrt(dot(a, a));
    }();
    const Vec3 p0{0, 0, 0}, p1{2 * u(rng), 2 * u(rng), 0.5 * u(rng)};
    const double x = 3 * u(rng), y = 3 * u(rng);
    const RefHit a = sweptLowest(c, p0, p1, axis, x, y);
    double depth = 0;
    const RefHit b = turningLowest(c, {p0, p1, [&](double) { return axis; }}, x, y, 401, &depth);
    if (std::fabs(depth) < 1e-6) continue;  // grazing: hit or miss by resolution
    ASSERT_EQ(a.hit, b.hit) << k;
    if (!a.hit) continue;
    EXPECT_NEAR(a.z, b.z, 1e-7) << k;
    ++compared;
  }
  EXPECT_GE(compared, 20);
}

// A ball cutter turning about its tip, standing still: its sphere's centre c runs on a
// circle of radius R about the tip. Where the vertical line x meets a sphere on its
// lower hemisphere (below the centre along the axis), that point is on the cutter's
// boundary with a downward normal, so it is the cutter's lowest point on the line:
// z = c_z - sqrt(R^2 - (x - c_x)^2). The swept answer is its minimum over the arc,
// here by a fine scan of the angle (closed form per angle).
TEST(TurningReference, BallTurningAboutItsTip) {
  const double R = 2;
  const RefCutter c = makeRefCutter(CutterType::Ball, R);
  for (double th0 : {-0.6, -0.2, 0.1, 0.4}) {
    const double th1 = th0 + 0.5;
    const RefCurve curve{{0, 0, 0}, {0, 0, 0}, [&](double t) {
                           const double th = th0 + (th1 - th0) * t;
                           return Vec3{std::sin(th), 0, std::cos(th)};
                         }};
    const double x = 0.7;
    double expected = HUGE_VAL;
    for (int i = 0; i <= 200000; ++i) {
      const double th = th0 + (th1 - th0) * i / 200000.0;
      const double cx = R * std::sin(th), cz = R * std::cos(th);
      const double down = std::sqrt(R * R - (x - cx) * (x - cx));
      // The precondition: the contact is on the lower hemisphere at every angle.
      ASSERT_LE((x - cx) * std::sin(th) - down * std::cos(th), 0) << th;
      expected = std::min(expected, cz - down);
    }
    const RefHit h = turningLowest(c, curve, x, 0);
    ASSERT_TRUE(h.hit);
    EXPECT_NEAR(h.z, expected, 1e-9) << th0;
  }
}

}  // namespace
}  // namespace ref
}  // namespace scallop
