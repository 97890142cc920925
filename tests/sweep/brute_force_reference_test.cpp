// The brute-force reference of tests/sweep/brute_force_reference.h, and the tests
// that check the reference itself against closed forms derived by hand. The file is
// named *_test.cpp so that tests/CMakeLists.txt's glob compiles it into scallop_tests.
//
// Nothing here calls sweep/*.cpp: the reference must stay independent of the code it
// judges, so a shared mistake cannot hide.
#include "sweep/brute_force_reference.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <utility>

namespace scallop {
namespace ref {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

template <class P>
double bisect(P&& pred, double in, double out) {
  for (int i = 0; i < 400; ++i) {
    const double mid = in + (out - in) / 2;
    if (mid == in || mid == out) break;
    (pred(mid) ? in : out) = mid;
  }
  return in;
}

// Every point of the cutter lies within sqrt(L^2 + R^2) of its tip; H bounds the z
// search with a margin.
double reach(const RefCutter& c) {
  return std::sqrt(c.L * c.L + c.R * c.R) + 1;
}

// The z interval on the vertical line (x, y) where 0 <= s <= L, clipped to the reach.
bool zDomain(const RefCutter& c, const Vec3& tip, const Vec3& a, double x, double y, double& lo,
             double& hi) {
  const double H = reach(c);
  const double cxy = (x - tip.x) * a.x + (y - tip.y) * a.y;  // s at z = tip.z
  if (a.z == 0) {
    if (cxy < 0 || cxy > c.L) return false;
    lo = tip.z - H;
    hi = tip.z + H;
    return true;
  }
  double z0 = tip.z + (0 - cxy) / a.z, z1 = tip.z + (c.L - cxy) / a.z;
  if (z0 > z1) std::swap(z0, z1);
  lo = std::max(z0, tip.z - H);
  hi = std::min(z1, tip.z + H);
  return lo <= hi;
}

// depth = prof(s) - rho at (x, y, z); >= 0 means inside. Only called inside the z
// domain, where 0 <= s <= L up to rounding; the clamp absorbs that rounding.
double depthAt(const RefCutter& c, const Vec3& tip, const Vec3& a, double x, double y, double z) {
  const Vec3 q{x - tip.x, y - tip.y, z - tip.z};
  const double s = dot(q, a);
  const double rho = length(q - a * s);
  return profile(c, std::min(std::max(s, 0.0), c.L)) - rho;
}

// Deepest point of the stationary cutter on the line: (z, depth); depth = -inf when
// the line never reaches heights 0 <= s <= L within the reach.
struct Deepest {
  bool domain = false;
  double lo = 0, z = 0, depth = -kInf;
};

Deepest deepest(const RefCutter& c, const Vec3& tip, const Vec3& a, double x, double y) {
  Deepest d;
  double hi = 0;
  if (!zDomain(c, tip, a, x, y, d.lo, hi)) return d;
  d.domain = true;
  const auto best = goldenMax([&](double z) { return depthAt(c, tip, a, x, y, z); }, d.lo, hi);
  d.z = best.first;
  d.depth = best.second;
  return d;
}

RefHit lowestFrom(const RefCutter& c, const Vec3& tip, const Vec3& a, double x, double y,
                  const Deepest& d) {
  RefHit h;
  if (!d.domain || d.depth < 0) return h;
  h.hit = true;
  auto in = [&](double z) { return depthAt(c, tip, a, x, y, z) >= 0; };
  // The chord is an interval (the solid is convex) containing d.z; its bottom is
  // either the bottom of the domain (the flat end s = 0) or a crossing below d.z.
  h.z = in(d.lo) ? d.lo : bisect(in, d.z, d.lo);
  return h;
}

}  // namespace

RefCutter makeRefCutter(CutterType type, double radius, double cornerRadius, double fluteLength) {
  RefCutter c;
  c.R = radius;
  c.r = type == CutterType::Ball ? radius : type == CutterType::Flat ? 0 : cornerRadius;
  c.L = fluteLength > 0 ? fluteLength : 4 * radius;
  return c;
}

double profile(const RefCutter& c, double s) {
  if (c.width) return c.width(s);
  if (s < c.r) return c.Rb() + std::sqrt(std::max(0.0, s * (2 * c.r - s)));  // = r^2-(r-s)^2
  return c.R;
}

bool inside(const RefCutter& c, const Vec3& tip, const Vec3& axis, const Vec3& p, double tol) {
  const Vec3 q = p - tip;
  const double s = dot(q, axis);
  if (s < -tol || s > c.L + tol) return false;
  const double rho = length(q - axis * s);
  return rho <= profile(c, std::min(std::max(s, 0.0), c.L)) + tol;
}

double deepestDepth(const RefCutter& c, const Vec3& tip, const Vec3& axis, double x, double y) {
  return deepest(c, tip, axis, x, y).depth;
}

RefHit stationaryLowest(const RefCutter& c, const Vec3& tip, const Vec3& axis, double x, double y) {
  return lowestFrom(c, tip, axis, x, y, deepest(c, tip, axis, x, y));
}

RefHit sweptLowest(const RefCutter& c, const Vec3& start, const Vec3& end, const Vec3& axis,
                   double x, double y) {
  const Vec3 d = end - start;
  auto tipAt = [&](double t) { return start + d * t; };
  // Positions t whose z domain is non-empty: with c(t) = s at z = tip.z, the domain is
  // non-empty iff -H|az| <= c(t) <= L + H|az| (see zDomain); c(t) is affine in t.
  const double m = reach(c) * std::fabs(axis.z);
  const double c0 = (x - start.x) * axis.x + (y - start.y) * axis.y;
  const double k = d.x * axis.x + d.y * axis.y;  // c(t) = c0 - k t
  double t0 = 0, t1 = 1;
  if (k == 0) {
    if (c0 < -m || c0 > c.L + m) return {};
  } else {
    const double ta = (c0 + m) / k, tb = (c0 - c.L - m) / k;
    t0 = std::max(0.0, std::min(ta, tb));
    t1 = std::min(1.0, std::max(ta, tb));
    if (t0 > t1) return {};
  }
  // G(t) = deepest depth at t is concave (depth is jointly concave in (t, z)): its
  // maximum says whether the line meets the swept solid at all.
  auto G = [&](double t) { return deepest(c, tipAt(t), axis, x, y).depth; };
  const auto gbest = goldenMax(G, t0, t1);
  if (gbest.second < 0) return {};
  auto hits = [&](double t) { return G(t) >= 0; };
  const double ta = hits(t0) ? t0 : bisect(hits, gbest.first, t0);
  const double tb = hits(t1) ? t1 : bisect(hits, gbest.first, t1);
  // F(t) = lowest z at t is convex on [ta, tb]. Dense grid first (a safety net that
  // does not trust convexity), then golden-section around the best grid point.
  auto F = [&](double t) {
    const RefHit h = stationaryLowest(c, tipAt(t), axis, x, y);
    return h.hit ? h.z : kInf;
  };
  const int n = 129;
  double bestZ = kInf;
  int bestI = 0;
  for (int i = 0; i < n; ++i) {
    const double t = i == n - 1 ? tb : ta + (tb - ta) * i / (n - 1);
    const double z = F(t);
    if (z < bestZ) {
      bestZ = z;
      bestI = i;
    }
  }
  const double lo = ta + (tb - ta) * std::max(0, bestI - 1) / (n - 1);
  const double hi = bestI + 1 >= n - 1 ? tb : ta + (tb - ta) * (bestI + 1) / (n - 1);
  const auto refined = goldenMax([&](double t) { return -F(t); }, lo, hi);
  RefHit h;
  h.hit = std::isfinite(bestZ);  // G(ta) >= 0, so F(ta) is finite: always true here
  h.z = std::min(bestZ, -refined.second);
  return h;
}

RefHit unionLowest(const RefCutter& c, const std::vector<RefMove>& moves, double x, double y) {
  RefHit best;
  for (const RefMove& mv : moves) {
    const RefHit h = sweptLowest(c, mv.start, mv.end, mv.axis, x, y);
    if (h.hit && (!best.hit || h.z < best.z)) best = h;
  }
  return best;
}

double supportValue(const RefCutter& c, const Vec3& axis, const Vec3& dir) {
  // A slice at height s is a disk of radius prof(s) around the axis, so the best point
  // of it gives na s + |dir_perp| prof(s): concave in s.
  const double na = dot(dir, axis);
  const double np = length(dir - axis * na);
  return goldenMax([&](double s) { return na * s + np * profile(c, s); }, 0.0, c.L).second;
}

double sweptSupportValue(const RefCutter& c, const Vec3& start, const Vec3& end, const Vec3& axis,
                         const Vec3& dir) {
  return std::max(dot(dir, start), dot(dir, end)) + supportValue(c, axis, dir);
}

double cuspHeight(const RefCutter& c, const std::vector<RefMove>& moves, double x0, double y0,
                  double x1, double y1, int samples) {
  auto f = [&](double u) {
    const RefHit h = unionLowest(c, moves, x0 + (x1 - x0) * u, y0 + (y1 - y0) * u);
    return h.hit ? h.z : kInf;
  };
  std::vector<double> z(samples);
  for (int i = 0; i < samples; ++i) {
    z[i] = f(double(i) / (samples - 1));
    if (!std::isfinite(z[i])) return -1;
  }
  const int iMax = int(std::max_element(z.begin(), z.end()) - z.begin());
  const int iMin = int(std::min_element(z.begin(), z.end()) - z.begin());
  auto bracket = [&](int i) {
    return std::make_pair(std::max(0, i - 1) / double(samples - 1),
                          std::min(samples - 1, i + 1) / double(samples - 1));
  };
  const auto bmax = bracket(iMax), bmin = bracket(iMin);
  const double top = std::max(z[iMax], goldenMax(f, bmax.first, bmax.second).second);
  const double bottom = std::min(
      z[iMin], -goldenMax([&](double u) { return -f(u); }, bmin.first, bmin.second).second);
  return top - bottom;
}

}  // namespace ref
}  // namespace scallop

// ---------------------------------------------------------------------------------
// Self-tests of the reference against hand-derived closed forms. Tolerances are 1e-9
// mm, a thousand times tighter than the 1e-6 the reference is used to judge.
namespace {

using scallop::CutterType;
using scallop::Vec3;
using namespace scallop::ref;

const Vec3 kUp{0, 0, 1};

TEST(BruteForceReference, ProfileAndInside) {
  const RefCutter bull = makeRefCutter(CutterType::Bull, 3, 1);
  EXPECT_DOUBLE_EQ(bull.L, 12);
  EXPECT_DOUBLE_EQ(profile(bull, 0), 2);
  EXPECT_DOUBLE_EQ(profile(bull, 1), 3);
  EXPECT_DOUBLE_EQ(profile(bull, 5), 3);
  EXPECT_NEAR(profile(bull, 0.5), 2 + std::sqrt(0.75), 1e-15);
  EXPECT_TRUE(inside(bull, {0, 0, 0}, kUp, {1.99, 0, 0}));
  EXPECT_FALSE(inside(bull, {0, 0, 0}, kUp, {2.01, 0, 0}));
  EXPECT_FALSE(inside(bull, {0, 0, 0}, kUp, {0, 0, -1e-9}));
  EXPECT_FALSE(inside(bull, {0, 0, 0}, kUp, {0, 0, 12 + 1e-9}));
  EXPECT_TRUE(inside(bull, {0, 0, 0}, kUp, {0, 2.99, 11.9}));
  const RefCutter ball = makeRefCutter(CutterType::Ball, 2);
  EXPECT_DOUBLE_EQ(ball.r, 2);
  EXPECT_DOUBLE_EQ(profile(ball, 0), 0);
  const RefCutter flat = makeRefCutter(CutterType::Flat, 2, 0, 3);
  EXPECT_DOUBLE_EQ(flat.r, 0);
  EXPECT_DOUBLE_EQ(flat.L, 3);
  EXPECT_DOUBLE_EQ(profile(flat, 0), 2);
}

TEST(BruteForceReference, VerticalStationaryClosedForms) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(0, 1);
  for (int i = 0; i < 200; ++i) {
    const double R = 0.5 + 7.5 * U(rng), r = R * (0.05 + 0.9 * U(rng));
    const Vec3 tip{10 * U(rng) - 5, 10 * U(rng) - 5, 10 * U(rng) - 5};
    const double rho = 1.2 * R * U(rng), phi = 6.283185307179586 * U(rng);
    const double x = tip.x + rho * std::cos(phi), y = tip.y + rho * std::sin(phi);
    if (std::fabs(rho - R) < 1e-6) continue;
    const RefHit ball = stationaryLowest(makeRefCutter(CutterType::Ball, R), tip, kUp, x, y);
    const RefHit flat = stationaryLowest(makeRefCutter(CutterType::Flat, R), tip, kUp, x, y);
    const RefHit bull = stationaryLowest(makeRefCutter(CutterType::Bull, R, r), tip, kUp, x, y);
    ASSERT_EQ(ball.hit, rho < R);
    ASSERT_EQ(flat.hit, rho < R);
    ASSERT_EQ(bull.hit, rho < R);
    if (rho >= R) continue;
    EXPECT_NEAR(ball.z, tip.z + R - std::sqrt(R * R - rho * rho), 1e-9);
    EXPECT_NEAR(flat.z, tip.z, 1e-9);
    const double e = rho - (R - r);
    EXPECT_NEAR(bull.z, tip.z + (e <= 0 ? 0 : r - std::sqrt(r * r - e * e)), 1e-9);
  }
}

TEST(BruteForceReference, HorizontalAndTiltedClosedForms) {
  // Horizontal axis +x, tip at the origin: the axis line passes through the tip, so the
  // cylinder's lowest point above (x, y) is -sqrt(R^2 - y^2), for 0 <= x <= L only.
  const double R = 2;
  const RefCutter flat = makeRefCutter(CutterType::Flat, R);
  const RefCutter ball = makeRefCutter(CutterType::Ball, R);
  const Vec3 ax{1, 0, 0};
  for (double x : {0.01, 0.5, 1.7, 3.0, 7.99})
    for (double y : {0.0, 0.3, -1.1, 1.9}) {
      const RefHit h = stationaryLowest(flat, {0, 0, 0}, ax, x, y);
      ASSERT_TRUE(h.hit);
      EXPECT_NEAR(h.z, -std::sqrt(R * R - y * y), 1e-9);
      // Ball: slice radius prof(x) = sqrt(R^2 - (R - x)^2) below s = R.
      const double p = x < R ? std::sqrt(R * R - (R - x) * (R - x)) : R;
      const RefHit b = stationaryLowest(ball, {0, 0, 0}, ax, x, y);
      ASSERT_EQ(b.hit, std::fabs(y) < p);
      if (b.hit) {
        EXPECT_NEAR(b.z, -std::sqrt(p * p - y * y), 1e-9);
      }
    }
  EXPECT_FALSE(stationaryLowest(flat, {0, 0, 0}, ax, -0.01, 0).hit);
  EXPECT_FALSE(stationaryLowest(flat, {0, 0, 0}, ax, 8.01, 0).hit);
  EXPECT_FALSE(stationaryLowest(flat, {0, 0, 0}, ax, 1, 2.01).hit);

  // Flat cutter tilted by th towards +x: the line enters through the bottom disk
  // (outward normal -a points down) at z = -x tan(th) while that point is within R.
  for (double th : {0.1, 0.6, 1.2}) {
    const Vec3 a{std::sin(th), 0, std::cos(th)};
    for (double x : {-0.5, 0.0, 0.4})
      for (double y : {0.0, 0.7, -1.5}) {
        const double z = -x * std::tan(th);
        if (x * x + y * y + z * z >= R * R) continue;
        const RefHit h = stationaryLowest(flat, {0, 0, 0}, a, x, y);
        ASSERT_TRUE(h.hit);
        EXPECT_NEAR(h.z, z, 1e-9);
      }
  }
  // Tilted ball: near the centre C = tip + R a the lowest point is on the sphere,
  // C.z - sqrt(R^2 - d^2), as long as that point is on the hemisphere (s <= R).
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(-1, 1);
  int checked = 0;
  for (int i = 0; i < 300; ++i) {
    const Vec3 a = scallop::normalize(Vec3{U(rng), U(rng), 1.5 + U(rng)});
    const Vec3 C = a * R;
    const double x = C.x + R * U(rng), y = C.y + R * U(rng);
    const double d2 = (x - C.x) * (x - C.x) + (y - C.y) * (y - C.y);
    if (d2 >= R * R * 0.999) continue;
    const Vec3 P{x, y, C.z - std::sqrt(R * R - d2)};
    if (dot(P, a) > R - 1e-3) continue;  // the lowest point would be on the cylinder
    const RefHit h = stationaryLowest(ball, {0, 0, 0}, a, x, y);
    ASSERT_TRUE(h.hit);
    EXPECT_NEAR(h.z, P.z, 1e-9);
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

TEST(BruteForceReference, StationaryAgreesWithDumbScan) {
  // The dumbest possible method: step z by 1e-4 with inside(). Agreement to a step
  // shows that golden-section + bisection find every chord that a scan sees.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(0, 1);
  int hits = 0;
  for (int i = 0; i < 150; ++i) {
    const CutterType type = CutterType(i % 3);
    const double R = 0.5 + 4 * U(rng), r = R * (0.05 + 0.9 * U(rng));
    const RefCutter c = makeRefCutter(type, R, r, R * (1 + 4 * U(rng)));
    const double th = 1.5707963267948966 * U(rng), ph = 6.283185307179586 * U(rng);
    const Vec3 a =
        i % 10 == 0 ? Vec3{std::cos(ph), std::sin(ph), 0}
                    : Vec3{std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)};
    // Aim near the axis's shadow so that most lines hit.
    const Vec3 on = a * (c.L * U(rng));
    const double x = on.x + (2 * U(rng) - 1) * 1.2 * R, y = on.y + (2 * U(rng) - 1) * 1.2 * R;
    const RefHit h = stationaryLowest(c, {0, 0, 0}, a, x, y);
    const double H = std::sqrt(c.L * c.L + R * R), step = 1e-4;
    double first = HUGE_VAL;
    for (double z = -H; z <= H; z += step)
      if (inside(c, {0, 0, 0}, a, {x, y, z})) {
        first = z;
        break;
      }
    if (!std::isfinite(first)) {
      EXPECT_FALSE(h.hit && inside(c, {0, 0, 0}, a, {x, y, h.z + step / 2}, 1e-12))
          << "reference hit where the scan found nothing with a thick chord";
      continue;
    }
    ++hits;
    ASSERT_TRUE(h.hit);
    EXPECT_LE(h.z, first + 1e-12);
    EXPECT_GE(h.z, first - step - 1e-12);
    EXPECT_TRUE(inside(c, {0, 0, 0}, a, {x, y, h.z}, 1e-9));
    EXPECT_FALSE(inside(c, {0, 0, 0}, a, {x, y, h.z - 1e-7}));
  }
  EXPECT_GT(hits, 40);
}

TEST(BruteForceReference, SweptClosedForms) {
  const double R = 1.5;
  const RefCutter ball = makeRefCutter(CutterType::Ball, R);
  // Vertical ball along x from (0,0,0) to (10,0,0): the sphere centres sweep a segment
  // at height R, so z = R - sqrt(R^2 - y^2) between the ends and the end caps beyond.
  for (double x : {-1.0, -0.2, 0.0, 3.3, 10.0, 10.7})
    for (double y : {0.0, 0.4, -1.2}) {
      const double dx = x < 0 ? x : x > 10 ? x - 10 : 0;
      const double rho2 = dx * dx + y * y;
      const RefHit h = sweptLowest(ball, {0, 0, 0}, {10, 0, 0}, kUp, x, y);
      ASSERT_EQ(h.hit, rho2 < R * R);
      if (h.hit) {
        EXPECT_NEAR(h.z, R - std::sqrt(R * R - rho2), 1e-9);
      }
    }
  EXPECT_FALSE(sweptLowest(ball, {0, 0, 0}, {10, 0, 0}, kUp, 5, 1.51).hit);
  // Plunges: the lowest point is the lower end's, whichever way the tool moves.
  for (const auto& se : {std::make_pair(Vec3{1, 2, 5}, Vec3{1, 2, 3}),
                         std::make_pair(Vec3{1, 2, 3}, Vec3{1, 2, 5})}) {
    const RefHit h = sweptLowest(ball, se.first, se.second, kUp, 1.8, 2.3);
    ASSERT_TRUE(h.hit);
    EXPECT_NEAR(h.z, 3 + R - std::sqrt(R * R - 0.73), 1e-9);
  }
  // Ramp of a vertical ball: the centres run along direction u = (cos al, 0, sin al)
  // from (0,0,R), so away from the ends the lowest point is on the cylinder of radius
  // R around that line: (z' cos al - x sin al)^2 = R^2 - y^2, z' = z - R.
  const double al = 0.3, len = 8;
  const Vec3 u{std::cos(al), 0, std::sin(al)};
  for (double x : {1.0, 3.0, 6.0})
    for (double y : {0.0, 0.8, -1.4}) {
      const double zc = (x * std::sin(al) - std::sqrt(R * R - y * y)) / std::cos(al);
      const double foot = x * u.x + zc * u.z;  // projection on the centre line
      ASSERT_GT(foot, 0.1);
      ASSERT_LT(foot, len - 0.1);
      const RefHit h = sweptLowest(ball, {0, 0, 0}, u * len, kUp, x, y);
      ASSERT_TRUE(h.hit);
      EXPECT_NEAR(h.z, zc + R, 1e-9);
    }
  // Horizontal flat cylinder (axis +x) moved along +y by 4: bottom line at z = -R.
  const RefCutter flat = makeRefCutter(CutterType::Flat, R);
  const RefHit h = sweptLowest(flat, {0, 0, 0}, {0, 4, 0}, {1, 0, 0}, 2, 1.3);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.z, -R, 1e-9);
  // Zero-length move equals the stationary cutter.
  const RefHit z0 = sweptLowest(ball, {1, 1, 1}, {1, 1, 1}, kUp, 1.5, 0.5);
  ASSERT_TRUE(z0.hit);
  EXPECT_NEAR(z0.z, 1 + R - std::sqrt(R * R - 0.5), 1e-9);
}

TEST(BruteForceReference, SweptAgreesWithDenseScanOverT) {
  // The minimum over t of the stationary lowest point, on a grid of 20001 positions,
  // is an upper bound of the true minimum that converges to it: the reference must
  // never be above it, and only below it by what the grid step can explain.
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> U(0, 1);
  int hits = 0;
  double worst = 0;
  for (int i = 0; i < 40; ++i) {
    const double R = 0.5 + 4 * U(rng);
    const RefCutter c = makeRefCutter(CutterType(i % 3), R, R * (0.1 + 0.8 * U(rng)));
    const double th = 1.5707963267948966 * U(rng), ph = 6.283185307179586 * U(rng);
    const Vec3 a{std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)};
    const Vec3 s{0, 0, 0}, e{8 * U(rng) - 4, 8 * U(rng) - 4, 4 * U(rng) - 2};
    const Vec3 m = (s + e) * 0.5 + a * (c.L * 0.3 * U(rng));
    const double x = m.x + (2 * U(rng) - 1) * R, y = m.y + (2 * U(rng) - 1) * R;
    const RefHit h = sweptLowest(c, s, e, a, x, y);
    const int n = 20001;
    double best = HUGE_VAL;
    for (int j = 0; j < n; ++j) {
      const RefHit hj = stationaryLowest(c, s + (e - s) * (double(j) / (n - 1)), a, x, y);
      if (hj.hit) best = std::min(best, hj.z);
    }
    if (!std::isfinite(best)) continue;  // a miss on the grid proves nothing
    ++hits;
    ASSERT_TRUE(h.hit);
    EXPECT_LE(h.z, best + 1e-12);
    // At the minimum F is either smooth (error ~ F'' step^2) or has a kink whose
    // slopes are those of the cutter's lower surface times |e - s|; allow ten times
    // |e - s| per grid step, which is still 4e-3 mm at most.
    const double slack = 10 * scallop::length(e - s) / (n - 1);
    EXPECT_GE(h.z, best - slack);
    worst = std::max(worst, (best - h.z) / slack);
  }
  std::printf("dense-t grid minus reference: worst %.3g of the allowed slack\n", worst);
  EXPECT_GT(hits, 20);
}

TEST(BruteForceReference, UnionAndCuspOfBallPasses) {
  // Two vertical-ball passes along x, w apart: the classic scallop R - sqrt(R^2 - w^2/4).
  const double R = 3, w = 2.2;
  const RefCutter ball = makeRefCutter(CutterType::Ball, R);
  const std::vector<RefMove> moves{{{-5, 0, 0}, {5, 0, 0}, kUp}, {{-5, w, 0}, {5, w, 0}, kUp}};
  const RefHit mid = unionLowest(ball, moves, 0, w / 2);
  ASSERT_TRUE(mid.hit);
  EXPECT_NEAR(mid.z, R - std::sqrt(R * R - w * w / 4), 1e-9);
  EXPECT_NEAR(unionLowest(ball, moves, 1, 0.1).z, R - std::sqrt(R * R - 0.01), 1e-9);
  EXPECT_NEAR(cuspHeight(ball, moves, 0.5, 0, 0.5, w, 201), R - std::sqrt(R * R - w * w / 4), 1e-9);
  EXPECT_LT(cuspHeight(ball, moves, 0.5, -4, 0.5, w, 201), 0);  // y = -4 is never cut
}

TEST(BruteForceReference, SupportValues) {
  const double R = 2;
  const RefCutter ball = makeRefCutter(CutterType::Ball, R);
  EXPECT_NEAR(supportValue(ball, kUp, {0, 0, -1}), 0, 1e-12);
  EXPECT_NEAR(supportValue(ball, kUp, {0, 0, 1}), 8, 1e-12);
  EXPECT_NEAR(supportValue(ball, kUp, {3, 0, 0}), 3 * R, 1e-12);
  // For a unit direction d pointing downwards the support point is on the hemisphere:
  // centre (0, 0, R) plus R d, so the value is R d.z + R.
  const Vec3 d = scallop::normalize(Vec3{1, 2, -2});
  EXPECT_NEAR(supportValue(ball, kUp, d), R * d.z + R, 1e-12);
  // Flat cutter, any axis: max over s in [0, L] of na s + np R = np R + max(0, na) L.
  const RefCutter flat = makeRefCutter(CutterType::Flat, R, 0, 5);
  const Vec3 a = scallop::normalize(Vec3{0.3, -0.2, 1});
  for (const Vec3& v : {Vec3{1, 0, 0}, Vec3{0, 0, -1}, Vec3{0.2, 0.5, 0.9}, Vec3{-1, 2, -3}}) {
    const double na = dot(v, a), np = scallop::length(v - a * na);
    EXPECT_NEAR(supportValue(flat, a, v), np * R + std::max(0.0, na) * 5, 1e-12);
  }
  EXPECT_NEAR(sweptSupportValue(flat, {0, 0, 0}, {0, 0, -3}, kUp, {0, 0, -1}), 3, 1e-12);
}

}  // namespace
